#pragma once
// Mechanically layered rock: beds of log-normal thickness stacked along the
// bedding normal, and joint sets bounded by each bed's bottom and top whose
// median spacing is thickness / FSI (fracture spacing index).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "dda/common/geometry.hpp"
#include "dda/common/line_model.hpp"
#include "dda/dl/clip.hpp"
#include "dda/dl/random.hpp"

namespace dda::dl {

struct ThicknessSpec {
  enum class Kind { LogNormal, Constant } kind = Kind::Constant;
  double mu = 0, sigma = 0;  // of ln(thickness), for LogNormal
  double minimum = 0;        // m; LogNormal draws below it are redrawn
  double value = 1;          // m, for Constant
};

// mu, sigma of ln(T) for a log-normal T with the given mean and std.
void lognormal_from_moments(double mean, double std, double& mu, double& sigma);
// P(T >= minimum) for the log-normal thickness (1 for Constant).
double thickness_acceptance(const ThicknessSpec& spec);
// One thickness: log-normal redrawn until >= minimum (or the constant).
double draw_thickness(const ThicknessSpec& spec, Stream& rng);

struct LayerSetSpec {
  std::string name;
  double dip_deg = 90;     // joint inclination from +x, counter-clockwise, (0, 180)
  double fsi = 1;          // fracture spacing index = bed thickness / median spacing
  double randomness = 0;   // spacing = median * (1 + r X), X uniform on [-1, 1)
};

struct LayeringSpec {
  double dip_deg = 0;                // bedding dip, deg, counter-clockwise from +x
  ThicknessSpec thickness;
  std::string bedding_set = "bedding";
  std::vector<LayerSetSpec> sets;
};

struct LayeredJoint {
  Segment seg;
  int layer = 0;
  int set = 0;  // index into LayeringSpec::sets
};

struct LayerSetInBed {
  std::size_t joints = 0;        // clipped pieces in the domain
  double total_length = 0;       // m, in the domain
  std::vector<double> spacings;  // normal spacings between consecutive joints in the domain
  double median_spacing() const;
};

struct LayeringOutput {
  std::vector<Layer> layers;                 // bottom/top along the bedding normal
  std::vector<Segment> bed_boundaries;       // interior boundaries clipped to the domain
  std::vector<LayeredJoint> joints;          // clipped to the domain
  std::vector<std::vector<LayerSetInBed>> per_set;  // [set][layer]
  Vec2 along{1, 0};   // unit vector along the beds
  Vec2 normal{0, 1};  // unit bedding normal (coordinate of Layer::bottom/top)
};

// Upper bound of the expected number of beds (the untruncated mean
// thickness is a lower bound of the truncated one), to refuse absurd requests.
double expected_bed_count(const LayeringSpec& spec, const Polygon2& domain);

// Beds from the lowest point of the domain (along the bedding normal) to the
// highest; the last bed is cut by the domain and may be thinner than the
// minimum. Thicknesses come from the stream derive_seed(seed, "layering.thickness").
// target_fsi / realised_fsi are left 0 (generate_layering fills them).
// `drawn_thickness`, if given, receives each bed's drawn thickness: equal to
// top - bottom except for the last bed, which the domain cuts. Joint spacing
// follows from the drawn thickness, since the bed goes on beyond the model.
std::vector<Layer> stack_beds(const LayeringSpec& spec, const Polygon2& domain, std::uint64_t seed,
                              std::vector<double>* drawn_thickness = nullptr);

// Expected number of layered joints for these beds (before clipping).
double expected_layered_joints(const LayeringSpec& spec, const Polygon2& domain, const std::vector<Layer>& beds);

// The beds of stack_beds, their interior boundaries, and the joints of every
// set in every bed (set k in bed i draws from derive_seed(seed,
// "layering.set.<k>", i)). Layer::target_fsi / realised_fsi describe the first
// set (the report has every set).
LayeringOutput generate_layering(const LayeringSpec& spec, const Polygon2& domain, std::uint64_t seed);

}  // namespace dda::dl
