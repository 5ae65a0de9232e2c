// Block cutter: hand-checked cases. Every expected number is derived in the
// comment next to it.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "dc_test_util.hpp"
#include "dda/common/error.hpp"

namespace dda::dc::test {
namespace {

CutResult cut(const LineModel& m, const CutOptions& o = {}) {
  CutResult r = cut_blocks(m, o);
  expect_valid_blocks(r.model);
  return r;
}

std::vector<double> sorted_areas(const BlockModel& m) {
  std::vector<double> a;
  for (const Block& b : m.blocks) a.push_back(b.area);
  std::sort(a.begin(), a.end());
  return a;
}

void expect_areas(const BlockModel& m, std::vector<double> expected, double tol = 1e-9) {
  std::sort(expected.begin(), expected.end());
  const auto got = sorted_areas(m);
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], expected[i], tol) << i;
}

// The block containing p (brute force on the output polygons).
int block_at(const BlockModel& m, Vec2 p) {
  for (std::size_t i = 0; i < m.blocks.size(); ++i)
    if (point_in_polygon(m.blocks[i].vertices, p)) return static_cast<int>(i);
  return -1;
}

TEST(Cut, GridOfThroughGoingLines) {
  // Box 10 x 6; horizontal lines at y = 1, 2.5, 4 (m = 3) and vertical lines
  // at x = 2, 5, 7, 9 (n = 4), all running past the box (clipped):
  // (m+1)(n+1) = 20 blocks, areas = dx * dy with dx in {2,3,2,2,1} and
  // dy in {1,1.5,1.5,2}.
  LineModel m;
  m.domain = box(0, 0, 10, 6);
  for (double y : {1.0, 2.5, 4.0}) m.lines.push_back(line(-1, y, 11, y, 0));
  for (double x : {2.0, 5.0, 7.0, 9.0}) m.lines.push_back(line(x, -1, x, 7, 1));
  const CutResult r = cut(m);
  std::vector<double> expected;
  for (double dx : {2.0, 3.0, 2.0, 2.0, 1.0})
    for (double dy : {1.0, 1.5, 1.5, 2.0}) expected.push_back(dx * dy);
  expect_areas(r.model, expected);
  EXPECT_EQ(r.report["blocks"], 20);
  EXPECT_EQ(r.report["lines_clipped"], 7);
  EXPECT_EQ(r.report["artificial_cuts"], 0);
  EXPECT_DOUBLE_EQ(r.model.domain_area, 60.0);
  // Every block of a grid is a rectangle: 4 vertices (T-vertices on the
  // boundary where a neighbour's corner touches are removed: same set).
  for (const Block& b : r.model.blocks) EXPECT_EQ(b.vertices.size(), 4u);
  // Block order: by centroid y, then x. The first is [0,2]x[0,1].
  EXPECT_NEAR(r.model.blocks[0].centroid.x(), 1.0, 1e-12);
  EXPECT_NEAR(r.model.blocks[0].centroid.y(), 0.5, 1e-12);
  // Its edges: bottom and left on the boundary, right on x=2 (set 1), top on
  // y=1 (set 0). The polygon starts at the lowest-leftmost vertex (0,0).
  const Block& b0 = r.model.blocks[0];
  EXPECT_EQ(b0.vertices[0], Vec2(0, 0));
  EXPECT_EQ(b0.edge_set, (std::vector<int>{kBoundarySet, 1, 0, kBoundarySet}));
}

TEST(Cut, RectangleMomentsAndNoLines) {
  // Zero lines: one block = the domain. Rectangle w = 4, h = 2 at (1, 3):
  // area 8, centroid (3, 4), sxx = h w^3 / 12 = 2*64/12, syy = w h^3 / 12 =
  // 4*8/12, sxy = 0.
  LineModel m;
  m.domain = box(1, 3, 5, 5);
  const CutResult r = cut(m);
  ASSERT_EQ(r.model.blocks.size(), 1u);
  const Block& b = r.model.blocks[0];
  EXPECT_NEAR(b.area, 8.0, 1e-12);
  EXPECT_NEAR(b.centroid.x(), 3.0, 1e-12);
  EXPECT_NEAR(b.centroid.y(), 4.0, 1e-12);
  EXPECT_NEAR(b.sxx, 2.0 * 64 / 12, 1e-12);
  EXPECT_NEAR(b.syy, 4.0 * 8 / 12, 1e-12);
  EXPECT_NEAR(b.sxy, 0.0, 1e-12);
  EXPECT_EQ(b.edge_set, std::vector<int>(4, kBoundarySet));
  EXPECT_EQ(b.layer, -1);
}

