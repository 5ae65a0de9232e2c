#include "dda/common/geometry3d.hpp"

namespace dda {

ConvexRegion box_region(const Box3& box) {
  ConvexRegion r;
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 n = Vec3::Zero();
    n[axis] = -1;
    r.half_spaces.push_back({n, -box.lo[axis]});
    n[axis] = 1;
    r.half_spaces.push_back({n, box.hi[axis]});
  }
  return r;
}

PolyhedronMoments polyhedron_moments(const std::vector<Vec3>& vertices, const std::vector<std::vector<int>>& faces) {
  PolyhedronMoments m;
  if (vertices.empty()) return m;
  // Coordinates relative to a vertex keep the sums well conditioned far
  // from the origin.
  const Vec3 ref = vertices.front();
  Vec3 first{0, 0, 0};
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (const auto& loop : faces) {
    if (loop.size() < 3) continue;
    const Vec3 a = vertices[static_cast<std::size_t>(loop[0])] - ref;
    for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
      const Vec3 b = vertices[static_cast<std::size_t>(loop[i])] - ref;
      const Vec3 c = vertices[static_cast<std::size_t>(loop[i + 1])] - ref;
      // Tetrahedron (0, a, b, c): volume a.(b x c)/6, first moment V s/4,
      // second moment V/20 (sum v v^T + s s^T) with s = a + b + c.
      const double v = a.dot(b.cross(c)) / 6.0;
      const Vec3 s = a + b + c;
      m.volume += v;
      first += v * s / 4.0;
      second += v / 20.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
    }
  }
  if (m.volume == 0) return m;
  const Vec3 g = first / m.volume;  // centroid relative to ref
  m.centroid = ref + g;
  m.second_moment = second - m.volume * g * g.transpose();
  return m;
}

}  // namespace dda
