#pragma once
// The analytical case of a wedge study: the document under `wedge:` read
// strictly, and the measures of `dda wedge` (limit equilibrium,
// tools/analysis/wedge.hpp) computed from it.
//
//   plane1: {dip: 51.4, dip_direction: 65.8}
//   plane2: {dip: 51.4, dip_direction: 295.2}
//   phi: 30            # both planes, or phi1 and phi2
//   azimuth: 180       # shaking direction for the yield acceleration
//                      # (default: the trend of the line of intersection)
#include <optional>
#include <vector>

#include "dda/analysis/wedge.hpp"
#include "dda/common/yaml_reader.hpp"
#include "dda/study/measure.hpp"

namespace dda::study {

struct WedgeCase {
  analysis::WedgeSpec spec;
  std::optional<double> azimuth_deg;
};

WedgeCase read_wedge_case(const YamlNode& node);

// One value per measure, in order; NaN where there is none (no yield
// acceleration up to 10 g, no critical friction angle).
std::vector<double> wedge_measures(const WedgeCase& c, const std::vector<MeasureSpec>& measures);

}  // namespace dda::study
