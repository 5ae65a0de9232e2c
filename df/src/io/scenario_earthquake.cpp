// loading.earthquake of a 2D scenario: the foundation, and the motion put
// into the model (scenario_earthquake.hpp; keys in docs/scenario.md).
#include "io/scenario_earthquake.hpp"

#include <algorithm>
#include <set>

#include "dda/common/error.hpp"

namespace dda::df {

EarthquakeEntry read_earthquake(const YamlNode& n) {
  n.allow({"record", "units", "direction", "components", "scale", "resample", "filter", "ramp", "baseline", "mode",
           "foundation"});
  EarthquakeEntry e{n, read_earthquake_record<2>(n), std::nullopt};
  if (n.has("foundation")) {
    e.foundation.emplace();
    const std::vector<YamlNode> items = n.list("foundation");
    if (items.empty()) n.fail_key("foundation", "must name at least one fixed point or side");
    for (const YamlNode& item : items) e.foundation->emplace_back(item, item.as_text());
  }
  return e;
}

namespace {

// Incident mode: marks the viscous edges of the entry sides as input.
void mark_input_sides(const EarthquakeEntry& e, const ViscousSides& viscous, ModelInput& in) {
  std::vector<std::pair<YamlNode, std::string>> sides;
  if (e.foundation) sides = *e.foundation;
  else sides.emplace_back(e.node, "bottom");
  for (const auto& [node, side] : sides) {
    const auto it = viscous.find(side);
    if (it == viscous.end()) {
      const std::string what = "the incident wave enters through side " + side +
                               ", which boundaries.viscous does not list (add it there)";
      if (e.foundation) node.fail(what);
      e.node.fail_key("mode", std::string("incident needs a viscous boundary: ") + what);
    }
    for (const std::size_t k : it->second) in.viscous_boundary->edges[k].input = true;
  }
}

}  // namespace

void apply_earthquake(const EarthquakeEntry& e, const std::vector<std::string>& boundary_sides,
                      const ViscousSides& viscous, ModelInput& in) {
  std::vector<std::size_t> foundation;
  if (e.record.mode.route == GroundMotionRoute::incident_wave) {
    mark_input_sides(e, viscous, in);
  } else if (!e.foundation) {
    for (std::size_t k = 0; k < in.fixed_points.size(); ++k) foundation.push_back(k);
  } else {
    std::set<std::size_t> chosen;
    for (const auto& [node, name] : *e.foundation) {
      const bool side = name == "bottom" || name == "top" || name == "left" || name == "right";
      const std::string prefix = "boundary_" + name + "_";
      std::size_t found = 0;
      for (std::size_t k = 0; k < in.fixed_points.size(); ++k) {
        const std::string& fp = in.fixed_points[k].name;
        if (side ? fp.rfind(prefix, 0) == 0 : fp == name) chosen.insert(k), ++found;
      }
      if (found > 0) continue;
      if (side) {
        const bool listed = std::find(boundary_sides.begin(), boundary_sides.end(), name) != boundary_sides.end();
        node.fail(listed ? "selects the fixed.boundary points of side " + name + ", but there are none"
                         : "names side " + name + ", which fixed.boundary does not hold (add it there)");
      }
      std::string known;
      for (const FixedPoint& f : in.fixed_points)
        if (f.name.rfind("boundary_", 0) != 0) known += (known.empty() ? "" : ", ") + f.name;
      node.fail("names '" + name + "', which is neither a fixed point nor a side of fixed.boundary (fixed points: " +
                (known.empty() ? "none" : known) + ")");
    }
    foundation.assign(chosen.begin(), chosen.end());
  }
  try {
    apply_ground_motion(e.record.motion, e.record.mode, foundation, in);
  } catch (const InputError& err) {
    e.node.fail_key(e.foundation ? "foundation" : "mode", "cannot be applied: " + sentence_tail(err));
  }
}

}  // namespace dda::df
