// 3D block statistics on cuts whose answer is known exactly.
#include <gtest/gtest.h>

#include "dc3d_test_util.hpp"
#include "dda/dc/cut3d.hpp"
#include "dda/dc/stats3d.hpp"

namespace dda::dc {
namespace {

using namespace test3;

TEST(Stats3d, BricksHaveTheirVolumeDiameterAndAspect) {
  // 2 x 1.5 x 1 bricks: volume 3, equivalent diameter (18/pi)^(1/3), aspect
  // (longest / shortest side) 2.
  FractureModel m = empty_model(Vec3(0, 0, 0), Vec3(10, 6, 4), 3);
  for (int i = 1; i < 5; ++i) m.fractures.push_back(plane(Vec3::UnitX(), Vec3(2.0 * i, 0, 0), 0));
  for (int i = 1; i < 4; ++i) m.fractures.push_back(plane(Vec3::UnitY(), Vec3(0, 1.5 * i, 0), 1));
  for (int i = 1; i < 4; ++i) m.fractures.push_back(plane(Vec3::UnitZ(), Vec3(0, 0, 1.0 * i), 2));
  const auto st = block_statistics_3d(cut_blocks_3d(m).model, 10);
  EXPECT_EQ(st["bodies"], 80);
  EXPECT_NEAR(st["total_volume"].get<double>(), 240, 1e-9);
  EXPECT_NEAR(st["volume"]["mean"].get<double>(), 3, 1e-12);
  EXPECT_NEAR(st["volume"]["std"].get<double>(), 0, 1e-9);
  EXPECT_NEAR(st["equivalent_diameter"]["median"].get<double>(), std::cbrt(18 / kPi), 1e-12);
  EXPECT_NEAR(st["aspect"]["max"].get<double>(), 2, 1e-9);
  EXPECT_NEAR(st["faces"]["mean"].get<double>(), 6, 1e-12);
  // With the ground surface free, the 20 top bricks are exposed and can
  // only be lifted: removable, held by gravity.
  EXPECT_EQ(st["removability"]["removable"], 20);
  EXPECT_EQ(st["removability"]["not_exposed"], 60);
}

TEST(Stats3d, GluedRingCountsAsOneBody) {
  FractureModel m = empty_model(Vec3(0, 0, 0), Vec3(4, 4, 4), 1);
  Excavation3 e;
  e.region.half_spaces = {{-Vec3::UnitX(), -1}, {Vec3::UnitX(), 3}, {-Vec3::UnitZ(), -1}, {Vec3::UnitZ(), 3}};
  m.excavations.push_back(e);
  const auto st = block_statistics_3d(cut_blocks_3d(m).model);
  EXPECT_EQ(st["bodies"], 1);
  EXPECT_GT(st["blocks"].get<int>(), 1);
  EXPECT_NEAR(st["volume"]["max"].get<double>(), 48, 1e-12);
  EXPECT_NEAR(st["excavated_volume"].get<double>(), 16, 1e-12);
}

}  // namespace
}  // namespace dda::dc
