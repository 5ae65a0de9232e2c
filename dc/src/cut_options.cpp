// The `cutting:` section of a scenario.
//
//   cutting:
//     min_segment_length: 0      # m, >= 0; 0 = 1e-9 x model diagonal
//     sliver:
//       min_area: 0              # m^2, >= 0; 0 = no area criterion
//       max_aspect: 0            # max Feret / min Feret, 0 = off, else >= 1
//       merge: true              # merge slivers into a neighbour, else report only
#include <sstream>

#include "dda/common/error.hpp"
#include "dda/dc/cut.hpp"

namespace dda::dc {

CutOptions parse_cut_options(const std::optional<YamlNode>& cutting) {
  CutOptions o;
  if (!cutting) return o;
  const YamlNode& c = *cutting;
  c.allow({"min_segment_length", "sliver"});
  o.min_segment_length = c.number("min_segment_length", 0.0, Range::non_negative());
  if (auto s = c.optional_child("sliver")) {
    s->allow({"min_area", "max_aspect", "merge"});
    o.sliver.min_area = s->number("min_area", 0.0, Range::non_negative());
    o.sliver.max_aspect = s->number("max_aspect", 0.0, Range::non_negative());
    if (o.sliver.max_aspect > 0 && o.sliver.max_aspect < 1) {
      std::ostringstream m;
      m << "must be 0 (off) or >= 1, got " << o.sliver.max_aspect;
      s->fail_key("max_aspect", m.str());
    }
    o.sliver.merge = s->flag("merge", true);
  }
  return o;
}

}  // namespace dda::dc
