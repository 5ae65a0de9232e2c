// Section `joint_sets`: statistical (Shi-Goodman) joint sets.
#include <cmath>

#include "builder.hpp"
#include "dda/dl/statistical.hpp"

namespace dda::dl::detail {

namespace {

StatisticalSetSpec read_set(const YamlNode& n, std::size_t index) {
  n.allow({"name", "dip", "mean_length", "mean_bridge", "mean_spacing", "randomness", "length_randomness",
           "bridge_randomness", "spacing_randomness", "dip_spread"});
  StatisticalSetSpec s;
  std::string fallback_name = "J";  // (not "J" + ...: GCC 12 -Wrestrict false positive)
  fallback_name += std::to_string(index + 1);
  s.name = n.text("name", fallback_name);
  if (s.name.empty()) n.fail_key("name", "must not be empty");
  s.dip_deg = n.number("dip", Range::half_open(0, 180));
  s.mean_length = n.number("mean_length", Range::positive());
  s.mean_bridge = n.number("mean_bridge", Range::non_negative());
  s.mean_spacing = n.number("mean_spacing", Range::positive());
  const double r = n.number("randomness", 0.0, Range::half_open(0, 1));
  s.length_randomness = n.number("length_randomness", r, Range::half_open(0, 1));
  s.bridge_randomness = n.number("bridge_randomness", r, Range::half_open(0, 1));
  s.spacing_randomness = n.number("spacing_randomness", r, Range::half_open(0, 1));
  s.dip_spread_deg = n.number("dip_spread", 0.0, Range::closed(0, 90));
  return s;
}

}  // namespace

void read_joint_sets(const YamlNode& root, Builder& b) {
  nlohmann::json rep = nlohmann::json::array();
  const auto items = root.list_or_empty("joint_sets");
  if (!items.empty() && b.model.domain.empty())
    root.fail_key("joint_sets", "needs a domain to fill; add a domain section");
  for (std::size_t i = 0; i < items.size(); ++i) {
    const YamlNode& n = items[i];
    const StatisticalSetSpec spec = read_set(n, i);
    b.check_line_budget(estimate_statistical_traces(spec, b.model.domain), n, "mean_spacing", "traces");
    const int set = b.add_new_set(spec.name, "statistical", n, "name");
    Stream rng(b.seed, "joint_sets", i);
    const StatisticalSetOutput out = generate_statistical_set(spec, b.model.domain, rng);
    std::size_t pieces = 0;
    double length = 0;
    const std::size_t first = b.model.lines.size();
    for (const Segment& s : out.traces) pieces += static_cast<std::size_t>(b.add_clipped(s, set));
    for (std::size_t k = first; k < b.model.lines.size(); ++k) length += (b.model.lines[k].b - b.model.lines[k].a).norm();
    const StatisticalSetStats& st = out.stats;
    rep.push_back({{"name", spec.name},
                   {"asked",
                    {{"dip", spec.dip_deg},
                     {"mean_length", spec.mean_length},
                     {"mean_bridge", spec.mean_bridge},
                     {"mean_spacing", spec.mean_spacing},
                     {"length_randomness", spec.length_randomness},
                     {"bridge_randomness", spec.bridge_randomness},
                     {"spacing_randomness", spec.spacing_randomness},
                     {"dip_spread", spec.dip_spread_deg}}},
                   {"realised",
                    {{"dip", st.mean_dip_deg()},
                     {"mean_length", st.mean_length()},
                     {"mean_bridge", st.mean_bridge()},
                     {"mean_spacing", st.mean_spacing()},
                     {"scan_lines", st.scan_lines},
                     {"generated_traces", st.traces},
                     {"generated_bridges", st.bridges}}},
                   {"in_domain",
                    {{"traces", pieces},
                     {"total_length", length},
                     {"p21", b.domain_area() > 0 ? length / b.domain_area() : 0.0}}}});
  }
  b.report["statistical_sets"] = rep;
}

}  // namespace dda::dl::detail
