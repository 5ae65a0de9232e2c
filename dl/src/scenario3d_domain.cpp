// Section `domain` in 3D: {box: [x0, y0, z0, x1, y1, z1]} or {surface: file}.
#include <cmath>

#include "builder.hpp"
#include "dda/common/scenario.hpp"
#include "dda/common/triangle_mesh.hpp"
#include "scenario3d_builder.hpp"

namespace dda::dl::detail {

namespace {

// A closed surface (STL, OBJ) bounds the rock; the box the fractures are
// generated in is its bounding box.
void read_surface_domain(const YamlNode& root, const YamlNode& node, Builder3& b) {
  // The 2D sections (dl/src/trace_plane.cpp) are outlined by the box.
  if (root.has("trace_planes"))
    node.fail_key("surface", "cannot be sectioned by trace_planes yet (leave out trace_planes, or use a box)");
  const std::string file = node.text("surface");
  TriangleMesh mesh;
  try {
    mesh = read_triangle_mesh(resolve_scenario_path(node, file));
  } catch (const InputError& e) {
    fail_from(node, "surface", "names a surface file with an error", e);
  }
  b.model.domain = mesh_bounds(mesh);
  const Vec3 lo = b.model.domain.lo, hi = b.model.domain.hi;
  b.report["domain"] = {{"surface", file},
                        {"vertices", mesh.vertices.size()},
                        {"triangles", mesh.triangles.size()},
                        {"box", {lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z()}},
                        {"box_volume", b.model.domain.volume()},
                        {"volume", enclosed_volume(mesh)}};
  b.model.domain_surface = std::move(mesh);
}

}  // namespace

void read_domain3(const YamlNode& root, Builder3& b) {
  const auto node = root.optional_child("domain");
  if (!node) root.fail_key("domain", "is required (a box [x0, y0, z0, x1, y1, z1] or a surface file)");
  node->allow({"box", "surface"});
  if (node->has("surface")) {
    if (node->has("box")) node->fail("must give either box or surface, not both (a surface's box is its bounding box)");
    read_surface_domain(root, *node, b);
    return;
  }
  const YamlNode box = node->child("box");
  if (!box.is_sequence()) box.fail("must be [x0, y0, z0, x1, y1, z1]");
  const auto v = box.as_numbers();
  if (v.size() != 6) box.fail("must be [x0, y0, z0, x1, y1, z1], got " + std::to_string(v.size()) + " numbers");
  if (!(v[3] > v[0] && v[4] > v[1] && v[5] > v[2])) box.fail("must have x1 > x0, y1 > y0 and z1 > z0");
  b.model.domain = {Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5])};
  b.report["domain"] = {{"box", v}, {"volume", b.model.domain.volume()}};
}

}  // namespace dda::dl::detail
