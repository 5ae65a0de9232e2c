// The scenario's `water` section and `joints.*.saturation`, 2D and 3D
// (df/src/io/scenario_water.cpp): read into the models, and every mistake
// refused with one sentence naming the file, the line and the key.
#include <gtest/gtest.h>

#include <string>

#include "../common/input_error_of.hpp"
#include "dda/df/io/scenario.hpp"
#include "dda/df/io/scenario3d.hpp"
#include "df_io_test_models3d.hpp"
#include "df_test_models.hpp"

namespace dda::df {
namespace {

using dda::testing::input_error_of;

const std::string kControl = "control: {dt: 0.01, steps: 2}\n";

DfScenario read2(const std::string& text) {
  return read_df_scenario(YamlNode::load_string(kControl + text, "w.yaml"), test::two_blocks(), "b.h5");
}
df3::DfScenario3 read3(const std::string& text) {
  return df3::read_df3_scenario(YamlNode::load_string("dimension: 3\n" + kControl + text, "w3.yaml"),
                                df3::testing::incline_blocks(), "b3.h5");
}

TEST(IoWater, ReadsLevelSurfaceUnitWeightAndSaturation) {
  const DfScenario a = read2("water: {level: 3.5}\njoints: {J: {saturation: 0.25}}\n");
  ASSERT_TRUE(a.input.water);
  EXPECT_EQ(a.input.water->level, 3.5);
  EXPECT_EQ(a.input.water->unit_weight, 9810);  // the default, rho_w g
  EXPECT_EQ(a.input.joint_sets[0].saturation, 0.25);
  EXPECT_EQ(a.input.default_joint.saturation, 1.0);
  const DfScenario b = read2("water: {surface: [[0, 1], [2, 3]], unit_weight: 10000}\n");
  ASSERT_EQ(b.input.water->knots.size(), 2u);
  EXPECT_EQ(b.input.water->head(Eigen::Vector2d(1, 0)), 2.0);
  EXPECT_FALSE(read2("").input.water);
  const df3::DfScenario3 c = read3("water: {surface: [[0, 0, 1], [1, 0, 1], [0, 1, 2]]}\n");
  ASSERT_TRUE(c.model.water);
  EXPECT_DOUBLE_EQ(c.model.water->head(Eigen::Vector3d(0.5, 0.5, 0)), 1.5);
}

TEST(IoWater, MistakesNameFileLineAndKey) {
  EXPECT_EQ(input_error_of([] { read2("water: [1, 2]\n"); }),
            "w.yaml:2: water must be a mapping such as {level: 12, unit_weight: 9810}.");
  EXPECT_EQ(input_error_of([] { read2("water: {level: 3, unit_weight: -9810}\n"); }),
            "w.yaml:2: water.unit_weight must be > 0, got -9810.");
  EXPECT_EQ(input_error_of([] { read2("water: {level: 3}\njoints: {J: {saturation: 1.5}}\n"); }),
            "w.yaml:3: joints.J.saturation must be in [0, 1], got 1.5.");
  EXPECT_NE(input_error_of([] { read2("water: {level: high}\n"); }).find("w.yaml:2: water.level"),
            std::string::npos);
  EXPECT_NE(input_error_of([] { read2("water: {unit_weight: 9810}\n"); }).find("w.yaml:2: water must have exactly one of"),
            std::string::npos);
  EXPECT_NE(input_error_of([] { read2("water: {level: 1, depth: 2}\n"); }).find("water.depth"), std::string::npos);
  EXPECT_NE(input_error_of([] { read2("water: {surface: [[0, 1], [0, 2]]}\n"); }).find("x must increase"),
            std::string::npos);
  EXPECT_NE(input_error_of([] { read3("water: {surface: [[0, 0, 1], [1, 1, 1], [2, 2, 5]]}\n"); })
                .find("w3.yaml:3: water.surface holds three points in one vertical plane"),
            std::string::npos);
}

}  // namespace
}  // namespace dda::df
