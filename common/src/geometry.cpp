#include "dda/common/geometry.hpp"

#include <algorithm>
#include <limits>

namespace dda {

double signed_area(const Polygon2& poly) {
  // About the first vertex, not the origin: a 10 m square at x, y = 1e12
  // has cross products of 1e24 about the origin, whose rounding (1e8) buries
  // its 100 m^2; about its own corner they are exact.
  double twice = 0;
  const std::size_t n = poly.size();
  if (n < 3) return 0;
  const Vec2 o = poly[0];
  for (std::size_t i = 1; i + 1 < n; ++i) twice += cross(poly[i] - o, poly[i + 1] - o);
  return 0.5 * twice;
}

PolygonMoments polygon_moments(const Polygon2& poly) {
  // Integrate over triangles (o, p_i, p_{i+1}) with o = first vertex, which
  // keeps the numbers small for polygons far from the origin. For a triangle
  // with vertices 0, a, b (relative to o): A = cross(a,b)/2,
  // int x dA = A (a_x + b_x)/3,
  // int x^2 dA = A (a_x^2 + a_x b_x + b_x^2)/6, int xy dA likewise.
  PolygonMoments m;
  const std::size_t n = poly.size();
  if (n < 3) return m;
  const Vec2 o = poly[0];
  double A = 0, Sx = 0, Sy = 0, Sxx = 0, Syy = 0, Sxy = 0;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const Vec2 a = poly[i] - o, b = poly[i + 1] - o;
    const double t = 0.5 * cross(a, b);
    A += t;
    Sx += t * (a.x() + b.x()) / 3.0;
    Sy += t * (a.y() + b.y()) / 3.0;
    Sxx += t * (a.x() * a.x() + a.x() * b.x() + b.x() * b.x()) / 6.0;
    Syy += t * (a.y() * a.y() + a.y() * b.y() + b.y() * b.y()) / 6.0;
    Sxy += t * (2 * a.x() * a.y() + a.x() * b.y() + b.x() * a.y() + 2 * b.x() * b.y()) / 12.0;
  }
  m.area = A;
  if (A == 0) return m;
  const double cx = Sx / A, cy = Sy / A;
  m.centroid = o + Vec2(cx, cy);
  m.sxx = Sxx - A * cx * cx;
  m.syy = Syy - A * cy * cy;
  m.sxy = Sxy - A * cx * cy;
  return m;
}

Box2 bounding_box(const Polygon2& poly) {
  Box2 b;
  if (poly.empty()) return b;
  b.lo = b.hi = poly[0];
  for (const Vec2& p : poly) {
    b.lo = b.lo.cwiseMin(p);
    b.hi = b.hi.cwiseMax(p);
  }
  return b;
}

bool point_in_polygon(const Polygon2& poly, const Vec2& p) {
  bool inside = false;
  const std::size_t n = poly.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) inside = !inside;
    }
  }
  return inside;
}

double distance_to_boundary(const Polygon2& poly, const Vec2& p) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = poly.size(); i < n; ++i) {
    const Vec2& a = poly[i];
    const Vec2 ab = poly[(i + 1) % n] - a;
    const double l2 = ab.squaredNorm();
    const double t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
    best = std::min(best, (a + t * ab - p).norm());
  }
  return best;
}

void make_counter_clockwise(Polygon2& poly) {
  if (signed_area(poly) < 0) std::reverse(poly.begin(), poly.end());
}

double extent_along(const Polygon2& poly, const Vec2& dir) {
  const Vec2 u = dir.normalized();
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Vec2& p : poly) {
    const double s = p.dot(u);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  return poly.empty() ? 0.0 : hi - lo;
}

Polygon2 convex_hull(Polygon2 pts) {
  // Andrew's monotone chain.
  std::sort(pts.begin(), pts.end(),
            [](const Vec2& a, const Vec2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return pts;
  Polygon2 hull(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(hull[k - 1] - hull[k - 2], pts[i] - hull[k - 2]) <= 0) --k;
    hull[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(hull[k - 1] - hull[k - 2], pts[i - 1] - hull[k - 2]) <= 0) --k;
    hull[k++] = pts[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

FeretMeasures feret_measures(const Polygon2& poly) {
  // The minimum width is attained perpendicular to a convex-hull edge, so
  // scanning the hull edges is exact: O(h^2) on the hull.
  FeretMeasures f;
  const Polygon2 hull = convex_hull(poly);
  const std::size_t h = hull.size();
  for (std::size_t i = 0; i < h; ++i)
    for (std::size_t j = i + 1; j < h; ++j) f.max_diameter = std::max(f.max_diameter, (hull[i] - hull[j]).norm());
  if (h < 3) {
    f.aspect = std::numeric_limits<double>::infinity();
    return f;
  }
  f.min_width = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < h; ++i) {
    const Vec2 e = hull[(i + 1) % h] - hull[i];
    const double w = extent_along(hull, Vec2(-e.y(), e.x()));
    const double len = extent_along(hull, e);
    // On ties (a square, a regular polygon) keep the longer perpendicular
    // length, so the result does not depend on where the hull starts.
    const double tol = 1e-12 * std::max(1.0, w);
    if (w < f.min_width - tol || (w <= f.min_width + tol && len > f.length)) {
      f.min_width = std::min(w, f.min_width);
      f.length = len;
    }
  }
  f.aspect = f.min_width > 0 ? f.length / f.min_width : std::numeric_limits<double>::infinity();
  return f;
}

double min_feret_width(const Polygon2& poly) { return feret_measures(poly).min_width; }

bool convex_polygons_overlap(const Polygon2& a, const Polygon2& b, double tol) {
  // Separated if all of one polygon lies beyond (or within tol of) an edge
  // line of the other.
  auto separated_by_edges_of = [tol](const Polygon2& p, const Polygon2& q) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec2 e = p[(i + 1) % p.size()] - p[i];
      const Vec2 n(e.y(), -e.x());  // outward for a counter-clockwise p
      const double len = n.norm();
      if (len == 0) continue;
      double nearest = std::numeric_limits<double>::infinity();
      for (const Vec2& v : q) nearest = std::min(nearest, (v - p[i]).dot(n) / len);
      if (nearest >= -tol) return true;
    }
    return false;
  };
  return !separated_by_edges_of(a, b) && !separated_by_edges_of(b, a);
}

Polygon2 clip_to_convex(const Polygon2& subject, const Polygon2& clip) {
  Polygon2 out = subject;
  for (std::size_t i = 0; i < clip.size() && !out.empty(); ++i) {
    const Vec2 a = clip[i], b = clip[(i + 1) % clip.size()];
    const Vec2 e = b - a;
    auto inside = [&](const Vec2& p) { return cross(e, p - a) >= 0; };
    Polygon2 in = std::move(out);
    out.clear();
    for (std::size_t k = 0; k < in.size(); ++k) {
      const Vec2& p = in[k];
      const Vec2& q = in[(k + 1) % in.size()];
      const bool pin = inside(p), qin = inside(q);
      if (pin) out.push_back(p);
      if (pin != qin) {
        const double cp = cross(e, p - a), cq = cross(e, q - a);
        out.push_back(p + (cp / (cp - cq)) * (q - p));
      }
    }
  }
  return out;
}

}  // namespace dda
