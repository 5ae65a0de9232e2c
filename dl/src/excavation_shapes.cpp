#include "dda/dl/excavation.hpp"

#include <algorithm>
#include <cmath>

namespace dda::dl {

Polygon2 rectangle_outline(const Vec2& c, double w, double h) {
  return {c + Vec2(-w / 2, -h / 2), c + Vec2(w / 2, -h / 2), c + Vec2(w / 2, h / 2), c + Vec2(-w / 2, h / 2)};
}

Polygon2 circle_outline(const Vec2& c, double r, int n) {
  Polygon2 poly;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * kPi * k / n;
    poly.push_back(c + r * Vec2(std::cos(a), std::sin(a)));
  }
  return poly;
}

int horseshoe_arc_pieces(double r, double d, int segments) {
  const double arc = kPi + 2 * std::asin(d / r);
  return std::max(2, static_cast<int>(std::ceil(segments * arc / (2 * kPi) - 1e-9)));
}

Polygon2 horseshoe_outline(const Vec2& c, double r, double d, int segments) {
  // From the right end of the invert, counter-clockwise over the crown to the
  // left end; the closing edge is the invert.
  const double start = -std::asin(d / r);
  const double arc = kPi + 2 * std::asin(d / r);
  const int pieces = horseshoe_arc_pieces(r, d, segments);
  Polygon2 poly;
  for (int k = 0; k <= pieces; ++k) {
    const double a = start + arc * k / pieces;
    poly.push_back(c + r * Vec2(std::cos(a), std::sin(a)));
  }
  // Put the invert ends exactly at depth d.
  poly.front().y() = c.y() - d;
  poly.back().y() = c.y() - d;
  return poly;
}

Polygon2 arch_outline(const Vec2& c, double w, double wall, double rise, int segments) {
  const double half = w / 2;
  const double rho = (half * half + rise * rise) / (2 * rise);   // roof radius
  const Vec2 rc = c + Vec2(0, wall + rise - rho);                 // roof centre
  const double psi = std::asin(std::min(1.0, half / rho));        // half-angle of the roof arc
  Polygon2 poly{c + Vec2(-half, 0), c + Vec2(half, 0)};
  for (int k = 0; k <= segments; ++k) {
    const double a = kPi / 2 - psi + 2 * psi * k / segments;
    poly.push_back(rc + rho * Vec2(std::cos(a), std::sin(a)));
  }
  // Wall tops exactly at wall height (removes rounding); a zero wall height
  // leaves floor and roof ends coincident, so drop the duplicates.
  poly[2] = c + Vec2(half, wall);
  poly.back() = c + Vec2(-half, wall);
  if (wall == 0) {
    poly.erase(poly.begin() + 2);
    poly.pop_back();
  }
  return poly;
}

}  // namespace dda::dl
