// Joints that nearly meet at one point (dc/src/near_crossings.cpp): their
// crossings are merged, and the rock around them is kept whole. Expected
// numbers are the geometry of the star, computed here independently of the
// cutter (each sector of the box seen from its centre, by the shoelace
// formula).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "dc_test_util.hpp"

namespace dda::dc::test {
namespace {

// n lines through (5, 5) at angles k pi / n, from 8 m on one side to 8 m on
// the other, each coordinate written to 12 decimals as a user's file would
// hold it: the lines then cross within a few 1e-10 m of the centre, not at
// one point.
LineModel star(int n) {
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  auto twelve = [](double x) { return std::round(x * 1e12) / 1e12; };
  for (int k = 0; k < n; ++k) {
    const double t = kPi * k / n, c = std::cos(t), s = std::sin(t);
    m.lines.push_back(line(twelve(5 - 8 * c), twelve(5 - 8 * s), twelve(5 + 8 * c), twelve(5 + 8 * s), 0));
  }
  return m;
}

// Where the ray from (5, 5) at angle t leaves the box [0, 10]^2.
Vec2 box_exit(double t) {
  const Vec2 d(std::cos(t), std::sin(t));
  double reach = 1e300;
  if (d.x() != 0) reach = std::min(reach, 5 / std::abs(d.x()));
  if (d.y() != 0) reach = std::min(reach, 5 / std::abs(d.y()));
  return Vec2(5, 5) + reach * d;
}

// The 2n sectors between consecutive rays at angles k pi / n, clipped to
// the box: centre, exit of the first ray, the box corners in between, exit
// of the second ray.
std::vector<double> sector_areas(int n) {
  std::vector<double> areas;
  const double corners[4] = {kPi / 4, 3 * kPi / 4, 5 * kPi / 4, 7 * kPi / 4};
  for (int k = 0; k < 2 * n; ++k) {
    const double t0 = kPi * k / n, t1 = kPi * (k + 1) / n;
    Polygon2 p{Vec2(5, 5), box_exit(t0)};
    for (const double c : corners)
      if (c > t0 && c < t1) p.push_back(box_exit(c));
    p.push_back(box_exit(t1));
    areas.push_back(std::abs(signed_area(p)));
  }
  std::sort(areas.begin(), areas.end());
  return areas;
}

void expect_star(int n) {
  const CutResult r = cut_blocks(star(n), {});
  expect_valid_blocks(r.model);
  ASSERT_EQ(r.model.blocks.size(), static_cast<std::size_t>(2 * n));
  EXPECT_EQ(r.report["degenerate_blocks"], 0);
  EXPECT_GE(r.report["near_crossings"]["merged"], 1);
  // The arrangement holds one vertex where the lines meet, not n (n - 1) / 2
  // crossings and as many faces: 2n blocks and the unbounded face.
  EXPECT_EQ(r.report["arrangement"]["faces"], 2 * n + 1);
  double total = 0;
  std::vector<double> got;
  for (const Block& b : r.model.blocks) {
    total += b.area;
    got.push_back(b.area);
    // Every block is a sector with its apex at the centre (the lines moved
    // by no more than the snap length, 1.4e-8 m here).
    double apex = 1e300;
    for (const Vec2& v : b.vertices) apex = std::min(apex, (v - Vec2(5, 5)).norm());
    EXPECT_LT(apex, 1.5e-8);
  }
  EXPECT_NEAR(total, 100, 1e-9);
  std::sort(got.begin(), got.end());
  const std::vector<double> expected = sector_areas(n);
  // 1e-7 m^2: the 12-decimal rounding turns each line by up to 1e-13 rad
  // and the merge moves it by up to 1.4e-8 m at the centre.
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], expected[i], 1e-7) << i;
}

TEST(CutNearCrossings, TenLinesThroughOnePointKeepAllTheRock) {
  // Before the merge two of the 20 sectors were dropped: 13.1 m^2 of 100.
  expect_star(10);
}

TEST(CutNearCrossings, AThousandLinesThroughOnePoint) {
  // Before: 464,705 faces, 460,810 of them dropped, 27.5 m^2 of the rock
  // with them.
  expect_star(1000);
}

TEST(CutNearCrossings, ALineGrazingTheDomainCornersKeepsTheCorners) {
  // The diagonal passes 1.4e-12 m from (0, 0) and (10, 10): it is taken
  // through the corners, which stay where the domain puts them: two
  // triangles of 50 m^2 with exact corners.
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  m.lines.push_back(line(-1, -1 + 2e-12, 11, 11 + 2e-12, 0));
  const CutResult r = cut_blocks(m, {});
  expect_valid_blocks(r.model);
  ASSERT_EQ(r.model.blocks.size(), 2u);
  for (const Block& b : r.model.blocks) {
    EXPECT_NEAR(b.area, 50, 1e-10);
    ASSERT_EQ(b.vertices.size(), 3u);
    int corners = 0;
    for (const Vec2& v : b.vertices) corners += v == Vec2(0, 0) || v == Vec2(10, 10);
    EXPECT_EQ(corners, 2);
  }
}

TEST(CutNearCrossings, CrossingsApartAreLeftAlone) {
  // Three lines that make a triangle of 1e-6 m sides near the centre (far
  // above the 1.4e-8 m snap length): its crossings are not merged, and the
  // tiny triangle is a block of its own, 7 blocks in all.
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  m.lines.push_back(line(-1, 5, 11, 5, 0));
  m.lines.push_back(line(5 - 6, 5 - 6 * std::sqrt(3.0), 5 + 6, 5 + 6 * std::sqrt(3.0), 0));
  m.lines.push_back(line(5 + 1e-6 + 6, 5 - 6 * std::sqrt(3.0), 5 + 1e-6 - 6, 5 + 6 * std::sqrt(3.0), 0));
  const CutResult r = cut_blocks(m, {});
  expect_valid_blocks(r.model);
  EXPECT_EQ(r.report["near_crossings"]["merged"], 0);
  EXPECT_EQ(r.model.blocks.size(), 7u);
  double smallest = 1e300;
  for (const Block& b : r.model.blocks) smallest = std::min(smallest, b.area);
  // An equilateral triangle of side 1e-6 m: sqrt(3)/4 1e-12 m^2.
  EXPECT_NEAR(smallest, std::sqrt(3.0) / 4 * 1e-12, 1e-16);
}

}  // namespace
}  // namespace dda::dc::test
