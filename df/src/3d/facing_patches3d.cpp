// Facing faces of 3D contacts (facing_patches3d.hpp).
#include "3d/facing_patches3d.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

namespace dda::df {
namespace {

using Vec3 = Eigen::Vector3d;

std::vector<Vec3> face_points(const Polyhedron& p, const PolyFace& f) {
  std::vector<Vec3> out;
  for (const int v : f.vertices) out.push_back(p.vertices[static_cast<std::size_t>(v)]);
  return out;
}

// The convex polygon `poly` (in the plane of `face`) clipped to the convex
// face, whose loop runs counter-clockwise seen from its outward normal n:
// the inside of an edge a -> b is where (n x (b - a)) . (p - a) >= 0.
std::vector<Vec3> clip_to_face(std::vector<Vec3> poly, const std::vector<Vec3>& face, const Vec3& n) {
  for (std::size_t e = 0; e < face.size() && !poly.empty(); ++e) {
    const Vec3& a = face[e];
    const Vec3 inward = n.cross(face[(e + 1) % face.size()] - a);
    std::vector<Vec3> kept;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const Vec3& p = poly[k];
      const Vec3& q = poly[(k + 1) % poly.size()];
      const double sp = inward.dot(p - a), sq = inward.dot(q - a);
      if (sp >= 0) kept.push_back(p);
      if ((sp > 0 && sq < 0) || (sp < 0 && sq > 0)) kept.push_back(p + sp / (sp - sq) * (q - p));
    }
    poly = std::move(kept);
  }
  return poly;
}

}  // namespace

std::vector<FacingPatch3> facing_patches3(const std::vector<Polyhedron>& blocks,
                                          const std::vector<df3::Contact3>& contacts, double reach,
                                          const std::function<bool(const df3::Contact3&)>& accept) {
  const double kCosTol = std::cos(10.0 * M_PI / 180.0);
  std::vector<FacingPatch3> patches;
  std::set<std::tuple<int, int, int, int>> seen;  // (block, face, other block, its face), lower block first
  for (std::size_t ci = 0; ci < contacts.size(); ++ci) {
    const df3::Contact3& c = contacts[ci];
    if (c.kind != df3::ContactKind3::VertexFace) continue;
    if (!accept(c)) continue;
    const Polyhedron& bi = blocks[static_cast<std::size_t>(c.i)];
    const Polyhedron& bj = blocks[static_cast<std::size_t>(c.j)];
    const PolyFace& fj = bj.faces[static_cast<std::size_t>(c.ids[1])];
    if (fj.set == kArtificialSet) continue;
    const std::vector<Vec3> face_j = face_points(bj, fj);
    const Vec3 n = (face_j[1] - face_j[0]).cross(face_j[2] - face_j[0]).normalized();  // outward, from the loop
    for (std::size_t k = 0; k < bi.faces.size(); ++k) {
      const PolyFace& fi = bi.faces[k];
      if (fi.set == kArtificialSet) continue;
      if (std::find(fi.vertices.begin(), fi.vertices.end(), c.ids[0]) == fi.vertices.end()) continue;
      std::vector<Vec3> face_i = face_points(bi, fi);
      const Vec3 ni = (face_i[1] - face_i[0]).cross(face_i[2] - face_i[0]).normalized();
      if (ni.dot(n) > -kCosTol) continue;  // not facing
      bool near = true;
      for (const Vec3& p : face_i) near = near && std::abs(n.dot(p - face_j[0])) <= reach;
      if (!near) continue;
      const int fk = static_cast<int>(k);
      const auto key = c.i < c.j ? std::make_tuple(c.i, fk, c.j, c.ids[1]) : std::make_tuple(c.j, c.ids[1], c.i, fk);
      if (!seen.insert(key).second) continue;
      // Face i onto face j's plane, in face j's sense of turning, then clipped by face j.
      for (Vec3& p : face_i) p -= n.dot(p - face_j[0]) * n;
      std::reverse(face_i.begin(), face_i.end());
      std::vector<Vec3> shared = clip_to_face(face_i, face_j, n);
      if (shared.size() < 3) continue;
      patches.push_back({ci, fk, n, std::move(shared)});
    }
  }
  return patches;
}

double polygon_area3(const std::vector<Vec3>& polygon) {
  Vec3 twice{0, 0, 0};
  for (std::size_t k = 0; k < polygon.size(); ++k)
    twice += (polygon[k] - polygon[0]).cross(polygon[(k + 1) % polygon.size()] - polygon[0]);
  return 0.5 * twice.norm();
}

}  // namespace dda::df
