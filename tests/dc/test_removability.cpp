// Block theory modes (Goodman & Shi 1985) for hand-made sets of face normals.
// Normals are outward from the body, towards the neighbouring rock.
#include <gtest/gtest.h>

#include <cmath>

#include "dda/dc/removability.hpp"
#include "dda/dl/dfn3d.hpp"

namespace dda::dc {
namespace {

const Vec3 kDown(0, 0, -1);

TEST(Removability, BodyWithoutFreeFaceIsNotExposed) {
  EXPECT_EQ(classify_removability({Vec3::UnitZ()}, false, kDown).mode, Removability::NotExposed);
}

TEST(Removability, RoofBlockHangingFromUpwardFacingFacesFalls) {
  // A tetrahedral key block in a tunnel roof: its three joint faces lie
  // above it, their outward normals all point upwards.
  const std::vector<Vec3> n = {Vec3(0.6, 0, 0.8), Vec3(-0.3, 0.5, 0.81).normalized(), Vec3(-0.3, -0.5, 0.81).normalized()};
  const auto r = classify_removability(n, true, kDown);
  EXPECT_EQ(r.mode, Removability::Falls);
  EXPECT_NEAR(r.direction.dot(kDown), 1.0, 1e-12);
}

TEST(Removability, BlockOnOneDippingPlaneSlidesDownDip) {
  // Plane dipping 30 degrees towards east (dip direction 90): the block above
  // it presses on it with outward normal -(sin 30, 0, cos 30); it slides
  // down the dip, direction (cos 30, 0, -sin 30).
  const std::vector<Vec3> n = {-dl::normal_from_dip(30, 90)};
  const auto r = classify_removability(n, true, kDown);
  EXPECT_EQ(r.mode, Removability::SlidesOne);
  EXPECT_NEAR(r.direction.x(), std::cos(kPi / 6), 1e-12);
  EXPECT_NEAR(r.direction.y(), 0, 1e-12);
  EXPECT_NEAR(r.direction.z(), -0.5, 1e-12);
}

TEST(Removability, SeedWedgeSlidesAlongTheLineOfIntersection) {
  // Validation case V4 (docs/validation.md): planes 51.4/065.8 and
  // 51.4/295.2 meet along trend 000.5 deg, plunge 27.63 deg; the wedge on
  // both slides along that line.
  const std::vector<Vec3> n = {-dl::normal_from_dip(51.4, 65.8), -dl::normal_from_dip(51.4, 295.2)};
  const auto r = classify_removability(n, true, kDown);
  ASSERT_EQ(r.mode, Removability::SlidesTwo);
  const double plunge = rad2deg(std::asin(-r.direction.z()));
  const double trend = rad2deg(std::atan2(r.direction.x(), r.direction.y()));
  EXPECT_NEAR(plunge, 27.63, 0.01);
  EXPECT_NEAR(trend, 0.5, 0.05);
}

TEST(Removability, BlockHeldOnlyByGravityIsRemovableUpwards) {
  // Four vertical walls and a floor: only lifting frees it.
  const std::vector<Vec3> n = {Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitY(), -Vec3::UnitZ()};
  EXPECT_EQ(classify_removability(n, true, kDown).mode, Removability::Removable);
}

TEST(Removability, BlockLockedOnAllSidesIsTapered) {
  const std::vector<Vec3> n = {Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitY(), -Vec3::UnitZ(),
                               Vec3::UnitZ()};
  EXPECT_EQ(classify_removability(n, true, kDown).mode, Removability::Tapered);
  // A wedge that widens into the rock (normals pointing outwards and down
  // on both sides of a vertical slot, and a floor) cannot leave.
  const std::vector<Vec3> w = {Vec3(0.8, 0, -0.6), Vec3(-0.8, 0, -0.6), Vec3(0, 1, 0), Vec3(0, -1, 0)};
  EXPECT_EQ(classify_removability(w, true, kDown).mode, Removability::Removable);  // it can go up
  std::vector<Vec3> locked = w;
  locked.push_back(Vec3::UnitZ());
  EXPECT_EQ(classify_removability(locked, true, kDown).mode, Removability::Tapered);
}

TEST(Removability, SlabBetweenTwoParallelFacesSlidesAlongThem) {
  // Faces on both sides of a vertical slab: motion in the slab's plane
  // is free, and gravity moves it straight down.
  const std::vector<Vec3> n = {Vec3::UnitX(), -Vec3::UnitX()};
  const auto r = classify_removability(n, true, kDown);
  EXPECT_EQ(r.mode, Removability::Falls);
}

}  // namespace
}  // namespace dda::dc
