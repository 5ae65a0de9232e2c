// Polygon integrals against closed forms.
#include <gtest/gtest.h>

#include "dda/common/geometry.hpp"

using dda::Polygon2;
using dda::Vec2;

TEST(PolygonMoments, RectangleMatchesClosedForm) {
  // w x h rectangle: A = w h, centroid at its centre, Sxx = h w^3 / 12,
  // Syy = w h^3 / 12, Sxy = 0 (textbook second moments about the centroid).
  const double w = 3.0, h = 2.0;
  const Polygon2 r{{10, 20}, {10 + w, 20}, {10 + w, 20 + h}, {10, 20 + h}};
  const auto m = dda::polygon_moments(r);
  EXPECT_NEAR(m.area, w * h, 1e-12);
  EXPECT_NEAR(m.centroid.x(), 10 + w / 2, 1e-12);
  EXPECT_NEAR(m.centroid.y(), 20 + h / 2, 1e-12);
  EXPECT_NEAR(m.sxx, h * w * w * w / 12, 1e-10);
  EXPECT_NEAR(m.syy, w * h * h * h / 12, 1e-10);
  EXPECT_NEAR(m.sxy, 0, 1e-10);
}

TEST(PolygonMoments, RightTriangleProductMoment) {
  // Right triangle with legs a (x) and b (y) at the origin: A = ab/2,
  // centroid (a/3, b/3), Ixy about the centroid = -a^2 b^2 / 72.
  const double a = 4, b = 3;
  const Polygon2 t{{0, 0}, {a, 0}, {0, b}};
  const auto m = dda::polygon_moments(t);
  EXPECT_NEAR(m.area, a * b / 2, 1e-12);
  EXPECT_NEAR(m.centroid.x(), a / 3, 1e-12);
  EXPECT_NEAR(m.centroid.y(), b / 3, 1e-12);
  EXPECT_NEAR(m.sxy, -a * a * b * b / 72, 1e-12);
  EXPECT_NEAR(m.sxx, b * a * a * a / 36, 1e-12);  // integral of (x-x0)^2: b a^3 / 36
}

TEST(PolygonMoments, NonConvexLShapeIsSumOfParts) {
  // L-shape = 2x1 bar + 1x1 square on top of its left end.
  const Polygon2 l{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  const auto m = dda::polygon_moments(l);
  EXPECT_NEAR(m.area, 3.0, 1e-12);
  // centroid = (2*(1,0.5) + 1*(0.5,1.5)) / 3
  EXPECT_NEAR(m.centroid.x(), 2.5 / 3, 1e-12);
  EXPECT_NEAR(m.centroid.y(), 2.5 / 3, 1e-12);
}

TEST(PolygonMoments, ClockwiseGivesNegativeArea) {
  Polygon2 sq{{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  EXPECT_NEAR(dda::signed_area(sq), -1.0, 1e-15);
  dda::make_counter_clockwise(sq);
  EXPECT_NEAR(dda::signed_area(sq), 1.0, 1e-15);
}

TEST(PointInPolygon, InsideOutsideOfNonConvex) {
  const Polygon2 l{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  EXPECT_TRUE(dda::point_in_polygon(l, {0.5, 1.5}));
  EXPECT_TRUE(dda::point_in_polygon(l, {1.5, 0.5}));
  EXPECT_FALSE(dda::point_in_polygon(l, {1.5, 1.5}));
  EXPECT_FALSE(dda::point_in_polygon(l, {-0.1, 0.5}));
}

TEST(Widths, ExtentAndMinimumFeret) {
  // 4 x 1 rectangle rotated by 30 degrees: min Feret width 1, extent along
  // its long axis 4.
  const double c = std::cos(dda::deg2rad(30)), s = std::sin(dda::deg2rad(30));
  Polygon2 r;
  for (Vec2 p : {Vec2(0, 0), Vec2(4, 0), Vec2(4, 1), Vec2(0, 1)}) r.emplace_back(c * p.x() - s * p.y(), s * p.x() + c * p.y());
  EXPECT_NEAR(dda::min_feret_width(r), 1.0, 1e-12);
  EXPECT_NEAR(dda::extent_along(r, Vec2(c, s)), 4.0, 1e-12);
  EXPECT_NEAR(dda::extent_along(r, Vec2(1, 0)), 4 * c + 1 * s, 1e-12);
}
