// The `fixed` section of a 3D scenario (scenario3d_detail.hpp; keys in
// docs/scenario.md). A geotechnical model holds its rock mass by blocks, not
// by points: a base block under a slide, the whole mass around a wedge, the
// foundation of a shaking table. So blocks are selected by id, by body, by
// where their centroid lies (below a level, inside or outside a box), or by
// their block-theory class, and a selected block has no unknowns at all.
#include <cmath>
#include <set>

#include "dda/common/error.hpp"
#include "scenario3d_detail.hpp"

namespace dda::df3 {
namespace {

Box3 read_box(const YamlNode& n, const std::string& key) {
  const YamlNode b = n.child(key);
  const std::vector<double> v = b.as_numbers();
  if (v.size() != 6) b.fail("must be [x0, y0, z0, x1, y1, z1], got " + std::to_string(v.size()) + " numbers");
  for (double x : v)
    if (!std::isfinite(x)) b.fail("must hold finite numbers");
  if (!(v[3] > v[0] && v[4] > v[1] && v[5] > v[2])) b.fail("must have x1 > x0, y1 > y0 and z1 > z0");
  return {Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5])};
}

std::vector<std::pair<YamlNode, long long>> read_ids(const YamlNode& n, const std::string& key) {
  std::vector<std::pair<YamlNode, long long>> out;
  const std::vector<YamlNode> items = n.list(key);
  if (items.empty()) n.fail_key(key, "must list at least one id");
  for (const YamlNode& item : items) out.emplace_back(item, item.as_integer(Range::non_negative()));
  return out;
}

}  // namespace

FixedSpec3 read_fixed3(const YamlNode& root) {
  FixedSpec3 s;
  s.node = root.optional_child("fixed");
  if (!s.node) return s;
  const YamlNode& f = *s.node;
  f.allow({"blocks", "bodies", "below", "box", "outside", "removability", "points"});
  if (f.has("blocks")) s.blocks = read_ids(f, "blocks");
  if (f.has("bodies")) s.bodies = read_ids(f, "bodies");
  if (f.has("below")) s.below = f.number("below");
  if (f.has("box")) s.box = read_box(f, "box");
  if (f.has("outside")) s.outside = read_box(f, "outside");
  for (const YamlNode& item : f.list_or_empty("removability")) {
    try {
      s.removability.emplace_back(item, removability_from_string(item.as_text()));
    } catch (const InputError&) {
      item.fail("must be a block-theory class (not_exposed, tapered, removable, falls, slides_one_face, "
                "slides_two_faces), got '" + item.as_text() + "'");
    }
  }
  for (const YamlNode& item : f.list_or_empty("points")) {
    item.allow({"point", "penalty", "displacement"});
    FixedSpec3::Point p{item, item.text("point"), 0, std::nullopt};
    if (item.has("penalty")) p.penalty = item.number("penalty", Range::positive());
    if (item.has("displacement")) p.displacement = read_history3(item, "displacement");
    s.points.push_back(p);
  }
  return s;
}

std::vector<bool> select_fixed_blocks(const FixedSpec3& s, const PolyhedronModel& blocks,
                                      const std::string& blocks_path) {
  const std::size_t n = blocks.blocks.size();
  std::vector<bool> fixed(n, false);
  if (!s.node) return fixed;
  const YamlNode& f = *s.node;
  // Marks the blocks `pick` selects; a selection that holds nothing is a mistake.
  auto select = [&](const std::string& key, auto pick) {
    int count = 0;
    for (std::size_t b = 0; b < n; ++b)
      if (pick(b)) fixed[b] = true, ++count;
    if (count == 0) f.fail_key(key, "selects no block of " + blocks_path);
  };
  for (const auto& [node, id] : s.blocks)
    if (id >= static_cast<long long>(n))
      node.fail("is block " + std::to_string(id) + ", but " + blocks_path + " has " + std::to_string(n) +
                " blocks (ids 0 to " + std::to_string(n - 1) + ")");
    else
      fixed[static_cast<std::size_t>(id)] = true;
  for (const auto& [node, id] : s.bodies) {
    if (id >= static_cast<long long>(blocks.bodies.size()))
      node.fail("is body " + std::to_string(id) + ", but " + blocks_path + " has " +
                std::to_string(blocks.bodies.size()) + " bodies");
    for (const int part : blocks.bodies[static_cast<std::size_t>(id)].parts) fixed[static_cast<std::size_t>(part)] = true;
  }
  const auto& bl = blocks.blocks;
  if (s.below) select("below", [&](std::size_t b) { return bl[b].centroid.z() < *s.below; });
  if (s.box) select("box", [&](std::size_t b) { return s.box->contains(bl[b].centroid); });
  if (s.outside) select("outside", [&](std::size_t b) { return !s.outside->contains(bl[b].centroid); });
  if (!s.removability.empty()) {
    std::set<Removability> classes;
    for (const auto& r : s.removability) classes.insert(r.second);
    select("removability", [&](std::size_t b) {
      const int body = bl[b].body;
      return body >= 0 && static_cast<std::size_t>(body) < blocks.bodies.size() &&
             classes.count(blocks.bodies[static_cast<std::size_t>(body)].removability) > 0;
    });
  }
  bool any_free = false;
  for (const bool x : fixed) any_free = any_free || !x;
  if (n > 0 && !any_free) f.fail("fixes every block of " + blocks_path + ", so nothing can move");
  return fixed;
}

}  // namespace dda::df3
