// Convex polygons in 3D: clipping, plane-box sections, area and centroid.
#include "dda/dl/polygon3d.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "dda/dl/dfn3d.hpp"  // plane_basis

namespace dda::dl {

Polygon3 clip_polygon(const Polygon3& poly, const HalfSpace& h, double tol) {
  Polygon3 out;
  const std::size_t n = poly.size();
  if (n == 0) return out;
  std::vector<double> d(n);
  for (std::size_t i = 0; i < n; ++i) d[i] = h.signed_distance(poly[i]);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const bool in_i = d[i] <= tol, in_j = d[j] <= tol;
    if (in_i) out.push_back(poly[i]);
    // A crossing adds a vertex only when the inside end is clearly inside: an
    // end on the plane (within tol) already is the crossing, and adding a
    // second point next to it would leave a near-duplicate vertex.
    if (in_i != in_j && (in_i ? d[i] : d[j]) < -tol)
      out.push_back(poly[i] + (d[i] / (d[i] - d[j])) * (poly[j] - poly[i]));
  }
  return out;
}

Polygon3 clip_polygon(const Polygon3& poly, const ConvexRegion& region, double tol) {
  Polygon3 out = poly;
  for (const HalfSpace& h : region.half_spaces) {
    if (out.empty()) break;
    out = clip_polygon(out, h, tol);
  }
  return out;
}

Polygon3 plane_in_box(const Vec3& normal, double offset, const Box3& box) {
  const double diag = (box.hi - box.lo).norm();
  const Vec3 mid = 0.5 * (box.lo + box.hi);
  // A square in the plane about the box centre's projection, half-side diag:
  // it covers every point of the plane within diag of that projection, hence
  // the whole section; clipping it by the six faces leaves the section.
  const Vec3 c = mid - (normal.dot(mid) - offset) * normal;
  const auto [e1, e2] = plane_basis(normal);
  Polygon3 poly{c + diag * (-e1 - e2), c + diag * (e1 - e2), c + diag * (e1 + e2), c + diag * (-e1 + e2)};
  const double tol = 1e-12 * diag;
  poly = clip_polygon(poly, box_region(box), tol);
  remove_duplicate_vertices(poly, tol);
  if (poly.size() < 3 || polygon_area(poly) <= 1e-12 * diag * diag) return {};
  return poly;
}

Vec3 vector_area(const Polygon3& poly) {
  Vec3 a = Vec3::Zero();
  if (poly.size() < 3) return a;
  // Relative to the first vertex: exact for the same polygon anywhere, and
  // accurate far from the origin.
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) a += (poly[i] - poly[0]).cross(poly[i + 1] - poly[0]);
  return 0.5 * a;
}

double polygon_area(const Polygon3& poly) { return vector_area(poly).norm(); }

Vec3 polygon_centroid(const Polygon3& poly) {
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : poly) mean += p;
  if (poly.empty()) return mean;
  mean /= static_cast<double>(poly.size());
  const Vec3 va = vector_area(poly);
  const double a2 = va.squaredNorm();
  if (poly.size() < 3 || !(a2 > 0)) return mean;
  // Fan of triangles from the first vertex, each weighted by its area
  // projected on the polygon's normal (signed, so a convex or not polygon works).
  Vec3 sum = Vec3::Zero();
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
    const double w = 0.5 * (poly[i] - poly[0]).cross(poly[i + 1] - poly[0]).dot(va);
    sum += w * (poly[0] + poly[i] + poly[i + 1]) / 3.0;
  }
  return sum / a2;
}

void remove_duplicate_vertices(Polygon3& poly, double tol) {
  Polygon3 out;
  for (const Vec3& p : poly)
    if (out.empty() || (p - out.back()).norm() > tol) out.push_back(p);
  while (out.size() > 1 && (out.back() - out.front()).norm() <= tol) out.pop_back();
  poly = std::move(out);
}

double polygon_area_in_box(const Polygon3& poly, const Box3& box) {
  return polygon_area(clip_polygon(poly, box_region(box)));
}

}  // namespace dda::dl
