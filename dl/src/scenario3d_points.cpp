// Section `points` in 3D: named fixed, load, measurement and hole points.
#include "builder.hpp"
#include "scenario3d_builder.hpp"

namespace dda::dl::detail {

void read_points3(const YamlNode& root, Builder3& b) {
  for (const YamlNode& n : root.list_or_empty("points")) {
    n.allow({"name", "kind", "at"});
    ModelPoint3 p;
    p.name = n.text("name");
    if (p.name.empty()) n.fail_key("name", "must not be empty");
    const std::string kind = n.choice("kind", {"fixed", "load", "measurement", "hole"}, "measurement");
    p.kind = kind == "fixed"  ? PointKind::Fixed
             : kind == "load" ? PointKind::Load
             : kind == "hole" ? PointKind::Hole
                              : PointKind::Measurement;
    p.p = point3(n, "at");
    for (const ModelPoint3& q : b.model.points)
      if (q.name == p.name) n.fail_key("name", "'" + p.name + "' is already the name of another point");
    if (!b.model.domain.contains(p.p))
      n.fail_key("at", "puts point '" + p.name + "' at " + point_text(p.p) + ", outside the domain");
    b.model.points.push_back(p);
  }
  nlohmann::json counts = {{"fixed", 0}, {"load", 0}, {"measurement", 0}, {"hole", 0}};
  for (const ModelPoint3& p : b.model.points) counts[to_string(p.kind)] = counts[to_string(p.kind)].get<int>() + 1;
  b.report["points"] = counts;
}

}  // namespace dda::dl::detail
