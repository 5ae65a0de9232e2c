// Selecting blocks in a 3D scenario (scenario3d_detail.hpp; keys in
// docs/scenario.md). A geotechnical model names its blocks by what an
// engineer knows of them: their id or body in the blocks file, where their
// centroid lies (below a level, inside or outside a box), or their
// block-theory class. `fixed` holds the blocks so selected and each
// `materials.zones` item gives them its material; both read and apply the
// keys here, so they mean the same thing in both places.
#include <cmath>
#include <set>

#include "dda/common/error.hpp"
#include "io/scenario3d_detail.hpp"

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

BlockSelection3 read_block_selection(const YamlNode& n) {
  BlockSelection3 s;
  if (n.has("blocks")) s.blocks = read_ids(n, "blocks");
  if (n.has("bodies")) s.bodies = read_ids(n, "bodies");
  if (n.has("below")) s.below = n.number("below");
  if (n.has("box")) s.box = read_box(n, "box");
  if (n.has("outside")) s.outside = read_box(n, "outside");
  for (const YamlNode& item : n.list_or_empty("removability")) {
    try {
      s.removability.emplace_back(item, removability_from_string(item.as_text()));
    } catch (const InputError&) {
      item.fail("must be a block-theory class (not_exposed, tapered, removable, falls, slides_one_face, "
                "slides_two_faces), got '" + item.as_text() + "'");
    }
  }
  return s;
}

std::vector<bool> select_blocks(const BlockSelection3& s, const YamlNode& n, const PolyhedronModel& blocks,
                                const std::string& blocks_path) {
  const std::size_t count = blocks.blocks.size();
  std::vector<bool> selected(count, false);
  // Marks the blocks `pick` selects; a selection that holds nothing is a mistake.
  auto select = [&](const std::string& key, auto pick) {
    int picked = 0;
    for (std::size_t b = 0; b < count; ++b)
      if (pick(b)) selected[b] = true, ++picked;
    if (picked == 0) n.fail_key(key, "selects no block of " + blocks_path);
  };
  for (const auto& [node, id] : s.blocks)
    if (id >= static_cast<long long>(count))
      node.fail("is block " + std::to_string(id) + ", but " + blocks_path + " has " + std::to_string(count) +
                " blocks (ids 0 to " + std::to_string(count - 1) + ")");
    else
      selected[static_cast<std::size_t>(id)] = true;
  for (const auto& [node, id] : s.bodies) {
    if (id >= static_cast<long long>(blocks.bodies.size()))
      node.fail("is body " + std::to_string(id) + ", but " + blocks_path + " has " +
                std::to_string(blocks.bodies.size()) + " bodies");
    for (const int part : blocks.bodies[static_cast<std::size_t>(id)].parts)
      selected[static_cast<std::size_t>(part)] = true;
  }
  const auto& bl = blocks.blocks;
  // Levels and boxes are given in the user's coordinates; the blocks lie
  // about their local origin (coordinate_range.hpp).
  const Vec3 o = blocks.origin;
  auto local = [&](const Box3& box) { return Box3{box.lo - o, box.hi - o}; };
  if (s.below) select("below", [&](std::size_t b) { return bl[b].centroid.z() < *s.below - o.z(); });
  if (s.box) select("box", [&](std::size_t b) { return local(*s.box).contains(bl[b].centroid); });
  if (s.outside) select("outside", [&](std::size_t b) { return !local(*s.outside).contains(bl[b].centroid); });
  if (!s.removability.empty()) {
    std::set<Removability> classes;
    for (const auto& r : s.removability) classes.insert(r.second);
    select("removability", [&](std::size_t b) {
      const int body = bl[b].body;
      return body >= 0 && static_cast<std::size_t>(body) < blocks.bodies.size() &&
             classes.count(blocks.bodies[static_cast<std::size_t>(body)].removability) > 0;
    });
  }
  return selected;
}

}  // namespace dda::df3
