#include "fracture_extent.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

namespace dda::dc {

namespace {

// Distance from p to the convex polygon (0 inside).
double distance_to_convex(const Polygon2& poly, const Vec2& p) {
  bool inside = true;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[(i + 1) % poly.size()];
    if (cross(b - a, p - a) < 0) inside = false;
    const Vec2 ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
    best = std::min(best, (a + t * ab - p).norm());
  }
  return inside ? 0.0 : best;
}

}  // namespace

FractureExtent::FractureExtent(const Fracture3& f) {
  const Vec3 n = f.normal.normalized();
  const Vec3 any = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  e1_ = n.cross(any).normalized();
  e2_ = n.cross(e1_);
  origin_ = f.centre;
  const double inf = std::numeric_limits<double>::infinity();
  bounds_ = {Vec3::Constant(-inf), Vec3::Constant(inf)};
  if (f.shape == FractureShape::Plane) return;
  bounded_ = true;
  if (f.shape == FractureShape::Disc) {
    disc_ = true;
    radius_ = f.radius;
    tol_ = 1e-9 * radius_;
    Vec3 reach;
    for (int i = 0; i < 3; ++i) reach[i] = radius_ * std::sqrt(std::max(0.0, 1.0 - n[i] * n[i]));
    bounds_ = {f.centre - reach, f.centre + reach};
    return;
  }
  bounds_ = {Vec3::Constant(inf), Vec3::Constant(-inf)};
  for (const Vec3& v : f.vertices) {
    polygon_.push_back(in_plane(v));
    bounds_.lo = bounds_.lo.cwiseMin(v);
    bounds_.hi = bounds_.hi.cwiseMax(v);
  }
  make_counter_clockwise(polygon_);
  tol_ = 1e-9 * (bounds_.hi - bounds_.lo).norm();
}

bool FractureExtent::covers(const Polygon2& poly) const {
  if (!bounded_) return true;
  for (const Vec2& p : poly) {
    if (disc_ ? p.norm() > radius_ + tol_ : distance_to_convex(polygon_, p) > tol_) return false;
  }
  return true;
}

Coverage FractureExtent::coverage(const std::vector<Vec3>& section) const {
  if (!bounded_) return Coverage::Full;
  Polygon2 pts;
  pts.reserve(section.size());
  for (const Vec3& p : section) pts.push_back(in_plane(p));
  bool all_in = true;
  if (disc_) {
    for (const Vec2& p : pts) all_in = all_in && p.norm() <= radius_ + tol_;
    if (all_in) return Coverage::Full;
    return distance_to_convex(convex_hull(pts), Vec2(0, 0)) < radius_ - tol_ ? Coverage::Partial : Coverage::None;
  }
  for (const Vec2& p : pts) all_in = all_in && distance_to_convex(polygon_, p) <= tol_;
  if (all_in) return Coverage::Full;
  return convex_polygons_overlap(polygon_, convex_hull(pts), tol_) ? Coverage::Partial : Coverage::None;
}

}  // namespace dda::dc
