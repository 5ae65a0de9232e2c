// Where a model may lie and the local origin it is computed about
// (coordinate_range.hpp): the rule that leaves models near the origin
// exactly where they are, the exact shift of a far model, the checks that
// still refuse, and the origin's round trip through the stage files.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "dda/common/coordinate_range.hpp"
#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"
#include "dda/common/model_io.hpp"
#include "dda/common/model_io3d.hpp"
#include "input_error_of.hpp"
#include "scratch_dir_test.hpp"

namespace dda {
namespace {

using testing::input_error_of;

Polygon2 square(double x0, double y0, double side) {
  return {Vec2(x0, y0), Vec2(x0 + side, y0), Vec2(x0 + side, y0 + side), Vec2(x0, y0 + side)};
}

// x - o is exact when adding o back gives x and the two-sum error of the
// subtraction is zero (Knuth's TwoSum: the rounding error of a - b in
// doubles, computed without rounding).
bool exact_difference(double x, double o) {
  const double d = x - o;
  const double bv = x - d;          // TwoSum of x and -o
  const double av = d - bv;
  const double err = (x - av) + (-o - bv);
  return err == 0 && d + o == x;
}

TEST(CoordinateRange, AreaOfASquareFarFromTheOrigin) {
  // 10 m square at x, y = 1e12: about the origin the cross products are
  // 1e24 and their rounding (1e8) swamps the 100 m^2; about its own corner
  // every product is exact.
  EXPECT_EQ(signed_area(square(1e12, 1e12, 10)), 100.0);
  EXPECT_EQ(signed_area(square(-3e9, 7e8, 0.5)), 0.25);
}

TEST(LocalOrigin, ModelsNearTheOriginKeepOriginZero) {
  // Every model that ran before local origins lay within 1e7 sizes and
  // 1e9 m, so its origin is exactly zero and it runs bit for bit as before.
  EXPECT_EQ(choose_local_origin(square(0, 0, 10)), Vec2(0, 0));
  // A 1 m model at UTM northing 5.4e6 m: 5.4e6 < 1e7 x 1.41 m.
  EXPECT_EQ(choose_local_origin(square(4.5e5, 5.4e6, 1)), Vec2(0, 0));
  // 10 m at 1e8 m: 1e8 < 1e7 x 14.1 m.
  EXPECT_EQ(choose_local_origin(square(1e8, 1e8, 10)), Vec2(0, 0));
  EXPECT_EQ(choose_local_origin(std::vector<Vec2>{}), Vec2(0, 0));
  EXPECT_EQ(choose_local_origin(std::vector<Vec3>{Vec3(0, 0, 0), Vec3(10, 10, 10)}), Vec3(0, 0, 0));
}

TEST(LocalOrigin, TheIssuesBoxAtOneE12) {
  // 10 m box at x, y = 1e12: 1e12 > 1e7 x 14.1 m. Its centre 1e12 + 5
  // rounded to a multiple of 8 (the largest power of two <= 10 m):
  // (1e12 + 5) / 8 = 125000000000.625 rounds to 125000000001, so the origin
  // is 1e12 + 8 on both axes and the corners are -8 and 2 about it.
  const Vec2 o = choose_local_origin(square(1e12, 1e12, 10));
  EXPECT_EQ(o, Vec2(1e12 + 8, 1e12 + 8));
  EXPECT_EQ(1e12 - o.x(), -8.0);
  EXPECT_EQ((1e12 + 10) - o.y(), 2.0);
  // Negative coordinates mirror it: centre -(1e12 + 5) rounds away from 0 too.
  EXPECT_EQ(choose_local_origin(square(-1e12 - 10, -1e12 - 10, 10)), Vec2(-1e12 - 8, -1e12 - 8));
}

TEST(LocalOrigin, BeyondOneE9MetresEvenALargeModelMoves) {
  // 1 km at 2e9 m: only 1.4e6 sizes away, but beyond 1e9 m. Centre
  // 2e9 + 500 is a multiple of 512 (the largest power of two <= 1000) to
  // the nearest: 2e9 + 500 = 3906250.9765625 x 512, so 3906251 x 512 =
  // 2000000512.
  const Vec2 o = choose_local_origin(square(2e9, 2e9, 1000));
  EXPECT_EQ(o, Vec2(2000000512.0, 2000000512.0));
}

TEST(LocalOrigin, AnAxisNearZeroStaysAtZero) {
  // At (1e12, 0): x moves, y straddles 0 (|y| <= 10 m already).
  const Vec2 o = choose_local_origin(square(1e12, -5, 10));
  EXPECT_EQ(o.y(), 0.0);
  EXPECT_EQ(o.x(), 1e12 + 8);
}

TEST(LocalOrigin, TheShiftIsExactForEveryPointOfTheModel) {
  // 100,000 random points of a 37.3 m x 21.9 m x 5.1 m model at (1e12,
  // -3e11, 7e9): each coordinate less the origin is exact (no rounding),
  // so the local model is the user's model moved, bit for bit.
  std::mt19937_64 rng(12345);
  const Vec3 lo(1e12, -3e11, 7e9), size(37.3, 21.9, 5.1);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec3> points;
  for (int i = 0; i < 100000; ++i)
    points.push_back(lo + Vec3(u(rng) * size.x(), u(rng) * size.y(), u(rng) * size.z()));
  const Vec3 o = choose_local_origin(points);
  for (int k = 0; k < 3; ++k) EXPECT_NE(o[k], 0.0) << k;
  int inexact = 0;
  double farthest_local = 0;
  for (const Vec3& p : points)
    for (int k = 0; k < 3; ++k) {
      inexact += !exact_difference(p[k], o[k]);
      farthest_local = std::max(farthest_local, std::abs(p[k] - o[k]));
    }
  EXPECT_EQ(inexact, 0);
  // About the origin the model is within its own extent (37.3 m).
  EXPECT_LE(farthest_local, 37.3);
  // The check can fail: 0.3 is no multiple of 2^-13, the spacing of
  // doubles at 1e12, so 1e12 + 0.1 less 0.3 is rounded.
  EXPECT_FALSE(exact_difference(1e12 + 0.1, 0.3));
}

TEST(LocalOrigin, MoveALinesModelKeepsEveryPositionTogether) {
  LineModel m;
  m.domain = square(1e12, 1e12, 10);
  m.excavations = {square(1e12 + 4, 1e12 + 4, 2)};
  m.lines = {{Vec2(1e12, 1e12 + 5), Vec2(1e12 + 10, 1e12 + 5), 0, LineKind::Bedding, -1}};
  m.points = {{"p", PointKind::Measurement, Vec2(1e12 + 1, 1e12 + 9)}};
  m.layers = {{1e12, 1e12 + 5, 0, 0}, {1e12 + 5, 1e12 + 10, 0, 0}};  // horizontal beds: levels are y
  move_to_local_origin(m);
  EXPECT_EQ(m.origin, Vec2(1e12 + 8, 1e12 + 8));  // as in TheIssuesBoxAtOneE12
  EXPECT_EQ(m.domain, square(-8, -8, 10));
  EXPECT_EQ(m.excavations[0], square(-4, -4, 2));
  EXPECT_EQ(m.lines[0].a, Vec2(-8, -3));
  EXPECT_EQ(m.points[0].p, Vec2(-7, 1));
  EXPECT_EQ(m.layers[1].bottom, -3.0);
  EXPECT_EQ(m.layers[1].top, 2.0);
  // A model near the origin is left alone, to the bit.
  LineModel near;
  near.domain = square(0.1, 0.2, 10);
  near.points = {{"q", PointKind::Fixed, Vec2(0.3, 0.7)}};
  move_to_local_origin(near);
  EXPECT_EQ(near.origin, Vec2(0, 0));
  EXPECT_EQ(near.domain, square(0.1, 0.2, 10));
  EXPECT_EQ(near.points[0].p, Vec2(0.3, 0.7));
}

TEST(LocalOrigin, MoveAFractureModelMovesPlanesByTheirNormal) {
  FractureModel m;
  m.domain = {Vec3(1e9 - 2, 1e9 - 2, 1e9 - 2), Vec3(1e9 + 2, 1e9 + 2, 1e9 + 2)};
  Excavation3 e;
  e.region.half_spaces = {{Vec3(0, 0, 1), 1e9 + 1}};  // z <= 1e9 + 1
  m.excavations = {e};
  Fracture3 f;
  f.centre = Vec3(1e9 + 1, 1e9 - 1, 1e9 + 1.5);
  m.fractures = {f};
  m.points = {{"p", PointKind::Measurement, Vec3(1e9 - 1, 1e9 - 1, 1e9 - 1)}};
  m.layers = {{1e9 - 2, 1e9, 0, 0}};  // levels along bed_normal (0, 0, 1)
  move_to_local_origin(m);
  // A 4 m box at 1e9: 1e9 > 1e7 x 6.93 m; its centre 1e9 is a multiple of
  // 4 (the largest power of two <= 4 m).
  EXPECT_EQ(m.origin, Vec3(1e9, 1e9, 1e9));
  EXPECT_EQ(m.domain.lo, Vec3(-2, -2, -2));
  EXPECT_EQ(m.excavations[0].region.half_spaces[0].offset, 1.0);  // z <= 1 about it
  EXPECT_EQ(m.fractures[0].centre, Vec3(1, -1, 1.5));
  EXPECT_EQ(m.points[0].p, Vec3(-1, -1, -1));
  EXPECT_EQ(m.layers[0].bottom, -2.0);
  EXPECT_EQ(m.layers[0].top, 0.0);
}

TEST(CoordinateRange, OnlyNonFiniteAndAstronomicalCoordinatesAreRefused) {
  // The issue's 10 m box at 1e12 passes now (it is moved, not refused).
  EXPECT_NO_THROW(check_coordinate_range(square(1e12, 1e12, 10), "far.yaml"));
  // The 1e300 m domain whose area was infinite: refused before it is cut.
  EXPECT_EQ(input_error_of([] { check_coordinate_range(square(0, 0, 1e300), "huge.yaml"); }),
            "huge.yaml: has coordinates up to 1e+300 m, beyond the 1e+15 m any model may reach (coordinates are "
            "metres; doubles there are more than 0.1 m apart).");
  EXPECT_EQ(input_error_of([] { check_coordinate_range(std::vector<Vec2>{Vec2(0, 0), Vec2(std::nan(""), 1)}, "nan.yaml"); }),
            "nan.yaml: has a coordinate that is not a finite number.");
  EXPECT_THROW(check_coordinate_range(std::vector<Vec3>{Vec3(0, 0, 0), Vec3(0, 2e15, 1)}, "f.yaml"), InputError);
}

class OriginFileTest : public testing::ScratchDirTest {
 protected:
  OriginFileTest() : ScratchDirTest("dda-origin") {}
};

TEST_F(OriginFileTest, TheOriginTravelsThroughTheStageFiles) {
  LineModel lines;
  lines.domain = square(-8, -8, 10);
  lines.origin = Vec2(1e12 + 8, 1e12 + 8);
  write_lines_h5(path("l.h5"), lines);
  EXPECT_EQ(read_lines_h5(path("l.h5")).origin, lines.origin);
  BlockModel blocks;
  blocks.origin = Vec2(-3.5e9, 1e12);
  write_blocks_h5(path("b.h5"), blocks);
  EXPECT_EQ(read_blocks_h5(path("b.h5")).origin, blocks.origin);
  FractureModel fractures;
  fractures.domain = {Vec3(-2, -2, -2), Vec3(2, 2, 2)};
  fractures.origin = Vec3(1e9 + 2, 0, -1e9);
  write_fractures_h5(path("f.h5"), fractures);
  EXPECT_EQ(read_fractures_h5(path("f.h5")).origin, fractures.origin);
  PolyhedronModel poly;
  poly.origin = Vec3(1, 2, 3);
  write_polyhedra_h5(path("p.h5"), poly);
  EXPECT_EQ(read_polyhedra_h5(path("p.h5")).origin, poly.origin);
  // A file without the attributes (written before, or near the origin) means 0.
  write_lines_h5(path("near.h5"), LineModel{});
  EXPECT_EQ(read_lines_h5(path("near.h5")).origin, Vec2(0, 0));
}

}  // namespace
}  // namespace dda
