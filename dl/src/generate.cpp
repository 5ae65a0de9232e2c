#include "dda/dl/generate.hpp"

#include <cmath>
#include <sstream>

#include "builder.hpp"
#include "dda/common/coordinate_range.hpp"
#include "dda/common/provenance.hpp"
#include "dda/common/scenario.hpp"

namespace dda::dl {

namespace detail {

int Builder::find_or_add_set(const std::string& name, const std::string& origin) {
  for (std::size_t i = 0; i < model.sets.size(); ++i)
    if (model.sets[i].name == name) return static_cast<int>(i);
  model.sets.push_back({name, origin});
  return static_cast<int>(model.sets.size()) - 1;
}

int Builder::add_new_set(const std::string& name, const std::string& origin, const YamlNode& node,
                         const std::string& key) {
  for (const JointSetInfo& s : model.sets)
    if (s.name == name) node.fail_key(key, "'" + name + "' is already the name of another set (" + s.origin + ")");
  model.sets.push_back({name, origin});
  return static_cast<int>(model.sets.size()) - 1;
}

int Builder::add_clipped(const Segment& s, int set, LineKind kind, int layer) {
  if (model.domain.empty()) {
    model.lines.push_back({s.a, s.b, set, kind, layer});
    return 1;
  }
  int n = 0;
  for (const Segment& piece : clip_segment(model.domain, s)) {
    model.lines.push_back({piece.a, piece.b, set, kind, layer});
    ++n;
  }
  return n;
}

void Builder::check_line_budget(double more, const YamlNode& node, const std::string& key,
                                const std::string& what) const {
  const double total = more + static_cast<double>(model.lines.size());
  if (total > kMaxLines)
    node.fail_key(key, "would make about " + format_number(more, 3) + " " + what + " (" +
                           format_number(total, 3) +
                           " lines in all), more than the limit of 5 million; make the spacing larger or the domain "
                           "smaller");
}

double Builder::domain_area() const { return model.domain.empty() ? 0.0 : std::abs(signed_area(model.domain)); }

std::string format_number(double v, int precision) {
  std::ostringstream s;
  s.precision(precision);
  s << v;
  return s.str();
}

}  // namespace detail

DlResult generate_from_scenario(const YamlNode& root) {
  root.allow(scenario_sections());
  detail::Builder b;
  b.seed = scenario_seed(root);
  b.report["seed"] = b.seed;
  detail::read_domain(root, b);
  // The domain first, before any joint is generated in it; it chooses the
  // local origin every later position is read about.
  check_coordinate_range(b.model.domain, root.file());
  b.model.origin = choose_local_origin(b.model.domain);
  for (Vec2& v : b.model.domain) v -= b.model.origin;
  detail::read_excavations(root, b);
  detail::read_joint_sets(root, b);
  detail::read_layering(root, b);
  detail::read_user_lines(root, b);
  detail::read_traces(root, b);
  detail::read_geometry(root, b);
  detail::read_points(root, b);
  detail::add_totals_to_report(b);
  check_coordinate_range(b.model, root.file());
  // A model without a domain chooses its origin from everything it holds.
  if (b.model.domain.empty()) move_to_local_origin(b.model);

  Provenance& p = b.model.provenance;
  p.scenario_text = root.source_text();
  p.scenario_path = root.file();
  p.seed = b.seed;
  p.program_version = version_string();
  return {std::move(b.model), std::move(b.report)};
}

}  // namespace dda::dl
