// Excavation outlines: areas against hand formulas, orientation, placement.
#include <gtest/gtest.h>

#include <cmath>

#include "dda/dl/excavation.hpp"
#include "dl_test_util.hpp"

namespace dda::dl {

TEST(DlExcavation, RectangleArea) {
  const auto p = rectangle_outline(Vec2(3, 4), 8, 6);
  EXPECT_DOUBLE_EQ(signed_area(p), 48.0);  // w h, counter-clockwise
  EXPECT_EQ(bounding_box(p).lo, Vec2(-1, 1));
}

TEST(DlExcavation, CircleAreaIsTheInscribedPolygon) {
  // n / 2 R^2 sin(2 pi / n): n = 48, R = 3 -> 24 * 9 * sin(7.5 deg) = 28.19366
  for (int n : {3, 4, 48, 200}) {
    const auto p = circle_outline(Vec2(1, -2), 3, n);
    ASSERT_EQ(p.size(), static_cast<std::size_t>(n));
    EXPECT_NEAR(signed_area(p), n / 2.0 * 9 * std::sin(2 * kPi / n), 1e-12 * 9 * n);
  }
  EXPECT_NEAR(signed_area(circle_outline(Vec2(0, 0), 3, 48)), 28.19366, 1e-5);
}

TEST(DlExcavation, HorseshoeArea) {
  // Crown of k pieces spanning pi + 2 asin(d/R) plus the triangle
  // (centre, invert ends) of area d sqrt(R^2 - d^2).
  const double R = 3, d = 1.5;
  const int k = horseshoe_arc_pieces(R, d, 48);
  EXPECT_EQ(k, 32);  // arc = pi + 2 asin(0.5) = 4 pi / 3 -> 48 * 2/3
  const auto p = horseshoe_outline(Vec2(0, 0), R, d, 48);
  ASSERT_EQ(p.size(), static_cast<std::size_t>(k + 1));
  const double arc = kPi + 2 * std::asin(d / R);
  EXPECT_NEAR(signed_area(p), k / 2.0 * R * R * std::sin(arc / k) + d * std::sqrt(R * R - d * d), 1e-12);
  // The invert is flat at depth d; nothing lies below it.
  EXPECT_DOUBLE_EQ(p.front().y(), -d);
  EXPECT_DOUBLE_EQ(p.back().y(), -d);
  for (const Vec2& v : p) EXPECT_GE(v.y(), -d - 1e-12);
  // With many pieces the area tends to the circular segment
  // R^2 (arc - sin(arc)) / 2 with arc the angle above the chord.
  const auto fine = horseshoe_outline(Vec2(0, 0), R, d, 200000);
  EXPECT_NEAR(signed_area(fine), R * R * (arc - std::sin(arc)) / 2, 1e-6);
}

TEST(DlExcavation, ArchArea) {
  // Semicircular roof (rise = w/2): w h_w + pi-ish; segmental: the fan of k
  // triangles from the roof centre minus the triangle below the wall tops.
  const double w = 6, hw = 2;
  {
    const auto p = arch_outline(Vec2(0, 0), w, hw, 3, 24);
    EXPECT_NEAR(signed_area(p), w * hw + 24 / 2.0 * 9 * std::sin(kPi / 24), 1e-12);
  }
  {
    const double f = 1.0, rho = (9 + f * f) / (2 * f), psi = std::asin(3 / rho);
    const auto p = arch_outline(Vec2(10, 5), w, hw, f, 16);
    EXPECT_NEAR(signed_area(p), w * hw + 8 * rho * rho * std::sin(2 * psi / 16) - 0.5 * w * (rho - f), 1e-12);
    double top = -1e9;
    for (const Vec2& v : p) top = std::max(top, v.y());
    EXPECT_NEAR(top, 5 + hw + f, 1e-12);  // crown at wall top + rise
  }
  {
    // No walls: the roof starts on the floor (no repeated vertices).
    const auto p = arch_outline(Vec2(0, 0), w, 0, 3, 24);
    EXPECT_EQ(p.size(), 2u + 23u);
    EXPECT_NEAR(signed_area(p), 12 * 9 * std::sin(kPi / 24), 1e-12);
  }
}

TEST(DlExcavation, ScenarioStoresOutlinesAndDoesNotClipJoints) {
  const auto r = test::run(R"(seed: 1
domain: {box: [0, 0, 40, 30]}
excavations:
  - {shape: rectangle, center: [10, 10], width: 8, height: 6}
  - {shape: circle, center: [30, 15], radius: 3}
  - {shape: horseshoe, center: [20, 22], radius: 3, invert_depth: 1.5}
  - {shape: arch, center: [10, 20], width: 6, wall_height: 2}
  - {shape: polygon, vertices: [[30, 2], [33, 2], [31, 5]]}
lines:
  - {set: fault, from: [0, 10], to: [40, 10]}
)");
  const auto& m = r.model;
  ASSERT_EQ(m.excavations.size(), 5u);
  for (const auto& e : m.excavations) EXPECT_GT(signed_area(e), 0);
  EXPECT_DOUBLE_EQ(r.report["excavations"][0]["area"].get<double>(), 48.0);
  EXPECT_NEAR(r.report["excavations"][1]["area"].get<double>(), 24 * 9 * std::sin(2 * kPi / 48), 1e-12);
  EXPECT_NEAR(r.report["excavations"][4]["area"].get<double>(), 4.5, 1e-12);
  // The fault runs through the rectangle but is kept whole (DC removes blocks).
  ASSERT_EQ(m.lines.size(), 1u);
  EXPECT_NEAR((m.lines[0].b - m.lines[0].a).norm(), 40, 1e-12);
}

}  // namespace dda::dl
