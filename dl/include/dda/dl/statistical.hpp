#pragma once
// Statistical joint sets after Shi & Goodman: parallel scan lines at the set's
// dip, one random spacing apart, each filled with alternating joints and rock
// bridges of random length.
#include <cstddef>
#include <string>
#include <vector>

#include "dda/common/geometry.hpp"
#include "dda/dl/clip.hpp"
#include "dda/dl/random.hpp"

namespace dda::dl {

struct StatisticalSetSpec {
  std::string name;
  double dip_deg = 0;            // trace inclination from +x, counter-clockwise, [0, 180)
  double mean_length = 1;        // m > 0
  double mean_bridge = 0;        // m >= 0
  double mean_spacing = 1;       // m > 0, normal distance between scan lines
  double length_randomness = 0;  // [0, 1)
  double bridge_randomness = 0;  // [0, 1)
  double spacing_randomness = 0; // [0, 1)
  double dip_spread_deg = 0;     // maximum deviation of one trace's dip, deg >= 0
};

// Sums over every value drawn for the set (before clipping), so that
// sum/count converges to the asked mean.
struct StatisticalSetStats {
  std::size_t scan_lines = 0;
  std::size_t traces = 0;       // joints drawn (including those later clipped away)
  std::size_t bridges = 0;
  std::size_t spacings = 0;
  double sum_length = 0, sum_bridge = 0, sum_spacing = 0, sum_dip_deg = 0;
  double mean_length() const { return traces ? sum_length / traces : 0; }
  double mean_bridge() const { return bridges ? sum_bridge / bridges : 0; }
  double mean_spacing() const { return spacings ? sum_spacing / spacings : 0; }
  double mean_dip_deg() const { return traces ? sum_dip_deg / traces : 0; }
};

struct StatisticalSetOutput {
  std::vector<Segment> traces;  // not clipped; only those reaching the domain's bounding region
  StatisticalSetStats stats;
};

// Expected number of traces the set makes over the domain's bounding region.
double estimate_statistical_traces(const StatisticalSetSpec& spec, const Polygon2& domain);

// Scan lines cover the domain's bounding region in the frame rotated to the
// set's dip; the first scan line sits a random fraction of a spacing above
// the lowest corner and each scan line starts a random fraction of one
// joint+bridge cycle before the region, so the pattern has no edge bias.
StatisticalSetOutput generate_statistical_set(const StatisticalSetSpec& spec, const Polygon2& domain, Stream& rng);

}  // namespace dda::dl
