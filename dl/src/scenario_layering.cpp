// Section `layering`: beds of log-normal thickness and joints bounded by them.
#include <cmath>

#include "builder.hpp"
#include "dda/common/coordinate_range.hpp"
#include "dda/common/error.hpp"
#include "dda/dl/layering.hpp"

namespace dda::dl::detail {

namespace {

LayerSetSpec read_layer_set(const YamlNode& n, std::size_t index, double bedding_dip) {
  n.allow({"name", "dip", "fsi", "randomness"});
  LayerSetSpec s;
  std::string fallback_name = "L";  // (not "L" + ...: GCC 12 -Wrestrict false positive)
  fallback_name += std::to_string(index + 1);
  s.name = n.text("name", fallback_name);
  if (s.name.empty()) n.fail_key("name", "must not be empty");
  s.dip_deg = n.number("dip", 90.0, Range::half_open(0, 180));
  s.fsi = n.number("fsi", Range::positive());
  s.randomness = n.number("randomness", 0.0, Range::half_open(0, 1));
  const double rel = std::abs(std::sin(deg2rad(s.dip_deg - bedding_dip)));
  if (rel < std::sin(deg2rad(5.0)))
    n.fail_key("dip", "must differ from the bedding dip by at least 5 degrees (the joints would run along the beds)");
  return s;
}

}  // namespace

// Smallest acceptance probability of the truncated log-normal we accept: below
// it the minimum sits so far in the upper tail that the thickness
// distribution asked for is not what would be drawn.
constexpr double kMinAcceptance = 0.01;

ThicknessSpec read_thickness(const YamlNode& n) {
  ThicknessSpec t;
  const std::string dist = n.choice("distribution", {"lognormal", "constant"}, "lognormal");
  if (dist == "constant") {
    n.allow({"distribution", "value"});
    t.kind = ThicknessSpec::Kind::Constant;
    t.value = n.number("value", Range::positive());
    return t;
  }
  n.allow({"distribution", "mean", "std", "mu", "sigma", "minimum"});
  t.kind = ThicknessSpec::Kind::LogNormal;
  const std::string which = n.one_of({"mean", "mu"});
  if (which == "mean") {
    if (n.has("sigma")) n.fail_key("sigma", "goes with mu, not with mean (give mean and std, or mu and sigma)");
    const double mean = n.number("mean", Range::positive());
    const double std = n.number("std", Range::non_negative());
    lognormal_from_moments(mean, std, t.mu, t.sigma);
    // (std / mean)^2 overflows for a mean this small against its std (found
    // by the fuzz target scenario2d: mean 4.9e-324): ln(thickness) would have
    // no finite mu and sigma, and no draw could ever reach the minimum.
    if (!std::isfinite(t.mu) || !std::isfinite(t.sigma))
      n.fail_key("mean", "is too small for a log-normal thickness with std " + format_number(std) +
                             " (the logarithm of the thickness would have no finite mean and spread)");
  } else {
    if (n.has("std")) n.fail_key("std", "goes with mean, not with mu (give mean and std, or mu and sigma)");
    t.mu = n.number("mu", Range::any());
    t.sigma = n.number("sigma", Range::non_negative());
  }
  t.minimum = n.number("minimum", 0.0, Range::non_negative());
  const double p = thickness_acceptance(t);
  if (p < kMinAcceptance)
    n.fail_key("minimum", "leaves only " + format_number(100 * p, 3) +
                              "% of the log-normal thicknesses (at least 1% must reach the minimum); lower the "
                              "minimum or raise the mean");
  return t;
}

void read_layering(const YamlNode& root, Builder& b) {
  const auto node = root.optional_child("layering");
  if (!node) {
    b.report["layering"] = nullptr;
    return;
  }
  const YamlNode& n = *node;
  n.allow({"dip", "thickness", "bedding_set", "sets"});
  if (b.model.domain.empty()) root.fail_key("layering", "needs a domain to fill; add a domain section");
  LayeringSpec spec;
  spec.dip_deg = n.number("dip", 0.0, Range{-90, 90, true, true});
  spec.thickness = read_thickness(n.child("thickness"));
  spec.bedding_set = n.text("bedding_set", "bedding");
  if (spec.bedding_set.empty()) n.fail_key("bedding_set", "must not be empty");
  const auto set_nodes = n.list_or_empty("sets");
  for (std::size_t k = 0; k < set_nodes.size(); ++k) spec.sets.push_back(read_layer_set(set_nodes[k], k, spec.dip_deg));

  b.check_line_budget(expected_bed_count(spec, b.model.domain), n, "thickness", "beds");
  const std::vector<Layer> beds = stack_beds(spec, b.model.domain, b.seed);
  const double joints = expected_layered_joints(spec, b.model.domain, beds);
  b.check_line_budget(joints + static_cast<double>(beds.size()), n, "sets", "layered joints");

  const int bedding = b.add_new_set(spec.bedding_set, "bedding", n, "bedding_set");
  std::vector<int> set_ids;
  for (std::size_t k = 0; k < spec.sets.size(); ++k)
    set_ids.push_back(b.add_new_set(spec.sets[k].name, "layered", set_nodes[k], "name"));

  const LayeringOutput out = generate_layering(spec, b.model.domain, b.seed);
  if (out.layers.size() != beds.size()) throw InternalError("layering: beds differ between two stackings");
  for (const Segment& s : out.bed_boundaries) b.model.lines.push_back({s.a, s.b, bedding, LineKind::Bedding, -1});
  for (const LayeredJoint& j : out.joints)
    b.model.lines.push_back({j.seg.a, j.seg.b, set_ids[static_cast<std::size_t>(j.set)], LineKind::Joint, j.layer});
  b.model.layers = out.layers;
  b.model.bedding_dip_deg = spec.dip_deg;

  // Report: beds, thickness statistics and each set per bed.
  nlohmann::json layers = nlohmann::json::array();
  double sum = 0, sum2 = 0, tmin = 1e300, tmax = 0;
  const std::size_t nfull = out.layers.empty() ? 0 : out.layers.size() - 1;  // the last bed is cut
  // Beds are levels about the local origin; the report gives the user's levels.
  const double level0 = level_along_beds(b.model.origin, spec.dip_deg);
  for (std::size_t i = 0; i < out.layers.size(); ++i) {
    const Layer& l = out.layers[i];
    std::size_t joints_in_bed = 0;
    for (const auto& per : out.per_set) joints_in_bed += per[i].joints;
    layers.push_back({{"index", i},
                      {"bottom", user_level(l.bottom, level0)},
                      {"top", user_level(l.top, level0)},
                      {"thickness", l.thickness()},
                      {"target_fsi", l.target_fsi},
                      {"realised_fsi", l.realised_fsi},
                      {"joints", joints_in_bed}});
    if (i < nfull) {
      sum += l.thickness();
      sum2 += l.thickness() * l.thickness();
      tmin = std::min(tmin, l.thickness());
      tmax = std::max(tmax, l.thickness());
    }
  }
  const double mean = nfull ? sum / nfull : 0;
  const double var = nfull > 1 ? (sum2 - nfull * mean * mean) / (nfull - 1) : 0;
  nlohmann::json sets = nlohmann::json::array();
  for (std::size_t k = 0; k < spec.sets.size(); ++k) {
    nlohmann::json per_layer = nlohmann::json::array();
    std::size_t count = 0;
    double length = 0;
    for (std::size_t i = 0; i < out.layers.size(); ++i) {
      const LayerSetInBed& st = out.per_set[k][i];
      const double h = out.layers[i].thickness();
      const double m = st.median_spacing();
      count += st.joints;
      length += st.total_length;
      per_layer.push_back({{"layer", i},
                           {"asked_median_spacing", h / spec.sets[k].fsi},
                           {"realised_median_spacing", m},
                           {"realised_fsi", m > 0 ? h / m : 0.0},
                           {"joints", st.joints}});
    }
    sets.push_back({{"name", spec.sets[k].name},
                    {"dip", spec.sets[k].dip_deg},
                    {"fsi", spec.sets[k].fsi},
                    {"randomness", spec.sets[k].randomness},
                    {"joints", count},
                    {"total_length", length},
                    {"per_layer", per_layer}});
  }
  b.report["layering"] = {{"bedding_dip", spec.dip_deg},
                          {"bedding_set", spec.bedding_set},
                          {"beds", out.layers.size()},
                          {"bed_boundaries", out.bed_boundaries.size()},
                          {"thickness",
                           {{"acceptance", thickness_acceptance(spec.thickness)},
                            {"minimum", spec.thickness.minimum},
                            {"full_beds", nfull},
                            {"mean", mean},
                            {"std", std::sqrt(std::max(0.0, var))},
                            {"min", nfull ? tmin : 0.0},
                            {"max", tmax}}},
                          {"layers", layers},
                          {"sets", sets}};
}

}  // namespace dda::dl::detail
