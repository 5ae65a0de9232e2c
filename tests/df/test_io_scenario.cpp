// The DF sections of a scenario into a ModelInput (df/io/scenario.hpp).
#include <gtest/gtest.h>

#include "dda/common/error.hpp"
#include "dda/df/io/scenario.hpp"
#include "df_test_models.hpp"

namespace dda::df {
namespace {

// Two beds of two blocks each (4 x 2 m box), joint sets "bed" (0) and
// "cross" (1); points: a fixed, a load and a measurement point.
BlockModel two_beds() {
  BlockModel m;
  m.sets = {{"bed", "layered"}, {"cross", "layered"}};
  m.layers = {Layer{0, 1, 0, 0}, Layer{1, 2, 0, 0}};
  for (int layer = 0; layer < 2; ++layer)
    for (int col = 0; col < 2; ++col) {
      Block b = test::make_block(test::rectangle(2.0 * col, layer, 2, 1));
      // bottom, right, top, left edges
      b.edge_set = {layer == 0 ? kBoundarySet : 0, col == 0 ? 1 : kBoundarySet, layer == 1 ? kBoundarySet : 0,
                    col == 1 ? 1 : kBoundarySet};
      b.layer = layer;
      m.blocks.push_back(b);
    }
  m.points = {{{"anchor", PointKind::Fixed, {1, 0.5}}, 0},
              {{"push", PointKind::Load, {3, 1.5}}, 3},
              {{"crown", PointKind::Measurement, {1, 1.5}}, 2}};
  return m;
}

const char* kScenario = R"(name: t
materials:
  default: {density: 2500, young: 2.0e10, poisson: 0.2}
  zones:
    - {layers: [1, 1], young: 1.0e10}
joints:
  default: {friction_deg: 35, cohesion: 1000}
  cross: {friction_deg: 25}
loading:
  gravity: 9.8
  point_loads:
    - {point: push, history: [[0, 0, 0], [1, 100, -50]]}
fixed:
  boundary: [bottom]
  points:
    - {point: anchor, penalty: 1.0e12, displacement: [[0, 0, 0], [2, 0.01, 0]]}
control: {dt: 0.002, total_time: 1.5, max_displacement_ratio: 0.005, dynamic: 0.5, solver: cholmod,
          output_interval: 0.1, initial_equilibrium: true}
)";

DfScenario read(const std::string& text) {
  const YamlNode root = YamlNode::load_string(text, "s.yaml");
  return read_df_scenario(root, two_beds(), "b.h5");
}

std::string error_of(const std::string& text) {
  try {
    read(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(IoScenario, ReadsEveryKey) {
  const DfScenario s = read(kScenario);
  const ModelInput& in = s.input;
  ASSERT_EQ(in.materials.size(), 2u);
  EXPECT_EQ(in.materials[0].density, 2500);
  EXPECT_EQ(in.materials[0].young, 2e10);
  EXPECT_EQ(in.materials[0].plane, PlaneMode::Strain);  // the default
  EXPECT_EQ(in.materials[1].young, 1e10);
  EXPECT_EQ(in.materials[1].density, 2500);  // a zone inherits what it does not give
  EXPECT_EQ(in.block_material, (std::vector<int>{0, 0, 1, 1}));

  ASSERT_EQ(in.joint_sets.size(), 2u);
  EXPECT_EQ(in.joint_sets[0].friction_deg, 35);  // "bed" not named: the default
  EXPECT_EQ(in.joint_sets[1].friction_deg, 25);
  EXPECT_EQ(in.joint_sets[1].cohesion, 1000);    // inherited from the default
  EXPECT_EQ(in.default_joint.friction_deg, 35);

  EXPECT_EQ(in.gravity, Vec2(0, -9.8));
  ASSERT_EQ(in.loads.size(), 1u);
  ASSERT_TRUE(in.loads[0].history.has_value());
  EXPECT_EQ(in.loads[0].history->value[1], Vec2(100, -50));

  // The named fixed point, then both ends of the bottom edge of blocks 0 and 1.
  ASSERT_EQ(in.fixed_points.size(), 5u);
  EXPECT_EQ(in.fixed_points[0].name, "anchor");
  EXPECT_EQ(*in.fixed_points[0].penalty, 1e12);
  ASSERT_TRUE(in.fixed_points[0].history.has_value());
  EXPECT_EQ(in.fixed_points[0].history->t.back(), 2);
  for (std::size_t k = 1; k < 5; ++k) EXPECT_EQ(in.fixed_points[k].position.y(), 0);

  ASSERT_EQ(in.measurements.size(), 1u);
  EXPECT_EQ(in.measurements[0].name, "crown");

  const Control& c = in.control;
  EXPECT_EQ(c.dt, 0.002);
  EXPECT_EQ(c.total_time, 1.5);
  EXPECT_EQ(c.steps, 0);
  EXPECT_EQ(c.max_displacement_ratio, 0.005);
  EXPECT_EQ(c.dynamic, 0.5);
  EXPECT_EQ(c.solver, "cholmod");
  EXPECT_TRUE(c.initial_equilibrium);
  EXPECT_EQ(c.penalty_factor, 50);  // defaults left alone
  EXPECT_EQ(s.output.interval, 0.1);
  EXPECT_NO_THROW(build_model(in));
}

TEST(IoScenario, DefaultsWithOnlyControl) {
  const DfScenario s = read("control: {dt: 0.01, steps: 40}\nloading: {point_loads: [{point: push, force: [1, 2]}]}\n");
  EXPECT_EQ(s.input.control.steps, 40);
  EXPECT_EQ(s.input.materials.size(), 1u);
  EXPECT_EQ(s.input.gravity, Vec2(0, -9.81));
  EXPECT_EQ(s.input.loads[0].force, Vec2(1, 2));
  const OutputSchedule o = resolve_output_schedule(s.output, s.input.control);
  EXPECT_EQ(o.every, 2);
  EXPECT_EQ(o.interval, 0);
}

TEST(IoScenario, ErrorsNameFileLineAndKey) {
  const std::string base = "control: {dt: 0.01, steps: 4}\nloading: {point_loads: [{point: push, force: [1, 2]}]}\n";
  EXPECT_EQ(error_of(base + "materials: {default: {density: 0}}\n"),
            "s.yaml:3: materials.default.density must be > 0, got 0.");
  EXPECT_EQ(error_of("control: {dt: 0, steps: 4}\n"), "s.yaml:1: control.dt must be > 0, got 0.");
  EXPECT_EQ(error_of(base + "joints:\n  nope: {friction_deg: 3}\n"),
            "s.yaml:4: joints.nope names a joint set that b.h5 does not have (its sets are bed, cross).");
  EXPECT_NE(error_of(base + "joints:\n  cross: {}\n").find("s.yaml:4: joints.cross gives no joint properties"),
            std::string::npos);
  EXPECT_NE(error_of("control: {dt: 0.01, steps: 4}\n").find("load point 'push'"), std::string::npos);
  EXPECT_NE(error_of(base + "fixed: {points: [{point: crown}]}\n").find("which is not a fixed point"),
            std::string::npos);
  EXPECT_NE(error_of(base + "materials: {zones: [{polygon: [[10, 10], [11, 10], [11, 11]], young: 1e9}]}\n")
                .find("selects no block"),
            std::string::npos);
  EXPECT_NE(error_of(base + "bolts: [{from: [1, 0.5], to: [1.5, 0.6], stiffness: 1e6}]\n")
                .find("bolts[0].to lies in the same block as `from`"),
            std::string::npos);
  EXPECT_NE(error_of("control: {dt: 0.01}\n").find("control must have exactly one of"), std::string::npos);
  EXPECT_NE(error_of("control: {dt: 0.01, steps: 4}\nloading: {point_loads: [{point: push, history: [[1, 0, 0], "
                     "[0.5, 1, 1]]}]}\n")
                .find("must come later than the row before it"),
            std::string::npos);
}

TEST(IoScenario, CheckWithoutBlocksAndBlocksChecks) {
  EXPECT_NO_THROW(check_df_scenario(YamlNode::load_string("name: x\n", "s.yaml")));
  EXPECT_THROW(check_df_scenario(YamlNode::load_string("materials: {default: {young: 1e9}}\n", "s.yaml")),
               InputError);
  EXPECT_THROW(check_df_scenario(YamlNode::load_string("control: {dt: 0.1, steps: 1, w0: -1}\n", "s.yaml")),
               InputError);
  BlockModel empty;
  try {
    check_blocks_for_df(empty, "e.h5");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("e.h5: has no blocks", 0), 0u);
  }
  BlockModel m = two_beds();
  m.points[2].block = -1;
  const YamlNode root = YamlNode::load_string("points:\n  - {name: crown, kind: measurement, at: [9, 9]}\n", "s.yaml");
  try {
    check_blocks_for_df(m, "b.h5", root);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "s.yaml:2: points[0].at (measurement point 'crown') lies outside every block.");
  }
}

}  // namespace
}  // namespace dda::df
