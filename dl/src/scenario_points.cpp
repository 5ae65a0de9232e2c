// Section `points`: named fixed, load, measurement and hole points.
#include "builder.hpp"

namespace dda::dl::detail {

void read_points(const YamlNode& root, Builder& b) {
  for (const YamlNode& n : root.list_or_empty("points")) {
    n.allow({"name", "kind", "at", "block"});
    if (placed_by_block(root, n)) continue;
    ModelPoint p;
    p.name = n.text("name");
    if (p.name.empty()) n.fail_key("name", "must not be empty");
    p.kind = read_point_kind(n);
    const Vec2 at = n.point("at");
    p.p = b.local(at);
    for (const ModelPoint& q : b.model.points)
      if (q.name == p.name) n.fail_key("name", "'" + p.name + "' is already the name of another point");
    if (!b.model.domain.empty() && !point_in_polygon(b.model.domain, p.p))
      n.fail_key("at", "puts point '" + p.name + "' at (" + format_number(at.x()) + ", " + format_number(at.y()) +
                           "), outside the domain");
    b.model.points.push_back(p);
  }
  std::vector<PointKind> kinds;
  for (const ModelPoint& p : b.model.points) kinds.push_back(p.kind);
  b.report["points"] = point_counts(kinds);
}

bool placed_by_block(const YamlNode& root, const YamlNode& item) {
  if (!item.has("block")) return false;
  if (!root.has("control"))
    item.fail_key("block", "places a measurement point on a block, which only the forward run does, but the scenario "
                           "has no control section: give the point's position in at instead");
  return true;
}

PointKind read_point_kind(const YamlNode& n) {
  const std::string kind = n.choice("kind", {"fixed", "load", "measurement", "hole"}, "measurement");
  return kind == "fixed" ? PointKind::Fixed
         : kind == "load" ? PointKind::Load
         : kind == "hole" ? PointKind::Hole
                          : PointKind::Measurement;
}

nlohmann::json point_counts(const std::vector<PointKind>& kinds) {
  nlohmann::json counts = {{"fixed", 0}, {"load", 0}, {"measurement", 0}, {"hole", 0}};
  for (PointKind k : kinds) counts[to_string(k)] = counts[to_string(k)].get<int>() + 1;
  return counts;
}

}  // namespace dda::dl::detail
