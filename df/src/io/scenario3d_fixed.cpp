// The `fixed` section of a 3D scenario (scenario3d_detail.hpp; keys in
// docs/scenario.md). A geotechnical model holds its rock mass by blocks, not
// by points: a base block under a slide, the whole mass around a wedge, the
// foundation of a shaking table. So blocks are selected by id, by body, by
// where their centroid lies (below a level, inside or outside a box), or by
// their block-theory class (scenario3d_select.cpp), and a selected block has
// no unknowns at all.
#include "dda/common/error.hpp"
#include "io/scenario3d_detail.hpp"

namespace dda::df3 {

FixedSpec3 read_fixed3(const YamlNode& root) {
  FixedSpec3 s;
  s.node = root.optional_child("fixed");
  if (!s.node) return s;
  const YamlNode& f = *s.node;
  f.allow({"blocks", "bodies", "below", "box", "outside", "removability", "points"});
  s.selection = read_block_selection(f);
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
  if (!s.node) return std::vector<bool>(n, false);
  const YamlNode& f = *s.node;
  const std::vector<bool> fixed = select_blocks(s.selection, f, blocks, blocks_path);
  bool any_free = false;
  for (const bool x : fixed) any_free = any_free || !x;
  if (n > 0 && !any_free) f.fail("fixes every block of " + blocks_path + ", so nothing can move");
  return fixed;
}

}  // namespace dda::df3
