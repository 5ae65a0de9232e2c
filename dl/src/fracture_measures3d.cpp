// P10 and P21 of planes, discs and convex polygons.
#include "dda/dl/fracture_measures3d.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "dda/common/error.hpp"

namespace dda::dl {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Is x (on the polygon's plane) inside the convex polygon, whose vertices
// turn counter-clockwise about its normal? Points on an edge count as inside,
// like a point on a disc's rim.
bool inside_polygon(const Fracture3& f, const Vec3& x) {
  const std::size_t n = f.vertices.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& p = f.vertices[i];
    const Vec3& q = f.vertices[(i + 1) % n];
    if (f.normal.dot((q - p).cross(x - p)) < 0) return false;
  }
  return n >= 3;
}

// The part [u0, u1] of the line p + u L (L unit, in the fracture's plane)
// that lies on the fracture; false if none.
bool range_on_line(const Fracture3& f, const Vec3& p, const Vec3& L, const Vec3& np, double np_offset, double& u0,
                   double& u1) {
  switch (f.shape) {
    case FractureShape::Plane:
      u0 = -kInf;
      u1 = kInf;
      return true;
    case FractureShape::Disc: {
      const Vec3 w = f.centre - p;
      const double uc = w.dot(L);
      const double h2 = f.radius * f.radius - (w.squaredNorm() - uc * uc);
      if (!(h2 > 0)) return false;
      u0 = uc - std::sqrt(h2);
      u1 = uc + std::sqrt(h2);
      return true;
    }
    case FractureShape::Polygon: {
      // A convex polygon meets the plane in one segment, between the least
      // and the greatest of its edges' crossings.
      u0 = kInf;
      u1 = -kInf;
      const std::size_t n = f.vertices.size();
      for (std::size_t i = 0; i < n; ++i) {
        const Vec3& a = f.vertices[i];
        const Vec3& b = f.vertices[(i + 1) % n];
        const double da = np.dot(a) - np_offset, db = np.dot(b) - np_offset;
        auto add = [&](const Vec3& x) {
          const double u = (x - p).dot(L);
          u0 = std::min(u0, u);
          u1 = std::max(u1, u);
        };
        if (da == 0) add(a);
        if ((da < 0 && db > 0) || (da > 0 && db < 0)) add(a + (da / (da - db)) * (b - a));
      }
      return u0 < u1;
    }
  }
  return false;
}

void check_rectangle(const Rectangle3& rect) {
  const double l1 = rect.e1.norm(), l2 = rect.e2.norm();
  if (!(l1 > 0) || !(l2 > 0) || !std::isfinite(l1 * l2))
    throw InputError("A P21 sampling rectangle must have two finite non-zero sides.");
  if (std::abs(rect.e1.dot(rect.e2)) > 1e-9 * l1 * l2)
    throw InputError("A P21 sampling rectangle must have orthogonal sides.");
}

}  // namespace

bool segment_meets(const Fracture3& f, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double nd = f.normal.dot(d);
  if (nd == 0) return false;
  const double t = (f.offset() - f.normal.dot(a)) / nd;
  if (t < 0 || t > 1) return false;
  const Vec3 x = a + t * d;
  switch (f.shape) {
    case FractureShape::Plane:
      return true;
    case FractureShape::Disc:
      return (x - f.centre).squaredNorm() <= f.radius * f.radius;
    case FractureShape::Polygon:
      return inside_polygon(f, x);
  }
  return false;
}

double p10_along(const std::vector<Fracture3>& fractures, const Vec3& a, const Vec3& b) {
  const double length = (b - a).norm();
  if (!(length > 0) || !std::isfinite(length)) throw InputError("A P10 scan line must have two distinct finite ends.");
  std::size_t met = 0;
  for (const Fracture3& f : fractures) met += segment_meets(f, a, b) ? 1 : 0;
  return static_cast<double>(met) / length;
}

double trace_length_on(const Fracture3& f, const Rectangle3& rect) {
  const double l1 = rect.e1.norm(), l2 = rect.e2.norm();
  const Vec3 np = rect.e1.cross(rect.e2) / (l1 * l2);
  Vec3 L = f.normal.cross(np);
  const double sine = L.norm();
  if (sine < 1e-12) return 0;  // parallel planes: no trace
  L /= sine;
  // A point of both planes n . x = d1 and np . x = d2 (unit normals, c = n . np).
  const double d1 = f.offset(), d2 = np.dot(rect.origin), c = f.normal.dot(np);
  const Vec3 p = ((d1 - d2 * c) * f.normal + (d2 - d1 * c) * np) / (sine * sine);
  double u0 = 0, u1 = 0;
  if (!range_on_line(f, p, L, np, d2, u0, u1)) return 0;
  // Clip to the rectangle's (s1, s2) in [0, 1]^2 (Liang-Barsky).
  const Vec3 rel = p - rect.origin;
  for (const Vec3* e : {&rect.e1, &rect.e2}) {
    const double e2 = e->squaredNorm();
    const double s = rel.dot(*e) / e2, q = L.dot(*e) / e2;  // coordinate s + u q
    if (q == 0) {
      if (s < 0 || s > 1) return 0;
      continue;
    }
    const double ua = -s / q, ub = (1 - s) / q;
    u0 = std::max(u0, std::min(ua, ub));
    u1 = std::min(u1, std::max(ua, ub));
  }
  return u1 > u0 ? u1 - u0 : 0;
}

double p21_on(const std::vector<Fracture3>& fractures, const Rectangle3& rect) {
  check_rectangle(rect);
  double length = 0;
  for (const Fracture3& f : fractures) length += trace_length_on(f, rect);
  return length / (rect.e1.norm() * rect.e2.norm());
}

}  // namespace dda::dl
