// P10, P21 and P32 of a disc network, exactly.
#include <algorithm>
#include <cmath>
#include <vector>

#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"
#include "dda/dl/dfn3d_measures.hpp"

namespace dda::dl {

namespace {

// Keeps the part of the convex polygon with a s + b t <= h (Sutherland-Hodgman
// for one half-plane; the orientation of the polygon is kept).
Polygon2 clip_half_plane(const Polygon2& poly, double a, double b, double h) {
  Polygon2 out;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& p = poly[i];
    const Vec2& q = poly[(i + 1) % n];
    const double fp = a * p.x() + b * p.y() - h, fq = a * q.x() + b * q.y() - h;
    if (fp <= 0) out.push_back(p);
    if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) out.push_back(p + (fp / (fp - fq)) * (q - p));
  }
  return out;
}

// Signed area of the circle of radius r about the origin intersected with the
// triangle (origin, p, q): along the edge p -> q, the pieces inside the circle
// add their triangle (half the cross product), those outside their sector
// (half r^2 times the signed angle).
double circle_triangle_area(const Vec2& p, const Vec2& q, double r) {
  const Vec2 d = q - p;
  const double a = d.squaredNorm();
  if (a == 0) return 0;
  auto triangle = [](const Vec2& u, const Vec2& v) { return 0.5 * cross(u, v); };
  auto sector = [r](const Vec2& u, const Vec2& v) { return 0.5 * r * r * std::atan2(cross(u, v), u.dot(v)); };
  const double b = p.dot(d), c = p.squaredNorm() - r * r;
  const double disc = b * b - a * c;  // roots of |p + t d|^2 = r^2: t = (-b -+ sqrt(disc)) / a
  if (disc <= 0) return sector(p, q);
  const double root = std::sqrt(disc);
  const double t1 = std::clamp((-b - root) / a, 0.0, 1.0), t2 = std::clamp((-b + root) / a, 0.0, 1.0);
  const Vec2 m1 = p + t1 * d, m2 = p + t2 * d;
  return sector(p, m1) + triangle(m1, m2) + sector(m2, q);
}

}  // namespace

double disc_area_in_box(const Disc& disc, const Box3& box) {
  const double r = disc.radius;
  const Eigen::Vector3d& c = disc.centre;
  const Eigen::Vector3d& n = disc.normal;
  // The disc's extent along axis k is r sqrt(1 - n_k^2) either side of c_k.
  bool inside = true;
  for (int k = 0; k < 3; ++k) {
    const double e = r * std::sqrt(std::max(0.0, 1 - n[k] * n[k]));
    if (c[k] + e <= box.lo[k] || c[k] - e >= box.hi[k]) return 0;
    inside = inside && c[k] - e >= box.lo[k] && c[k] + e <= box.hi[k];
  }
  if (inside) return kPi * r * r;
  // In the disc's frame (s, t): the box is six half-planes; start from the
  // square circumscribing the disc (counter-clockwise).
  const auto [e1, e2] = plane_basis(n);
  Polygon2 poly{Vec2(-r, -r), Vec2(r, -r), Vec2(r, r), Vec2(-r, r)};
  for (int k = 0; k < 3 && !poly.empty(); ++k) {
    poly = clip_half_plane(poly, e1[k], e2[k], box.hi[k] - c[k]);     // c_k + s e1_k + t e2_k <= hi_k
    poly = clip_half_plane(poly, -e1[k], -e2[k], c[k] - box.lo[k]);   // ... >= lo_k
  }
  double area = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) area += circle_triangle_area(poly[i], poly[(i + 1) % poly.size()], r);
  return std::abs(area);
}

double p32_in_box(const std::vector<Disc>& discs, const Box3& box) {
  validate_box(box, "The P32 sampling box");
  double area = 0;
  for (const Disc& d : discs) area += disc_area_in_box(d, box);
  return area / box.volume();
}

double p10_along(const std::vector<Disc>& discs, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d d = b - a;
  const double length = d.norm();
  if (!(length > 0) || !std::isfinite(length))
    throw InputError("A P10 scan line must have two distinct finite ends.");
  std::size_t crossed = 0;
  for (const Disc& disc : discs) {
    const double nd = disc.normal.dot(d);
    if (nd == 0) continue;  // parallel to the disc's plane
    const double t = disc.normal.dot(disc.centre - a) / nd;
    if (t < 0 || t > 1) continue;
    if ((a + t * d - disc.centre).squaredNorm() <= disc.radius * disc.radius) ++crossed;
  }
  return static_cast<double>(crossed) / length;
}

double p21_on(const std::vector<Disc>& discs, const Rectangle3& rect) {
  const double l1 = rect.e1.norm(), l2 = rect.e2.norm();
  if (!(l1 > 0) || !(l2 > 0) || !std::isfinite(l1 * l2))
    throw InputError("A P21 sampling rectangle must have two finite non-zero sides.");
  if (std::abs(rect.e1.dot(rect.e2)) > 1e-9 * l1 * l2)
    throw InputError("A P21 sampling rectangle must have orthogonal sides.");
  const Eigen::Vector3d np = rect.e1.cross(rect.e2) / (l1 * l2);
  double length = 0;
  for (const Disc& disc : discs) {
    Eigen::Vector3d line = disc.normal.cross(np);  // direction of the planes' intersection
    const double sin_angle = line.norm();
    if (sin_angle < 1e-12) continue;  // parallel planes: no trace
    line /= sin_angle;
    // In the disc's plane, w is perpendicular to the line; the line is where
    // np . (c + s w - origin) = 0, s being the centre's distance to it.
    const Eigen::Vector3d w = disc.normal.cross(line);
    const double s = -np.dot(disc.centre - rect.origin) / np.dot(w);
    if (std::abs(s) >= disc.radius) continue;
    const double h = std::sqrt(disc.radius * disc.radius - s * s);
    const Eigen::Vector3d mid = disc.centre + s * w;
    // Clip mid + u line, u in [-h, h], to the rectangle's (s1, s2) in [0, 1]^2
    // (Liang-Barsky).
    double u0 = -h, u1 = h;
    const Eigen::Vector3d rel = mid - rect.origin;
    for (const Eigen::Vector3d* e : {&rect.e1, &rect.e2}) {
      const double e2 = e->squaredNorm();
      const double p = rel.dot(*e) / e2, q = line.dot(*e) / e2;  // coordinate p + u q
      if (q == 0) {
        if (p < 0 || p > 1) u1 = u0 - 1;  // outside the strip: no trace
        continue;
      }
      const double ua = (0 - p) / q, ub = (1 - p) / q;
      u0 = std::max(u0, std::min(ua, ub));
      u1 = std::min(u1, std::max(ua, ub));
    }
    if (u1 > u0) length += u1 - u0;
  }
  return length / (l1 * l2);
}

}  // namespace dda::dl