TEST(Cut, DomainGivenClockwiseIsAccepted) {
  LineModel m;
  m.domain = {Vec2(0, 0), Vec2(0, 2), Vec2(2, 2), Vec2(2, 0)};  // clockwise
  m.lines.push_back(line(1, -1, 1, 3));
  const CutResult r = cut(m);
  expect_areas(r.model, {2, 2});
}

TEST(Cut, DanglingLinesMakeNoBlocks) {
  // A 10x10 box; a line floating inside, one touching only the left side,
  // and a tree of two lines meeting at a point: none closes a face.
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  m.lines.push_back(line(2, 2, 5, 5));
  m.lines.push_back(line(0, 8, 4, 8));
  m.lines.push_back(line(6, 1, 8, 3));
  m.lines.push_back(line(8, 3, 9, 1));
  const CutResult r = cut(m);
  expect_areas(r.model, {100});
  EXPECT_GE(r.report["dangling_edges_removed"].get<long long>(), 4);
  EXPECT_EQ(r.report["artificial_cuts"], 0);
  // the remaining block has only the 4 domain corners
  EXPECT_EQ(r.model.blocks[0].vertices.size(), 4u);
}

TEST(Cut, CollinearOverlappingLinesOfDifferentSets) {
  // Box 10x10; set 1 from x=0 to 6 and set 0 from x=4 to 10 on y=5. Two blocks
  // of 50. On the lower block's top edge: [6,10] and [4,6] are set 0 (lowest
  // set wins on the overlap) and merge into one edge (common input line);
  // [0,4] is set 1, so the vertex (4,5) stays.
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  m.lines.push_back(line(0, 5, 6, 5, 1));
  m.lines.push_back(line(4, 5, 10, 5, 0));
  const CutResult r = cut(m);
  expect_areas(r.model, {50, 50});
  const Block& low = r.model.blocks[0];
  ASSERT_EQ(low.vertices.size(), 5u);
  // (4,5) is where set 0 starts: every line is extended by the snap length
  // (1e-9 x diagonal = 1.4e-8 m here) at its ends, so it sits within that.
  const Polygon2 want{Vec2(0, 0), Vec2(10, 0), Vec2(10, 5), Vec2(4, 5), Vec2(0, 5)};
  for (std::size_t i = 0; i < 5; ++i) EXPECT_LT((low.vertices[i] - want[i]).norm(), 2e-8) << i;
  EXPECT_EQ(low.vertices[4], Vec2(0, 5));  // on the boundary: exact
  EXPECT_FALSE(std::signbit(low.vertices[4].x()));  // a clean 0, not -0
  EXPECT_EQ(low.edge_set, (std::vector<int>{kBoundarySet, kBoundarySet, 0, 1, kBoundarySet}));
}

TEST(Cut, CollinearOverlappingDiagonalsStayCollinear) {
  // Three overlapping pieces of the diagonal y = x (extended exactly, so no
  // sliver appears between them): two triangles of 50. Along the diagonal
  // the covering sets are [0,1.1] {0}, [1.1,3] {0,2}, [3,6] {0,1,2},
  // [6,7.3] {1,2}, [7.3,10] {1}: edge sets 0,0,0,1,1 (lowest wins), so only
  // (6,6) stays as a vertex: 4 vertices per triangle.
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  m.lines.push_back(line(0, 0, 6, 6, 0));
  m.lines.push_back(line(3, 3, 10, 10, 1));
  m.lines.push_back(line(1.1, 1.1, 7.3, 7.3, 2));
  const CutResult r = cut(m);
  expect_areas(r.model, {50, 50});
  for (const Block& b : r.model.blocks) {
    ASSERT_EQ(b.vertices.size(), 4u);
    double d = 1e9;  // (6,6), within the snap length (see above)
    for (const Vec2& v : b.vertices) d = std::min(d, (v - Vec2(6, 6)).norm());
    EXPECT_LT(d, 2e-8);
    auto sets = b.edge_set;
    std::sort(sets.begin(), sets.end());
    EXPECT_EQ(sets, (std::vector<int>{kBoundarySet, kBoundarySet, 0, 1}));
  }
}

