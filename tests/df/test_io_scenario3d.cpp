// The forward-run sections of a 3D scenario (df/scenario3d.hpp): what they
// build, and one sentence naming the file, line and key for each mistake.
#include <gtest/gtest.h>

#include <cmath>

#include "dda/common/error.hpp"
#include "dda/df/scenario3d.hpp"
#include "df3_io_test_models.hpp"

namespace dda::df3 {
namespace {

const char* kScenario = R"(dimension: 3
materials:
  default: {density: 2500, young: 2.0e10, poisson: 0.2}
joints:
  default: {friction_deg: 35}
  slide: {friction_deg: 12}
loading:
  gravity: 9.8
  point_loads:
    - {point: push, force: [0, 100, 0]}
fixed: {below: -0.2}
control: {dt: 0.002, total_time: 0.5, contact_reach: 0.02}
)";

// The cube's centre and a point on its top (rotated with the plane).
std::vector<ModelPoint3> points() {
  const Eigen::Matrix3d r = testing::plane_rotation(20, 90);
  return {{"top", PointKind::Measurement, r * Vec3(0, 0, 0.9)},
          {"push", PointKind::Load, r * Vec3(0, 0, 0.5)},
          {"ground", PointKind::Measurement, r * Vec3(2, 2, -0.5)}};
}

DfScenario3 read(const std::string& text, const PolyhedronModel& blocks = testing::incline_blocks(points())) {
  return read_df3_scenario(YamlNode::load_string(text, "s.yaml"), blocks, "b3.h5");
}

std::string error_of(const std::string& text, const PolyhedronModel& blocks = testing::incline_blocks(points())) {
  try {
    read(text, blocks);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

TEST(Scenario3d, BuildsTheModel) {
  const DfScenario3 s = read(kScenario);
  const Model3& m = s.model;
  EXPECT_EQ(m.material.density, 2500);
  EXPECT_EQ(m.material.young, 2e10);
  EXPECT_EQ(m.fixed, (std::vector<bool>{true, false}));  // the base's centroid lies below z = -0.2
  ASSERT_EQ(m.joint_sets.size(), 1u);
  EXPECT_EQ(m.joint_sets[0].friction_deg, 12);
  EXPECT_EQ(m.default_joint.friction_deg, 35);
  EXPECT_EQ(m.gravity, Vec3(0, 0, -9.8));
  ASSERT_EQ(m.measurements.size(), 2u);
  EXPECT_EQ(m.measurements[0].name, "top");
  EXPECT_EQ(m.measurements[0].block, 1);
  EXPECT_EQ(m.measurements[1].block, 0);
  ASSERT_EQ(m.loads.size(), 1u);
  EXPECT_EQ(m.loads[0].block, 1);
  EXPECT_EQ(m.loads[0].force.at(0.3), Vec3(0, 100, 0));
  EXPECT_EQ(m.control.dt, 0.002);
  EXPECT_EQ(m.control.total_time, 0.5);
  EXPECT_EQ(m.contact_reach, 0.02);
  // Defaults: the normal spring E x (mean free volume)^(1/3), the shear one the same.
  EXPECT_DOUBLE_EQ(m.normal_penalty, 2e10 * std::cbrt(1.0));
  EXPECT_EQ(m.shear_penalty, m.normal_penalty);
  EXPECT_EQ(resolve_output_schedule(s.output, m.control).interval, 0.5 / 20);
}

TEST(Scenario3d, FixedBlocksByIdBodyAndBox) {
  EXPECT_EQ(read(replaced(kScenario, "fixed: {below: -0.2}", "fixed: {blocks: [0]}")).model.fixed,
            (std::vector<bool>{true, false}));
  EXPECT_EQ(read(replaced(kScenario, "fixed: {below: -0.2}", "fixed: {outside: [-2, -2, -0.2, 2, 2, 2]}")).model.fixed,
            (std::vector<bool>{true, false}));
  EXPECT_EQ(read(replaced(kScenario, "fixed: {below: -0.2}", "fixed: {box: [-9, -9, -9, 9, 9, -0.2]}")).model.fixed,
            (std::vector<bool>{true, false}));
}

TEST(Scenario3d, EveryMistakeIsOneSentence) {
  struct Case {
    std::string text, message;
  };
  const std::vector<Case> cases{
      {replaced(kScenario, "dt: 0.002", "dt: 0"), "s.yaml:12: control.dt must be > 0, got 0."},
      {replaced(kScenario, "fixed: {below: -0.2}", "fixed: {belo: -0.5}"),
       "s.yaml:11: unknown key 'fixed.belo' (did you mean 'below'?)"},
      {replaced(kScenario, "materials:\n  default: {density: 2500, young: 2.0e10, poisson: 0.2}\n", "materials: {}\n"),
       "s.yaml:2: required key 'materials.default' is missing."},
      {replaced(kScenario, "young: 2.0e10", "young: -1"), "s.yaml:3: materials.default.young must be > 0, got -1."},
      {replaced(kScenario, "slide: {friction_deg: 12}", "J7: {friction_deg: 12}"),
       "s.yaml:6: joints.J7 names a joint set that b3.h5 does not have (its sets are slide)."},
      {replaced(kScenario, "slide: {friction_deg: 12}", "slide: {friction_deg: 12, cohesion: 1e4}"),
       "s.yaml:6: joints.slide.cohesion is not modelled by the 3D solver yet"},
      {replaced(kScenario, "fixed: {below: -0.2}", "fixed: {blocks: [7]}"),
       "s.yaml:11: fixed.blocks[0] is block 7, but b3.h5 has 2 blocks (ids 0 to 1)."},
      {replaced(kScenario, "fixed: {below: -0.2}", "fixed: {below: 9}"),
       "s.yaml:11: fixed fixes every block of b3.h5, so nothing can move."},
      {replaced(kScenario, "gravity: 9.8", "gravity: [0, -9.8]"),
       "s.yaml:8: loading.gravity must be [x, y, z] (three numbers), got 2."},
      {replaced(kScenario, "{point: push, force: [0, 100, 0]}", "{point: pull, force: [0, 100, 0]}"),
       "s.yaml:10: loading.point_loads[0].point names 'pull', which is not a load point of b3.h5 (its load points are "
       "push)."},
      {replaced(kScenario, "control: {dt: 0.002, total_time: 0.5, contact_reach: 0.02}", ""),
       "s.yaml:1: control is required for a forward run"},
  };
  for (const Case& c : cases) {
    const std::string e = error_of(c.text);
    EXPECT_EQ(e.rfind(c.message, 0), 0u) << "got: " << e << "\nexpected to start with: " << c.message;
  }
}

TEST(Scenario3d, PointOutsideEveryBlock) {
  std::vector<ModelPoint3> p = points();
  p.push_back({"air", PointKind::Measurement, Vec3(0, 0, 5)});
  EXPECT_EQ(error_of(kScenario, testing::incline_blocks(p)),
            "b3.h5: the measurement point 'air' at (0.000000, 0.000000, 5.000000) lies outside every block.");
  // Placed by the scenario's own points: its line.
  const std::string text = std::string(kScenario) + "points:\n  - {name: air, at: [0, 0, 5]}\n";
  EXPECT_EQ(error_of(text, testing::incline_blocks(p)),
            "s.yaml:14: points[0].at (measurement point 'air') lies outside every block.");
}

TEST(Scenario3d, EarthquakeInThreeComponents) {
  const std::string dir = ::testing::TempDir();
  {
    std::FILE* f = std::fopen((dir + "/eq3.csv").c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs("t,ax,ay,az\n0,0,0,0\n0.1,1,2,3\n0.2,0,0,0\n", f);
    std::fclose(f);
  }
  const std::string text =
      replaced(kScenario, "  point_loads:", "  earthquake: {record: eq3.csv, units: m/s2, mode: displacement}\n  point_loads:");
  const DfScenario3 s = read_df3_scenario(YamlNode::load_string(text, dir + "/s.yaml"),
                                          testing::incline_blocks(points()), "b3.h5");
  ASSERT_TRUE(s.model.earthquake.motion);
  EXPECT_EQ(s.model.earthquake.mode->name(), "displacement");
  // Displacement mode corrects the baseline (degree 3) by default, so only
  // the shape is checked: all three components act.
  const Vec3 a = s.model.earthquake.motion->acceleration(0.1);
  EXPECT_NE(a.x(), 0);
  EXPECT_NE(a.y(), 0);
  EXPECT_NE(a.z(), 0);
  const std::string bad = replaced(kScenario, "  point_loads:", "  earthquake: {record: eq3.csv, units: m/s2, mode: incident}\n  point_loads:");
  try {
    read_df3_scenario(YamlNode::load_string(bad, dir + "/s.yaml"), testing::incline_blocks(points()), "b3.h5");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("loading.earthquake.mode must be one of"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dda::df3
