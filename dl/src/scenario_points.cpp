// Section `points`: named fixed, load, measurement and hole points.
#include "builder.hpp"

namespace dda::dl::detail {

void read_points(const YamlNode& root, Builder& b) {
  for (const YamlNode& n : root.list_or_empty("points")) {
    n.allow({"name", "kind", "at"});
    ModelPoint p;
    p.name = n.text("name");
    if (p.name.empty()) n.fail_key("name", "must not be empty");
    const std::string kind = n.choice("kind", {"fixed", "load", "measurement", "hole"}, "measurement");
    p.kind = kind == "fixed" ? PointKind::Fixed
             : kind == "load" ? PointKind::Load
             : kind == "hole" ? PointKind::Hole
                              : PointKind::Measurement;
    p.p = n.point("at");
    for (const ModelPoint& q : b.model.points)
      if (q.name == p.name) n.fail_key("name", "'" + p.name + "' is already the name of another point");
    if (!b.model.domain.empty() && !point_in_polygon(b.model.domain, p.p))
      n.fail_key("at", "puts point '" + p.name + "' at (" + format_number(p.p.x()) + ", " + format_number(p.p.y()) +
                           "), outside the domain");
    b.model.points.push_back(p);
  }
  nlohmann::json counts = {{"fixed", 0}, {"load", 0}, {"measurement", 0}, {"hole", 0}};
  for (const ModelPoint& p : b.model.points) {
    const char* k = p.kind == PointKind::Fixed ? "fixed"
                    : p.kind == PointKind::Load ? "load"
                    : p.kind == PointKind::Hole ? "hole"
                                                : "measurement";
    counts[k] = counts[k].get<int>() + 1;
  }
  b.report["points"] = counts;
}

}  // namespace dda::dl::detail