TEST(Cut, DuplicateLines) {
  // The same line three times, sets 2, 1, 2: two blocks of 50, the shared
  // edge gets set 1 (lowest).
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  m.lines.push_back(line(5, 0, 5, 10, 2));
  m.lines.push_back(line(5, 0, 5, 10, 1));
  m.lines.push_back(line(5, 0, 5, 10, 2));
  const CutResult r = cut(m);
  expect_areas(r.model, {50, 50});
  for (const Block& b : r.model.blocks) {
    int n1 = 0;
    for (int s : b.edge_set) n1 += s == 1;
    EXPECT_EQ(n1, 1);
  }
}

TEST(Cut, TJunctionsExactAndNearlyExact) {
  // Box 10x10, y=5 across; x=5 from y=5 up (ends exactly on y=5); x=2 from
  // y = 5 + 1e-13 down to the bottom (misses y=5 by far less than the snap
  // length 1e-9 * diag): blocks 25 + 25 (top) and 10 + 40 (bottom).
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  m.lines.push_back(line(0, 5, 10, 5, 0));
  m.lines.push_back(line(5, 5, 5, 10, 1));
  m.lines.push_back(line(2, 0, 2, 5 - 1e-13, 1));
  const CutResult r = cut(m);
  expect_areas(r.model, {25, 25, 10, 40}, 1e-9);
  // The lower right block [2,10]x[0,5] does not keep (5,5): the upper blocks'
  // corner touches its straight top edge (same set on both sides).
  const int lr = block_at(r.model, Vec2(6, 2));
  ASSERT_GE(lr, 0);
  EXPECT_EQ(r.model.blocks[lr].vertices.size(), 4u);
}

TEST(Cut, LinesThroughVertices) {
  // The diagonal through both domain corners, and x=5, y=5 crossing at (5,5)
  // where the diagonal passes too: triangles of 12.5 in the two quadrants the
  // diagonal cuts, squares of 25 in the other two.
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  m.lines.push_back(line(-1, -1, 11, 11, 0));
  m.lines.push_back(line(5, -1, 5, 11, 1));
  m.lines.push_back(line(-1, 5, 11, 5, 1));
  const CutResult r = cut(m);
  expect_areas(r.model, {12.5, 12.5, 12.5, 12.5, 25, 25});
}

TEST(Cut, NearZeroLengthAndShortSegments) {
  // 1e-12 m is below the default 1e-9 x diag (1.4e-8); 0.3 m is below an
  // explicit min_segment_length of 0.5. Neither cuts; the line y=5 does.
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  m.lines.push_back(line(3, 3, 3 + 1e-12, 3));
  m.lines.push_back(line(0, 5, 10, 5));
  {
    const CutResult r = cut(m);
    expect_areas(r.model, {50, 50});
    EXPECT_EQ(r.report["segments_too_short"], 1);
  }
  m.lines.push_back(line(7, 4.9, 7, 5.2));  // 0.3 m, crosses y=5: would make no block anyway
  m.lines.push_back(line(2, 0, 2, 5));      // 5 m, kept
  CutOptions o;
  o.min_segment_length = 0.5;
  const CutResult r = cut(m, o);
  EXPECT_EQ(r.report["segments_too_short"], 2);
  expect_areas(r.model, {50, 10, 40});
}

TEST(Cut, LinesOutsideTheDomain) {
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  m.lines.push_back(line(11, 0, 11, 10));
  m.lines.push_back(line(-5, -5, -1, 20));
  m.lines.push_back(line(-1, 20, 20, 11));
  const CutResult r = cut(m);
  expect_areas(r.model, {100});
  EXPECT_EQ(r.report["lines_outside_domain"], 3);
}

