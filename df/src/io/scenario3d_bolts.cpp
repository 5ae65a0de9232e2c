// The `bolts` section of a 3D scenario (docs/scenario.md): read as in 2D
// (scenario_bolts.hpp), each end then placed in the block that holds it.
#include <string>
#include <vector>

#include "dda/df/io/scenario3d.hpp"
#include "io/scenario3d_detail.hpp"
#include "io/scenario_bolts.hpp"

namespace dda::df3 {

void add_bolts3(const YamlNode& root, const std::vector<Polyhedron>& blocks, double tolerance, Model3& m) {
  for (df::BoltEntry<Vec3> e : df::read_bolt_entries<Vec3>(root, read_vec3)) {
    e.from -= m.origin, e.to -= m.origin;  // given in the user's coordinates
    const int anchor = block_containing(blocks, e.from, tolerance);
    if (anchor < 0) e.node.fail_key("from", "lies outside every block");
    const int head = block_containing(blocks, e.to, tolerance);
    if (head < 0) e.node.fail_key("to", "lies outside every block");
    if (anchor == head) e.node.fail_key("to", "lies in the same block as `from` (a bolt must join two blocks)");
    if (m.fixed[static_cast<std::size_t>(anchor)] && m.fixed[static_cast<std::size_t>(head)])
      e.node.fail_key("to", "lies in block " + std::to_string(head) + ", which is fixed like block " +
                                std::to_string(anchor) + " of `from`, so the bolt would do nothing");
    Bolt3 b;
    b.name = e.name;
    b.anchor = e.from;
    b.head = e.to;
    b.anchor_block = anchor;
    b.head_block = head;
    b.stiffness = e.stiffness;
    b.pretension = e.pretension;
    b.breaking_force = e.breaking_force;
    m.bolts.push_back(b);
  }
}

}  // namespace dda::df3
