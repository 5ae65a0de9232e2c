// Section `points` in 3D: named fixed, load, measurement and hole points.
#include "builder.hpp"
#include "scenario3d_builder.hpp"

namespace dda::dl::detail {

void read_points3(const YamlNode& root, Builder3& b) {
  for (const YamlNode& n : root.list_or_empty("points")) {
    n.allow({"name", "kind", "at", "block"});
    if (placed_by_block(root, n)) continue;
    ModelPoint3 p;
    p.name = n.text("name");
    if (p.name.empty()) n.fail_key("name", "must not be empty");
    p.kind = read_point_kind(n);
    const Vec3 at = point3(n, "at");
    p.p = b.local(at);
    for (const ModelPoint3& q : b.model.points)
      if (q.name == p.name) n.fail_key("name", "'" + p.name + "' is already the name of another point");
    if (!b.model.domain.contains(p.p))
      n.fail_key("at", "puts point '" + p.name + "' at " + point_text(at) + ", outside the domain");
    b.model.points.push_back(p);
  }
  std::vector<PointKind> kinds;
  for (const ModelPoint3& p : b.model.points) kinds.push_back(p.kind);
  b.report["points"] = point_counts(kinds);
}

}  // namespace dda::dl::detail