TEST(Cut, NonConvexDomainClipsIntoPieces) {
  // U-shaped domain: [0,10]x[0,10] minus the notch [4,6]x[5,10]. The line
  // y=7 crosses both arms and the notch: its middle piece is outside.
  // Arms above y=7: 4 x 3 = 12 each; the rest: 100 - 10 - 24 = 66.
  LineModel m;
  m.domain = {Vec2(0, 0), Vec2(10, 0), Vec2(10, 10), Vec2(6, 10), Vec2(6, 5), Vec2(4, 5), Vec2(4, 10), Vec2(0, 10)};
  m.lines.push_back(line(-1, 7, 11, 7));
  const CutResult r = cut(m);
  expect_areas(r.model, {12, 12, 66});
  EXPECT_DOUBLE_EQ(r.model.domain_area, 90.0);
}

TEST(Cut, ExcavationTouchingNoJointGetsArtificialCuts) {
  // Box 10x10, rectangle excavation [4,6]x[4,5] touching nothing: the face
  // around it has a hole, cut up from (6,5) to (6,10) and down from (4,4) to
  // (4,0): two blocks, 100 - 2 = 98 in total.
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  m.excavations.push_back(box(4, 4, 6, 5));
  const CutResult r = cut(m);
  ASSERT_EQ(r.model.blocks.size(), 2u);
  EXPECT_NEAR(total_area(r.model), 98.0, 1e-12);
  EXPECT_NEAR(r.model.excavated_area, 2.0, 1e-12);
  EXPECT_EQ(r.report["artificial_cuts"], 2);
  EXPECT_EQ(r.report["removed_in_excavations"], 1);
  // Left block: x in [0,4] plus [4,6]x[0,4] below... exact: the down cut at
  // x=4 and the up cut at x=6 give a left part of 4*10 + 2*4 = 48 and a
  // right part of 4*10 + 2*5 = 50.
  expect_areas(r.model, {48, 50});
  int artificial = 0;
  for (const Block& b : r.model.blocks)
    for (int s : b.edge_set) artificial += s == kArtificialSet;
  EXPECT_EQ(artificial, 4);  // each cut is an edge of both blocks
}

TEST(Cut, FloatingClosedTriangle) {
  // A triangle of joints (2,2) (4,2) (3,4) inside a 10x10 box touches
  // nothing: a block of area 2 and a face with a hole, cut up from the top
  // (3,4) to (3,10) and down from the bottom-left (2,2) to (2,0): the outside
  // splits into two blocks; the areas sum to 100.
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  m.lines.push_back(line(2, 2, 4, 2, 0));
  m.lines.push_back(line(4, 2, 3, 4, 1));
  m.lines.push_back(line(3, 4, 2, 2, 2));
  const CutResult r = cut(m);
  ASSERT_EQ(r.model.blocks.size(), 3u);
  EXPECT_NEAR(total_area(r.model), 100.0, 1e-12);
  EXPECT_EQ(r.report["artificial_cuts"], 2);
  const int t = block_at(r.model, Vec2(3, 2.5));
  ASSERT_GE(t, 0);
  EXPECT_NEAR(r.model.blocks[t].area, 2.0, 1e-12);
  EXPECT_EQ(r.model.blocks[t].vertices.size(), 3u);
  auto sets = r.model.blocks[t].edge_set;
  std::sort(sets.begin(), sets.end());
  EXPECT_EQ(sets, (std::vector<int>{0, 1, 2}));
  // Left of the cuts: [0,2]x[0,10] + [2,3]x[4,10] + the part of [2,3]x[2,4]
  // left of the triangle (1) = 20 + 6 + 1 = 27; right: 100 - 2 - 27 = 71.
  expect_areas(r.model, {2, 27, 71});
}

