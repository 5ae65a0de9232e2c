// How far from the origin a model may lie (coordinate_range.hpp): the
// limits, the sentence that names the source and the shift, and areas that
// do not depend on where a polygon lies.
#include <gtest/gtest.h>

#include <string>

#include "dda/common/coordinate_range.hpp"
#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"

namespace dda {
namespace {

Polygon2 square(double x0, double y0, double side) {
  return {Vec2(x0, y0), Vec2(x0 + side, y0), Vec2(x0 + side, y0 + side), Vec2(x0, y0 + side)};
}

std::string refusal(const std::vector<Vec2>& points) {
  try {
    check_coordinate_range(points, "far.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CoordinateRange, AreaOfASquareFarFromTheOrigin) {
  // 10 m square at x, y = 1e12: about the origin the cross products are
  // 1e24 and their rounding (1e8) swamps the 100 m^2; about its own corner
  // every product is exact.
  EXPECT_EQ(signed_area(square(1e12, 1e12, 10)), 100.0);
  EXPECT_EQ(signed_area(square(-3e9, 7e8, 0.5)), 0.25);
}

TEST(CoordinateRange, ModelsNearTheOriginOrInUtmPass) {
  EXPECT_EQ(refusal(square(0, 0, 10)), "");
  // A 1 m model at UTM northing 5.4e6 m: 5.4e6 < 1e7 x 1.41 m.
  EXPECT_EQ(refusal(square(4.5e5, 5.4e6, 1)), "");
  EXPECT_EQ(refusal({}), "");
}

TEST(CoordinateRange, AModelTooFarForItsSizeIsRefusedWithItsShift) {
  // 10 m at 5e8 m: 5e8 > 1e7 x 14.1 m. Doubles resolve 5e8 x 2.2e-16 =
  // 1.1e-7 m there; the shift is minus its centre, 5e8 + 5, to three
  // digits.
  EXPECT_EQ(refusal(square(5e8, 5e8, 10)),
            "far.yaml: lies up to 5e+08 m from the origin and is only 14.1 m across; doubles there resolve 1.1e-07 m, "
            "too coarse for its details; give its coordinates about a local origin near it (shift every point by "
            "(-5e+08, -5e+08)).");
  // The same square at 1e8 m passes: 1e8 < 1.41e8.
  EXPECT_EQ(refusal(square(1e8, 1e8, 10)), "");
}

TEST(CoordinateRange, CoordinatesBeyondAnyRockMassAreRefused) {
  // The 1e300 m domain whose area was infinite: refused before it is cut.
  const std::string why = refusal(square(0, 0, 1e300));
  EXPECT_EQ(why,
            "far.yaml: has coordinates up to 1e+300 m, beyond the 1e+09 m any model may reach (coordinates are "
            "metres); give them about a local origin near the model.");
  EXPECT_NE(refusal(square(1e12, 1e12, 10)), "");
  EXPECT_NE(refusal({Vec2(0, 0), Vec2(std::nan(""), 1)}), "");
}

TEST(CoordinateRange, ThreeDimensionsToo) {
  EXPECT_NO_THROW(check_coordinate_range(std::vector<Vec3>{Vec3(0, 0, 0), Vec3(10, 10, 10)}, "f.yaml"));
  EXPECT_THROW(check_coordinate_range(std::vector<Vec3>{Vec3(5e8, 0, 0), Vec3(5e8 + 1, 1, 1)}, "f.yaml"),
               InputError);
}

}  // namespace
}  // namespace dda
