// The forward run's own positions in a scenario (water table, bolts' ends,
// zones, points placed on a block, 3D `below` levels and boxes) are given
// in the user's coordinates and read about the blocks' local origin
// (coordinate_range.hpp): a far model's scenario read with its blocks must
// give exactly the model the same scenario written in local coordinates
// gives with the same blocks at origin 0.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "dda/df/io/scenario.hpp"
#include "dda/df/io/scenario3d.hpp"
#include "df_io_test_models3d.hpp"
#include "df_test_models.hpp"

namespace dda::df {
namespace {

const std::string kControl = "control: {dt: 0.01, steps: 2}\n";

// "[x, y(, z)]" to 17 digits: a double written so that it reads back the same.
template <class Point>
std::string yaml_point(const Point& p) {
  std::string out = "[";
  for (int k = 0; k < p.size(); ++k) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", p[k]);
    out += (k ? ", " : "") + std::string(buf);
  }
  return out + "]";
}

TEST(LocalOriginScenario, TwoDimensionsReadAboutTheBlocksOrigin) {
  // 1e12 and 5e11 plus the halves and quarters below are exact in doubles
  // (their spacing there is 2^-13 and 2^-14), so the far scenario says
  // exactly what the near one says.
  const Vec2 origin(1e12, 5e11);
  auto text = [](const Vec2& s) {
    auto at = [&](double x, double y) { return yaml_point(Vec2(Vec2(x, y) + s)); };
    char level[40];
    std::snprintf(level, sizeof level, "%.17g", 0.5 + s.y());
    return kControl + "water: {level: " + level + "}\n" +
           "bolts: [{from: " + at(0.5, 0.5) + ", to: " + at(1.5, 0.5) + ", stiffness: 1e6}]\n" +
           "materials: {zones: [{polygon: [" + at(1, 0) + ", " + at(2, 0) + ", " + at(2, 1) + ", " + at(1, 1) +
           "], young: 1e10}]}\n" + "points: [{name: m, block: {containing: " + at(1.5, 0.5) + "}, at: " +
           at(1.25, 0.75) + "}]\n";
  };
  const DfScenario far =
      read_df_scenario(YamlNode::load_string(text(origin), "far.yaml"), test::two_blocks(origin), "b.h5");
  const DfScenario near =
      read_df_scenario(YamlNode::load_string(text(Vec2(0, 0)), "near.yaml"), test::two_blocks(Vec2(0, 0)), "b.h5");
  ASSERT_TRUE(far.input.water && near.input.water);
  EXPECT_EQ(far.input.water->level, 0.5);
  EXPECT_EQ(far.input.water->level, near.input.water->level);
  ASSERT_EQ(far.input.bolts.size(), 1u);
  EXPECT_EQ(far.input.bolts[0].anchor, Vec2(0.5, 0.5));
  EXPECT_EQ(far.input.bolts[0].head, near.input.bolts[0].head);
  EXPECT_EQ(far.input.block_material, (std::vector<int>{0, 1}));  // the zone holds block 1
  EXPECT_EQ(far.input.block_material, near.input.block_material);
  ASSERT_EQ(far.input.measurements.size(), 1u);
  EXPECT_EQ(far.input.measurements[0].block, 1);
  EXPECT_EQ(far.input.measurements[0].position, Vec2(1.25, 0.75));
  // The model carries the origin on to the results writers.
  EXPECT_EQ(build_model(far.input).origin, origin);
  // A water surface's knots move on both axes.
  const std::string surface = kControl + "water: {surface: [" + yaml_point(Vec2(Vec2(0, 1) + origin)) + ", " +
                              yaml_point(Vec2(Vec2(2, 3) + origin)) + "]}\n";
  const DfScenario w = read_df_scenario(YamlNode::load_string(surface, "w.yaml"), test::two_blocks(origin), "b.h5");
  EXPECT_EQ(w.input.water->head(Vec2(1, 0)), 2.0);
}

TEST(LocalOriginScenario, ThreeDimensionsReadAboutTheBlocksOrigin) {
  // The 3D incline blocks (a cube on a base whose top dips 20 deg east)
  // about the origin (3e9, -2e9, 1e9); positions in the cube and the base
  // are written as fl(p + origin) in the far scenario and as
  // fl(p + origin) - origin (exact: Sterbenz) in the near one, so both
  // name the same doubles about the blocks.
  const Vec3 origin(3e9, -2e9, 1e9);
  const Eigen::Matrix3d r = df3::testing::plane_rotation(20, 90);
  // "[x0, y0, z0, x1, y1, z1]"
  auto box = [](const Vec3& lo, const Vec3& hi) {
    return yaml_point(lo).substr(0, yaml_point(lo).size() - 1) + ", " + yaml_point(hi).substr(1);
  };
  const Vec3 in_base = r * Vec3(2, 0, -0.5), in_cube = r * Vec3(0, 0, 0.5);
  auto text = [&](const Vec3& s) {
    auto at = [&](const Vec3& p) { return yaml_point(Vec3(Vec3(p + origin) - origin + s)); };
    char below[40], level[40];
    std::snprintf(below, sizeof below, "%.17g", 0.0 + s.z());
    std::snprintf(level, sizeof level, "%.17g", 0.25 + s.z());
    return "dimension: 3\n" + kControl + "fixed: {below: " + below + "}\n" + "water: {level: " + level + "}\n" +
           "bolts: [{from: " + at(in_base) + ", to: " + at(in_cube) + ", stiffness: 1e6}]\n" +
           "materials: {default: {young: 2e10}, zones: [{box: " +
           box(Vec3(Vec3(-1, -1, 0) + s), Vec3(Vec3(1, 1, 2) + s)) + ", young: 1e10}]}\n" +
           "points: [{name: m, block: {containing: " + at(in_cube) + "}}]\n";
  };
  PolyhedronModel far_blocks = df3::testing::incline_blocks();
  far_blocks.origin = origin;
  const df3::DfScenario3 far =
      df3::read_df3_scenario(YamlNode::load_string(text(origin), "far.yaml"), far_blocks, "b3.h5");
  const df3::DfScenario3 near = df3::read_df3_scenario(YamlNode::load_string(text(Vec3(0, 0, 0)), "near.yaml"),
                                                       df3::testing::incline_blocks(), "b3.h5");
  EXPECT_EQ(far.model.origin, origin);
  EXPECT_EQ(far.model.fixed, (std::vector<bool>{true, false}));  // the base's centroid lies below 0, the cube's above
  EXPECT_EQ(far.model.fixed, near.model.fixed);
  ASSERT_TRUE(far.model.water && near.model.water);
  EXPECT_EQ(far.model.water->level, 0.25);
  ASSERT_EQ(far.model.bolts.size(), 1u);
  EXPECT_EQ(far.model.bolts[0].anchor, near.model.bolts[0].anchor);
  EXPECT_EQ(far.model.bolts[0].head, near.model.bolts[0].head);
  EXPECT_EQ(far.model.block_material, (std::vector<int>{0, 1}));  // the box holds the cube's centroid
  EXPECT_EQ(far.model.block_material, near.model.block_material);
  ASSERT_EQ(far.model.measurements.size(), 1u);
  EXPECT_EQ(far.model.measurements[0].block, 1);
  EXPECT_EQ(far.model.measurements[0].position, near.model.measurements[0].position);
}

}  // namespace
}  // namespace dda::df