TEST(Cut, StackedFloatingTrianglesCutOneAnother) {
  // Two triangles above each other on x in [4,6]: the lower one's up cut ends
  // on the upper one's base, the upper one's down cut ends on the lower one's
  // corner. Areas still sum to 100 and every block is simple.
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  for (double y : {2.0, 6.0}) {
    m.lines.push_back(line(4, y, 6, y));
    m.lines.push_back(line(6, y, 5, y + 2));
    m.lines.push_back(line(5, y + 2, 4, y));
  }
  const CutResult r = cut(m);
  EXPECT_NEAR(total_area(r.model), 100.0, 1e-12);
  EXPECT_GE(r.report["artificial_cuts"].get<int>(), 3);
  EXPECT_GE(r.model.blocks.size(), 4u);
}

TEST(Cut, TriangleTouchingTheBoundaryAtOneVertex) {
  // The triangle (5,0) (6,2) (4,2) hangs on the bottom boundary at (5,0): the
  // face around it touches itself there. A cut up from (6,2) to (6,10) makes
  // it simple: blocks 2 (triangle), and 100 - 2 split at x = 6: the right
  // part is [6,10]x[0,10] plus the triangle (5,0) (6,0) (6,2) under the
  // triangle's right side = 40 + 1; the left part 100 - 2 - 41 = 57.
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  m.lines.push_back(line(5, 0, 6, 2));
  m.lines.push_back(line(6, 2, 4, 2));
  m.lines.push_back(line(4, 2, 5, 0));
  const CutResult r = cut(m);
  EXPECT_NEAR(total_area(r.model), 100.0, 1e-12);
  EXPECT_EQ(r.report["degenerate_blocks"], 0);
  // right of x=6: 4*10 = 40; left: 100 - 40 - 2 = 58
  expect_areas(r.model, {2, 41, 57});
}

TEST(Cut, PointsAreLocated) {
  // Box 10x10 cut by x=5: left block index 0 (centroid (2.5,5) sorts first by
  // y tie then x). A point on the joint x=5 belongs to the block to its west
  // (left of the edge directed upward); a point on y-edges to the block above.
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  m.lines.push_back(line(5, -1, 5, 11));
  m.points.push_back(point("fix", PointKind::Fixed, 1, 1));
  m.points.push_back(point("load", PointKind::Load, 9, 9));
  m.points.push_back(point("meas", PointKind::Measurement, 5, 3));
  m.points.push_back(point("corner", PointKind::Fixed, 10, 0));
  const CutResult r = cut(m);
  ASSERT_EQ(r.model.blocks.size(), 2u);
  const int left = block_at(r.model, Vec2(1, 1)), right = block_at(r.model, Vec2(9, 9));
  ASSERT_EQ(r.model.points.size(), 4u);
  EXPECT_EQ(r.model.points[0].block, left);
  EXPECT_EQ(r.model.points[1].block, right);
  EXPECT_EQ(r.model.points[2].block, left);
  EXPECT_EQ(r.model.points[3].block, right);
  EXPECT_EQ(r.model.points[1].point.name, "load");
}

TEST(Cut, PointInExcavationOrOutsideIsAnError) {
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  m.excavations.push_back(box(4, 4, 6, 6));
  m.lines.push_back(line(5, -1, 5, 11));
  m.points.push_back(point("m1", PointKind::Measurement, 5.5, 5.5));
  try {
    cut_blocks(m, {});
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string w = e.what();
    EXPECT_NE(w.find("'m1'"), std::string::npos) << w;
    EXPECT_NE(w.find("(5.5, 5.5)"), std::string::npos) << w;
    EXPECT_NE(w.find("excavation"), std::string::npos) << w;
  }
  m.points[0] = point("f1", PointKind::Fixed, 12, 5);
  EXPECT_THROW(cut_blocks(m, {}), InputError);
  m.points[0] = point("h1", PointKind::Hole, 12, 5);
  EXPECT_THROW(cut_blocks(m, {}), InputError);
}

