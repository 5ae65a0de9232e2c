// ParaView files of fractures and polyhedral blocks; see vtk3d.hpp.
#include "dda/common/vtk3d.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "dda/common/vtu_writer.hpp"

namespace dda {
namespace {

using Polygon3 = std::vector<Vec3>;

constexpr int kVtkTriangle = 5;
constexpr std::int32_t kSurfaceShape = 3;  // `shape` of a surface triangle (after the FractureShape codes)

// e1, e2 with (e1, e2, n) a right-handed orthonormal frame, so that
// cos t e1 + sin t e2 turns counter-clockwise about the unit normal n. The
// coordinate axis least aligned with n keeps the cross product well
// conditioned.
std::pair<Vec3, Vec3> in_plane_axes(const Vec3& n) {
  Eigen::Index k = 0;
  n.cwiseAbs().minCoeff(&k);
  Vec3 a = Vec3::Zero();
  a[k] = 1;
  const Vec3 e1 = a.cross(n).normalized();
  return {e1, n.cross(e1)};
}

// The part of a convex polygon inside h (one Sutherland-Hodgman pass); the
// order of the vertices, hence the orientation, is kept.
Polygon3 clip(const Polygon3& poly, const HalfSpace& h) {
  Polygon3 out;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& p = poly[i];
    const Vec3& q = poly[(i + 1) % n];
    const double dp = h.normal.dot(p) - h.offset, dq = h.normal.dot(q) - h.offset;
    if (dp <= 0) out.push_back(p);
    if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) out.push_back(p + (dp / (dp - dq)) * (q - p));
  }
  return out;
}

// The section of the domain box by the plane through `centre` with unit
// normal n, counter-clockwise about n; empty if the plane misses the box.
Polygon3 plane_in_box(const Vec3& n, const Vec3& centre, const Box3& box) {
  if (!(box.volume() > 0)) return {};
  // A square about the box middle's foot on the plane, large enough to
  // cover every point of the box that lies in the plane, cut by the six sides.
  const Vec3 mid = (box.lo + box.hi) / 2;
  const Vec3 foot = mid - n * n.dot(mid - centre);
  const double half = (box.hi - box.lo).norm();
  const auto [e1, e2] = in_plane_axes(n);
  Polygon3 poly = {foot - half * (e1 + e2), foot + half * (e1 - e2), foot + half * (e1 + e2),
                   foot - half * (e1 - e2)};
  for (const HalfSpace& h : box_region(box).half_spaces) poly = clip(poly, h);
  return poly.size() >= 3 ? poly : Polygon3{};
}

Polygon3 outline(const Fracture3& f, const Box3& domain) {
  const double len = f.normal.norm();
  if (!(len > 0) || !std::isfinite(len)) return {};
  const Vec3 n = f.normal / len;
  switch (f.shape) {
    case FractureShape::Plane: return plane_in_box(n, f.centre, domain);
    case FractureShape::Polygon: return f.vertices;
    case FractureShape::Disc: {
      const auto [e1, e2] = in_plane_axes(n);
      Polygon3 poly;
      for (int k = 0; k < kDiscPolygonSides; ++k) {
        const double t = 2 * std::numbers::pi * k / kDiscPolygonSides;
        poly.push_back(f.centre + f.radius * (std::cos(t) * e1 + std::sin(t) * e2));
      }
      return poly;
    }
  }
  return {};
}

}  // namespace

void write_fractures_vtu(const std::string& path, const FractureModel& model) {
  VtuGrid g(model.origin);
  std::vector<std::int32_t> set, kind, shape, layer;
  std::vector<std::int64_t> id;
  for (std::size_t i = 0; i < model.fractures.size(); ++i) {
    const Fracture3& f = model.fractures[i];
    const Polygon3 poly = outline(f, model.domain);
    if (poly.size() < 3) continue;
    for (const Vec3& p : poly) g.add_point(p);
    g.add_cell(poly.size(), kVtkPolygon);
    set.push_back(f.set);
    kind.push_back(static_cast<std::int32_t>(f.kind));
    shape.push_back(static_cast<std::int32_t>(f.shape));
    layer.push_back(f.layer);
    id.push_back(static_cast<std::int64_t>(i));
  }
  // The closed surfaces (the domain's, the excavations'), so that the
  // ground and the openings show with the fractures; each triangle is a
  // cell of the set its faces get in the blocks.
  auto add_surface = [&](const TriangleMesh& s, int tag) {
    for (const auto& t : s.triangles) {
      for (int v : t) g.add_point(s.vertices[static_cast<std::size_t>(v)]);
      g.add_cell(3, kVtkTriangle);
      set.push_back(tag);
      kind.push_back(-1);
      shape.push_back(kSurfaceShape);
      layer.push_back(-1);
      id.push_back(-1);
    }
  };
  if (model.domain_surface) add_surface(*model.domain_surface, kBoundarySet);
  for (const Excavation3& e : model.excavations)
    if (e.surface) add_surface(*e.surface, kExcavationSet);
  g.cell_data("set", 1, std::move(set));
  g.cell_data("kind", 1, std::move(kind));
  g.cell_data("shape", 1, std::move(shape));
  g.cell_data("layer", 1, std::move(layer));
  g.cell_data("fracture_id", 1, std::move(id));
  g.write(path);
}

void write_polyhedra_vtu(const std::string& path, const PolyhedronModel& model) {
  VtuGrid g(model.origin);
  std::vector<std::int64_t> id;
  std::vector<std::int32_t> body, layer, removability;
  std::vector<double> volume;
  std::vector<std::vector<int>> faces;
  for (std::size_t i = 0; i < model.blocks.size(); ++i) {
    const Polyhedron& b = model.blocks[i];
    for (const Vec3& p : b.vertices) g.add_point(p);
    faces.clear();
    for (const PolyFace& f : b.faces) faces.push_back(f.vertices);
    g.add_polyhedron(b.vertices.size(), faces);
    id.push_back(static_cast<std::int64_t>(i));
    body.push_back(b.body);
    volume.push_back(b.volume);
    layer.push_back(b.layer);
    const auto k = static_cast<std::size_t>(b.body);
    const bool has_body = b.body >= 0 && k < model.bodies.size();
    removability.push_back(has_body ? static_cast<std::int32_t>(model.bodies[k].removability) : -1);
  }
  g.cell_data("block_id", 1, std::move(id));
  g.cell_data("body", 1, std::move(body));
  g.cell_data("volume", 1, std::move(volume));
  g.cell_data("layer", 1, std::move(layer));
  g.cell_data("removability", 1, std::move(removability));
  g.write(path);
}

}  // namespace dda
