// Shape measures of a block and the simple-polygon check on doubles.
//
// Sliver aspect ratio: dda::feret_measures (common/geometry.hpp), the same
// elongation the block statistics report: an L x W rectangle has L/W.
#include <algorithm>
#include <cmath>
#include <limits>

#include "cut_internal.hpp"

namespace dda::dc::detail {
namespace {

double orient(const Vec2& a, const Vec2& b, const Vec2& c) { return cross(b - a, c - a); }

bool on_segment(const Vec2& a, const Vec2& b, const Vec2& p) {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
         std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
}

bool segments_meet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double o1 = orient(a, b, c), o2 = orient(a, b, d);
  const double o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
    return true;
  if (o1 == 0 && on_segment(a, b, c)) return true;
  if (o2 == 0 && on_segment(a, b, d)) return true;
  if (o3 == 0 && on_segment(c, d, a)) return true;
  if (o4 == 0 && on_segment(c, d, b)) return true;
  return false;
}

}  // namespace

ShapeMeasures shape_measures(const Polygon2& poly) {
  const FeretMeasures f = feret_measures(poly);
  return {f.max_diameter, f.min_width, f.aspect};
}

bool is_sliver(double area, double aspect, const SliverFilter& f) {
  return (f.min_area > 0 && area < f.min_area) || (f.max_aspect > 0 && aspect > f.max_aspect);
}

bool is_simple_polygon(const Polygon2& poly) {
  const std::size_t n = poly.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = poly[(i + n - 1) % n];
    const Vec2& b = poly[i];
    const Vec2& c = poly[(i + 1) % n];
    if (b == c) return false;  // zero-length edge
    // a spike: the polygon folds back on itself at b
    if (orient(a, b, c) == 0 && (b - a).dot(c - b) < 0) return false;
  }
  if (n == 3) return true;
  // Non-adjacent edges must not meet. Sweep over x to skip far pairs.
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  auto xlo = [&](std::size_t i) { return std::min(poly[i].x(), poly[(i + 1) % n].x()); };
  auto xhi = [&](std::size_t i) { return std::max(poly[i].x(), poly[(i + 1) % n].x()); };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return xlo(a) < xlo(b); });
  std::vector<std::size_t> active;
  for (std::size_t i : order) {
    const double x0 = xlo(i);
    active.erase(std::remove_if(active.begin(), active.end(), [&](std::size_t j) { return xhi(j) < x0; }),
                 active.end());
    for (std::size_t j : active) {
      const bool adjacent = (i + 1) % n == j || (j + 1) % n == i;
      if (adjacent) continue;
      if (segments_meet(poly[i], poly[(i + 1) % n], poly[j], poly[(j + 1) % n])) return false;
    }
    active.push_back(i);
  }
  return true;
}

}  // namespace dda::dc::detail
