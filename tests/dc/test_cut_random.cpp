// Block cutter on random line sets: conservation of area, edge provenance,
// determinism, and degenerate (lattice) input.
#include <gtest/gtest.h>

#include "dc_test_util.hpp"

namespace dda::dc::test {
namespace {

// Each edge lies on something of its set: a line of that set, the domain
// outline, an excavation outline, or (artificial) is vertical.
void expect_edges_on_their_sets(const LineModel& m, const BlockModel& bm, double tol) {
  for (const Block& b : bm.blocks) {
    const std::size_t n = b.vertices.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2& p = b.vertices[i];
      const Vec2& q = b.vertices[(i + 1) % n];
      const Vec2 mid = 0.5 * (p + q);
      const int s = b.edge_set[i];
      if (s == kBoundarySet) {
        EXPECT_LT(dist_to_outline(mid, m.domain), tol);
      } else if (s == kExcavationSet) {
        double d = 1e300;
        for (const Polygon2& e : m.excavations) d = std::min(d, dist_to_outline(mid, e));
        EXPECT_LT(d, tol);
      } else if (s == kArtificialSet) {
        EXPECT_EQ(p.x(), q.x());
      } else {
        double d = 1e300;
        for (const JointLine& l : m.lines)
          if (l.set == s) d = std::min(d, dist_to_segment(mid, l.a, l.b));
        EXPECT_LT(d, tol) << "edge " << i << " set " << s;
      }
    }
  }
}

class RandomCut : public ::testing::TestWithParam<unsigned> {};

TEST_P(RandomCut, AreasSumToDomainMinusExcavations) {
  // Domain 100 x 80 with a rectangle excavation [20,40]x[20,30] (200 m^2) and
  // a 64-gon of radius 8 at (70,50) (area 0.5*64*64*sin(2pi/64) m^2); 300
  // lines of length 5..40 m, three sets.
  LineModel m;
  m.domain = box(0, 0, 100, 80);
  m.excavations.push_back(box(20, 20, 40, 30));
  m.excavations.push_back(circle(Vec2(70, 50), 8, 64));
  m.lines = random_lines(GetParam(), 300, Box2{Vec2(-10, -10), Vec2(110, 90)}, 5, 40, 3);
  const double circle_area = 0.5 * 64 * 64 * std::sin(2 * kPi / 64);
  const double expected = 8000 - 200 - circle_area;

  const CutResult r = cut_blocks(m, {});
  expect_valid_blocks(r.model);
  EXPECT_NEAR(total_area(r.model), expected, 1e-9 * 8000);
  EXPECT_NEAR(r.model.excavated_area, 200 + circle_area, 1e-9 * 8000);
  EXPECT_EQ(r.report["degenerate_blocks"], 0);
  EXPECT_GT(r.model.blocks.size(), 100u);
  expect_edges_on_their_sets(m, r.model, 1e-7);

  // Deterministic: the same input gives the same blocks in the same order.
  const CutResult again = cut_blocks(m, {});
  ASSERT_EQ(again.model.blocks.size(), r.model.blocks.size());
  for (std::size_t i = 0; i < r.model.blocks.size(); ++i) {
    EXPECT_EQ(again.model.blocks[i].vertices, r.model.blocks[i].vertices);
    EXPECT_EQ(again.model.blocks[i].edge_set, r.model.blocks[i].edge_set);
  }
}

TEST_P(RandomCut, SliverMergingKeepsTheAreaSum) {
  LineModel m;
  m.domain = box(0, 0, 100, 80);
  m.excavations.push_back(circle(Vec2(50, 40), 10, 48));
  m.lines = random_lines(GetParam() + 100, 400, Box2{Vec2(0, 0), Vec2(100, 80)}, 5, 30, 2);
  const double expected = 8000 - 0.5 * 48 * 100 * std::sin(2 * kPi / 48);
  CutOptions o;
  o.sliver.min_area = 0.5;
  o.sliver.max_aspect = 30;
  const CutResult r = cut_blocks(m, o);
  expect_valid_blocks(r.model);
  EXPECT_NEAR(total_area(r.model), expected, 1e-9 * 8000);
  EXPECT_GT(r.report["slivers_merged"].get<long long>(), 0);
  CutOptions report_only = o;
  report_only.sliver.merge = false;
  const CutResult r2 = cut_blocks(m, report_only);
  EXPECT_GT(r2.model.blocks.size(), r.model.blocks.size());
  EXPECT_NEAR(total_area(r2.model), expected, 1e-9 * 8000);
  EXPECT_GE(r2.report["slivers_reported"].get<long long>(), r.report["slivers_merged"].get<long long>());
}

TEST_P(RandomCut, LatticeLinesFullOfDegeneracies) {
  // Endpoints on the integer lattice of a 12 x 12 box: collinear overlaps,
  // duplicates, lines through vertices and T-junctions everywhere, plus
  // closed loops floating in faces. Every block valid, areas sum to 144.
  std::mt19937_64 rng(GetParam());
  std::uniform_int_distribution<int> u(-1, 13);
  LineModel m;
  m.domain = box(0, 0, 12, 12);
  for (int i = 0; i < 60; ++i) {
    const int x0 = u(rng), y0 = u(rng);
    int x1 = u(rng), y1 = u(rng);
    if (x0 == x1 && y0 == y1) ++x1;
    m.lines.push_back(line(x0, y0, x1, y1, i % 4));
  }
  // floating squares and triangles
  m.lines.push_back(line(3.5, 3.5, 4.5, 3.5, 1));
  m.lines.push_back(line(4.5, 3.5, 4.5, 4.5, 1));
  m.lines.push_back(line(4.5, 4.5, 3.5, 4.5, 1));
  m.lines.push_back(line(3.5, 4.5, 3.5, 3.5, 1));
  m.excavations.push_back(box(7.25, 7.25, 8.75, 8.5));
  const CutResult r = cut_blocks(m, {});
  expect_valid_blocks(r.model);
  EXPECT_EQ(r.report["degenerate_blocks"], 0);
  EXPECT_NEAR(total_area(r.model) + r.model.excavated_area, 144.0, 1e-9 * 144);
  EXPECT_NEAR(r.model.excavated_area, 1.5 * 1.25, 1e-9);
  expect_edges_on_their_sets(m, r.model, 1e-7);
}

TEST_P(RandomCut, NoDomainEveryBoundedFaceIsABlock) {
  LineModel m;
  m.lines = random_lines(GetParam() + 7, 200, Box2{Vec2(0, 0), Vec2(50, 50)}, 5, 25, 2);
  const CutResult r = cut_blocks(m, {});
  expect_valid_blocks(r.model);
  EXPECT_NEAR(total_area(r.model), r.model.domain_area, 1e-9 * r.model.domain_area);
  EXPECT_EQ(r.report["degenerate_blocks"], 0);
  for (const Block& b : r.model.blocks)
    for (int s : b.edge_set) EXPECT_TRUE(s >= 0 || s == kArtificialSet);
}

INSTANTIATE_TEST_SUITE_P(Seeds, RandomCut, ::testing::Values(1u, 2u, 3u, 4u, 5u));

}  // namespace
}  // namespace dda::dc::test
