// Section `layering` in 3D: beds along the bedding normal and joint sets
// bounded by them (generate_layering3d), with each bed's realised FSI.
#include <algorithm>
#include <cmath>

#include "builder.hpp"
#include "dda/common/coordinate_range.hpp"
#include "dda/dl/dfn3d.hpp"
#include "dda/dl/layering3d.hpp"
#include "scenario3d_builder.hpp"

namespace dda::dl::detail {

namespace {

constexpr double kMinAngleToBedsDeg = 5;  // generate_layering3d's rule, checked here to name the key

LayerSetSpec3 read_layer_set3(const YamlNode& n, std::size_t index, const Vec3& bed_normal) {
  n.allow({"name", "dip", "dip_direction", "fsi", "randomness"});
  LayerSetSpec3 s;
  s.name = read_name(n, "L", index);
  s.dip_deg = read_dip(n, "dip", 90.0);
  s.dip_direction_deg = read_dip_direction(n, "dip_direction", 0.0);
  s.fsi = n.number("fsi", Range::positive());
  s.randomness = n.number("randomness", 0.0, Range::half_open(0, 1));
  if (normal_from_dip(s.dip_deg, s.dip_direction_deg).cross(bed_normal).norm() < std::sin(deg2rad(kMinAngleToBedsDeg)))
    n.fail_key("dip",
               "must make an angle of at least 5 degrees with the bedding (the joints would run along the beds)");
  return s;
}

nlohmann::json thickness_summary(const ThicknessSpec& t, const std::vector<Layer>& layers) {
  // The last bed is cut by the domain: only the full beds sample the law.
  const std::size_t full = layers.empty() ? 0 : layers.size() - 1;
  double sum = 0, sum2 = 0, lo = 0, hi = 0;
  for (std::size_t i = 0; i < full; ++i) {
    const double h = layers[i].thickness();
    sum += h;
    sum2 += h * h;
    lo = i == 0 ? h : std::min(lo, h);
    hi = std::max(hi, h);
  }
  const double mean = full ? sum / static_cast<double>(full) : 0;
  const double var = full > 1 ? (sum2 - static_cast<double>(full) * mean * mean) / static_cast<double>(full - 1) : 0;
  return {{"acceptance", thickness_acceptance(t)},
          {"minimum", t.minimum},
          {"full_beds", full},
          {"mean", mean},
          {"std", std::sqrt(std::max(0.0, var))},
          {"min", lo},
          {"max", hi}};
}

}  // namespace

void read_layering3(const YamlNode& root, Builder3& b) {
  const auto node = root.optional_child("layering");
  if (!node) {
    b.report["layering"] = nullptr;
    return;
  }
  const YamlNode& n = *node;
  n.allow({"dip", "dip_direction", "thickness", "bedding_set", "sets"});
  LayeringSpec3 spec;
  spec.dip_deg = read_dip(n, "dip", 0.0);
  spec.dip_direction_deg = read_dip_direction(n, "dip_direction", 0.0);
  spec.thickness = read_thickness(n.child("thickness"));
  spec.bedding_set = n.text("bedding_set", "bedding");
  if (spec.bedding_set.empty()) n.fail_key("bedding_set", "must not be empty");
  const Vec3 nb = normal_from_dip(spec.dip_deg, spec.dip_direction_deg);
  const auto set_nodes = n.list_or_empty("sets");
  for (std::size_t k = 0; k < set_nodes.size(); ++k) {
    spec.sets.push_back(read_layer_set3(set_nodes[k], k, nb));
    b.check_set_name_free(spec.sets[k].name, set_nodes[k], "name");
    for (std::size_t j = 0; j < k; ++j)
      if (spec.sets[j].name == spec.sets[k].name)
        set_nodes[k].fail_key("name", "'" + spec.sets[k].name + "' is already the name of another layered set");
  }
  b.check_set_name_free(spec.bedding_set, n, "bedding_set");
  for (const LayerSetSpec3& s : spec.sets)
    if (s.name == spec.bedding_set) n.fail_key("bedding_set", "'" + s.name + "' is already the name of a layered set");

  LayeringOutput3 out;
  try {
    out = generate_layering3d(spec, b.model.domain, b.seed);
  } catch (const InputError& e) {
    // Left after the checks above: the limits on beds and joints.
    fail_from(n, "thickness", "cannot be generated", e);
  }
  const int base = static_cast<int>(b.model.sets.size());
  add_layering(b.model, spec, out);
  b.asked_p32.resize(b.model.sets.size());

  nlohmann::json beds = nlohmann::json::array();
  const double level0 = b.model.bed_normal.dot(b.model.origin);  // the report gives the user's levels
  for (std::size_t i = 0; i < out.layers.size(); ++i) {
    const Layer& l = out.layers[i];
    beds.push_back({{"index", i},
                    {"bottom", user_level(l.bottom, level0)},
                    {"top", user_level(l.top, level0)},
                    {"thickness", l.thickness()},
                    {"drawn_thickness", out.drawn_thickness[i]},
                    {"target_fsi", l.target_fsi},
                    {"realised_fsi", l.realised_fsi}});
  }
  nlohmann::json sets = nlohmann::json::array();
  for (std::size_t k = 0; k < spec.sets.size(); ++k) {
    nlohmann::json per_bed = nlohmann::json::array();
    std::size_t joints = 0;
    double area = 0;
    for (std::size_t i = 0; i < out.layers.size(); ++i) {
      const BedSetStats& st = out.per_set[k][i];
      joints += st.joints;
      area += st.area;
      per_bed.push_back({{"bed", i},
                         {"asked_median_spacing", st.target_median},
                         {"realised_median_spacing", st.median_spacing()},
                         {"target_fsi", spec.sets[k].fsi},
                         {"realised_fsi", st.realised_fsi},
                         {"joints", st.joints}});
    }
    sets.push_back({{"name", spec.sets[k].name},
                    {"set", base + static_cast<int>(k)},
                    {"dip", spec.sets[k].dip_deg},
                    {"dip_direction", spec.sets[k].dip_direction_deg},
                    {"fsi", spec.sets[k].fsi},
                    {"randomness", spec.sets[k].randomness},
                    {"joints", joints},
                    {"area", area},
                    {"per_bed", per_bed}});
  }
  b.report["layering"] = {{"dip", spec.dip_deg},
                          {"dip_direction", spec.dip_direction_deg},
                          {"bedding_set", spec.bedding_set},
                          {"beds", out.layers.size()},
                          {"bed_boundaries", out.bed_boundaries.size()},
                          {"thickness", thickness_summary(spec.thickness, out.layers)},
                          {"layers", beds},
                          {"sets", sets}};
}

}  // namespace dda::dl::detail
