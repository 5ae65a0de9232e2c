#include "dda/dl/clip.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dda::dl {

namespace {

// Parameter t along p + t r where it meets segment q + u s (0 <= u <= 1), if it does.
bool intersect(const Vec2& p, const Vec2& r, const Vec2& q, const Vec2& s, double& t) {
  const double denom = cross(r, s);
  if (denom == 0) return false;  // parallel (collinear overlaps are handled by the midpoint test)
  const Vec2 qp = q - p;
  const double u = cross(qp, r) / denom;
  if (u < 0 || u > 1) return false;
  t = cross(qp, s) / denom;
  return true;
}

int orientation(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double v = cross(b - a, c - a);
  return (v > 0) - (v < 0);
}

bool on_segment(const Vec2& a, const Vec2& b, const Vec2& p) {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= p.y() &&
         p.y() <= std::max(a.y(), b.y());
}

bool segments_touch(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const int o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  if (o1 != o2 && o3 != o4) return true;
  if (o1 == 0 && on_segment(a, b, c)) return true;
  if (o2 == 0 && on_segment(a, b, d)) return true;
  if (o3 == 0 && on_segment(c, d, a)) return true;
  if (o4 == 0 && on_segment(c, d, b)) return true;
  return false;
}

// Proper crossing: the segments cross at a point interior to both.
bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const int o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  return o1 * o2 < 0 && o3 * o4 < 0;
}

}  // namespace

std::vector<Segment> clip_segment(const Polygon2& poly, const Segment& s, double min_length) {
  std::vector<Segment> out;
  const Vec2 r = s.b - s.a;
  const double len = r.norm();
  if (len == 0 || poly.size() < 3) return out;
  std::vector<double> ts{0.0, 1.0};
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2& q = poly[i];
    const Vec2 e = poly[(i + 1) % poly.size()] - q;
    double t = 0;
    if (intersect(s.a, r, q, e, t) && t > 0 && t < 1) ts.push_back(t);
  }
  std::sort(ts.begin(), ts.end());
  // Boundary scale for the "on the boundary counts as inside" test.
  const Box2 box = bounding_box(poly);
  const double eps = 1e-12 * std::max({1.0, box.width(), box.height()});
  double open_t = -1;  // start of the part being built, -1 if none
  for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
    const double t0 = ts[k], t1 = ts[k + 1];
    if (t1 - t0 <= 0) continue;
    const Vec2 mid = s.a + 0.5 * (t0 + t1) * r;
    const bool inside = point_in_polygon(poly, mid) || distance_to_boundary(poly, mid) <= eps;
    if (inside && open_t < 0) open_t = t0;
    if (!inside && open_t >= 0) {
      if ((t0 - open_t) * len >= min_length) out.push_back({s.a + open_t * r, s.a + t0 * r});
      open_t = -1;
    }
  }
  if (open_t >= 0 && (1.0 - open_t) * len >= min_length) out.push_back({s.a + open_t * r, s.b});
  return out;
}

bool is_simple_polygon(const Polygon2& poly) {
  const std::size_t n = poly.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    if (poly[i] == poly[(i + 1) % n]) return false;  // repeated vertex
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      const Vec2 &a = poly[i], &b = poly[(i + 1) % n], &c = poly[j], &d = poly[(j + 1) % n];
      if (adjacent) {
        // Adjacent edges share one vertex; they must not fold back onto each other.
        const Vec2& shared = (j == i + 1) ? b : a;
        const Vec2& other_i = (j == i + 1) ? a : b;
        const Vec2& other_j = (j == i + 1) ? d : c;
        if (orientation(other_i, shared, other_j) == 0 && (other_i - shared).dot(other_j - shared) > 0) return false;
        continue;
      }
      if (segments_touch(a, b, c, d)) return false;
    }
  }
  return true;
}

bool polygon_inside(const Polygon2& outer, const Polygon2& inner) {
  const Box2 box = bounding_box(outer);
  const double eps = 1e-9 * std::max({1.0, box.width(), box.height()});
  for (const Vec2& p : inner)
    if (!point_in_polygon(outer, p) && distance_to_boundary(outer, p) > eps) return false;
  for (std::size_t i = 0; i < inner.size(); ++i)
    for (std::size_t j = 0; j < outer.size(); ++j)
      if (segments_cross(inner[i], inner[(i + 1) % inner.size()], outer[j], outer[(j + 1) % outer.size()]))
        return false;
  return true;
}

}  // namespace dda::dl