TEST(Cut, HolePointRemovesItsBlock) {
  // x=5 and y=5 make four 25 m^2 blocks; a hole point at (7,7) removes the
  // top-right one: 3 blocks, excavated area 25; a measurement point in the
  // removed block is an error.
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  m.lines.push_back(line(5, -1, 5, 11));
  m.lines.push_back(line(-1, 5, 11, 5));
  m.points.push_back(point("h", PointKind::Hole, 7, 7));
  m.points.push_back(point("m", PointKind::Measurement, 2, 2));
  const CutResult r = cut(m);
  expect_areas(r.model, {25, 25, 25});
  EXPECT_NEAR(r.model.excavated_area, 25, 1e-12);
  EXPECT_EQ(r.report["removed_by_hole_points"], 1);
  ASSERT_EQ(r.model.points.size(), 1u);  // the hole point is consumed
  EXPECT_EQ(r.model.points[0].point.name, "m");
  m.points.push_back(point("bad", PointKind::Load, 8, 8));
  EXPECT_THROW(cut_blocks(m, {}), InputError);
}

TEST(Cut, SliverIsMergedOrReported) {
  // y=5 and y=5.01 across a 10x10 box: a sliver 10 x 0.01 (area 0.1,
  // aspect = length / width = 10 / 0.01 = 1000).
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  m.lines.push_back(line(-1, 5, 11, 5, 0));
  m.lines.push_back(line(-1, 5.01, 11, 5.01, 1));
  {
    CutOptions o;
    o.sliver.min_area = 0.5;
    const CutResult r = cut(m, o);
    ASSERT_EQ(r.model.blocks.size(), 2u);
    EXPECT_NEAR(total_area(r.model), 100.0, 1e-9);
    EXPECT_EQ(r.report["slivers_merged"], 1);
    EXPECT_EQ(r.report["slivers_reported"], 0);
    // Merged into one neighbour (both joint edges are 10 m long): into the
    // lower block 50.1 + 49.9, into the upper one 50 + 50.
    const auto a = sorted_areas(r.model);
    const bool lower = std::abs(a[0] - 49.9) < 1e-9 && std::abs(a[1] - 50.1) < 1e-9;
    const bool upper = std::abs(a[0] - 50) < 1e-9 && std::abs(a[1] - 50) < 1e-9;
    EXPECT_TRUE(lower || upper) << a[0] << " " << a[1];
  }
  {
    CutOptions o;
    o.sliver.max_aspect = 50;
    o.sliver.merge = false;
    const CutResult r = cut(m, o);
    ASSERT_EQ(r.model.blocks.size(), 3u);
    EXPECT_EQ(r.report["slivers_merged"], 0);
    ASSERT_EQ(r.report["slivers_reported"], 1);
    EXPECT_NEAR(r.report["slivers"][0]["area"].get<double>(), 0.1, 1e-9);
    EXPECT_NEAR(r.report["slivers"][0]["aspect"].get<double>(), 10.0 / 0.01, 1e-6);
  }
}

TEST(Cut, SliverAgainstBoundaryIsNotMergedAcrossIt) {
  // The sliver between the boundary y=0 and the joint y=0.01 can only merge
  // across the joint: 2 blocks, 10*0.01 + the rest.
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  m.lines.push_back(line(-1, 0.01, 11, 0.01));
  m.excavations.push_back(box(4, 9.99, 6, 10));  // excavation touching the top
  CutOptions o;
  o.sliver.min_area = 0.5;
  const CutResult r = cut(m, o);
  ASSERT_EQ(r.model.blocks.size(), 1u);
  EXPECT_NEAR(total_area(r.model), 100.0 - 0.02, 1e-9);
  EXPECT_EQ(r.report["slivers_merged"], 1);
}

TEST(Cut, ImportedGeometryWithoutDomain) {
  // No domain: a closed outline of joints 4 x 3 with a line across at x=2:
  // two blocks of 6, domain area 12; a dangling line outside adds nothing.
  LineModel m;
  m.lines.push_back(line(0, 0, 4, 0, 0));
  m.lines.push_back(line(4, 0, 4, 3, 0));
  m.lines.push_back(line(4, 3, 0, 3, 0));
  m.lines.push_back(line(0, 3, 0, 0, 0));
  m.lines.push_back(line(2, 0, 2, 3, 1));
  m.lines.push_back(line(5, 5, 7, 6, 1));
  const CutResult r = cut(m);
  expect_areas(r.model, {6, 6});
  EXPECT_NEAR(r.model.domain_area, 12, 1e-12);
  for (const Block& b : r.model.blocks) {
    EXPECT_EQ(b.vertices.size(), 4u);
    for (int s : b.edge_set) EXPECT_GE(s, 0);
  }
}

TEST(Cut, LayersFromCentroids) {
  // Horizontal beds [0,4) and [4,10]; bedding line y=4: the lower block's
  // centroid y=2 is in bed 0, the upper one's (y=7) in bed 1.
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  JointLine bed = line(-1, 4, 11, 4, 0);
  bed.kind = LineKind::Bedding;
  m.lines.push_back(bed);
  m.layers = {Layer{0, 4}, Layer{4, 10}};
  const CutResult r = cut(m);
  ASSERT_EQ(r.model.blocks.size(), 2u);
  EXPECT_EQ(r.model.blocks[0].layer, 0);
  EXPECT_EQ(r.model.blocks[1].layer, 1);
  EXPECT_EQ(r.model.layers.size(), 2u);
}

TEST(Cut, DippingLayersUseTheBedNormal) {
  // Dip 30 deg: n = (-sin 30, cos 30) = (-0.5, 0.866). A 10x10 box cut by
  // x=5: centroids (2.5, 5) and (7.5, 5) have s = -1.25 + 4.33 = 3.08 and
  // -3.75 + 4.33 = 0.58. Beds [-10, 2) and [2, 20]: right block bed 0, left
  // bed 1.
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  m.lines.push_back(line(5, -1, 5, 11));
  m.layers = {Layer{-10, 2}, Layer{2, 20}};
  m.bedding_dip_deg = 30;
  const CutResult r = cut(m);
  ASSERT_EQ(r.model.blocks.size(), 2u);
  EXPECT_EQ(r.model.blocks[block_at(r.model, Vec2(1, 1))].layer, 1);
  EXPECT_EQ(r.model.blocks[block_at(r.model, Vec2(9, 1))].layer, 0);
}

TEST(Cut, ReportKeys) {
  LineModel m;
  m.domain = box(0, 0, 10, 10);
  m.lines.push_back(line(5, -1, 5, 11));
  const CutResult r = cut(m);
  for (const char* k :
       {"input_lines", "segments_too_short", "lines_outside_domain", "lines_clipped", "arrangement",
        "dangling_edges_removed", "faces", "blocks", "removed_in_excavations", "removed_by_hole_points",
        "artificial_cuts", "slivers_merged", "slivers_reported", "degenerate_blocks", "seconds"})
    EXPECT_TRUE(r.report.contains(k)) << k;
  EXPECT_EQ(r.report["input_lines"], 1);
  // the line's two stubs past the boundary are dangling
  EXPECT_EQ(r.report["dangling_edges_removed"], 2);
}

TEST(CutOptions, ParsesTheCuttingSection) {
  const YamlNode root = YamlNode::load_string(
      "cutting:\n  min_segment_length: 0.001\n  sliver:\n    min_area: 0.01\n    max_aspect: 20\n"
      "    merge: false\n",
      "s.yaml");
  const CutOptions o = parse_cut_options(root.optional_child("cutting"));
  EXPECT_DOUBLE_EQ(o.min_segment_length, 0.001);
  EXPECT_DOUBLE_EQ(o.sliver.min_area, 0.01);
  EXPECT_DOUBLE_EQ(o.sliver.max_aspect, 20);
  EXPECT_FALSE(o.sliver.merge);
  const CutOptions d = parse_cut_options(std::nullopt);
  EXPECT_EQ(d.min_segment_length, 0);
  EXPECT_TRUE(d.sliver.merge);
  const YamlNode bad = YamlNode::load_string("cutting:\n  min_segment_lenght: 1\n", "s.yaml");
  EXPECT_THROW(parse_cut_options(bad.optional_child("cutting")), InputError);
  const YamlNode neg = YamlNode::load_string("cutting:\n  sliver:\n    max_aspect: 0.5\n", "s.yaml");
  EXPECT_THROW(parse_cut_options(neg.optional_child("cutting")), InputError);
}

}  // namespace
}  // namespace dda::dc::test
