// The forward-run sections of a 3D scenario (df/io/scenario3d.hpp): what they
// build, and one sentence naming the file, line and key for each mistake.
#include <gtest/gtest.h>

#include <cmath>

#include "dda/common/error.hpp"
#include "dda/df/io/scenario3d.hpp"
#include "df_io_test_models3d.hpp"

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
  EXPECT_EQ(m.material_of(1).density, 2500);
  EXPECT_EQ(m.material_of(1).young, 2e10);
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

// control.initial_equilibrium is read in 3D as in 2D (on unless given).
TEST(Scenario3d, ReadsInitialEquilibrium) {
  EXPECT_TRUE(read(kScenario).model.control.initial_equilibrium);
  const std::string on = replaced(kScenario, "contact_reach: 0.02}", "contact_reach: 0.02, initial_equilibrium: true}");
  EXPECT_TRUE(read(on).model.control.initial_equilibrium);
  const std::string off = replaced(kScenario, "contact_reach: 0.02}", "contact_reach: 0.02, initial_equilibrium: false}");
  EXPECT_FALSE(read(off).model.control.initial_equilibrium);
  const std::string bad = replaced(kScenario, "contact_reach: 0.02}", "contact_reach: 0.02, initial_equilibrium: 3}");
  EXPECT_EQ(error_of(bad).rfind("s.yaml:12: control.initial_equilibrium", 0), 0u) << error_of(bad);
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
      {replaced(kScenario, "slide: {friction_deg: 12}", "slide: {friction_deg: 12, tensile_strength: -1e4}"),
       "s.yaml:6: joints.slide.tensile_strength must be >= 0, got -10000."},
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
  EXPECT_EQ(s.model.earthquake.mode->name, "displacement");
  // Displacement mode corrects the baseline (degree 3) by default, so only
  // the shape is checked: all three components act.
  const Vec3 a = s.model.earthquake.motion->acceleration(0.1);
  EXPECT_NE(a.x(), 0);
  EXPECT_NE(a.y(), 0);
  EXPECT_NE(a.z(), 0);
  const std::string bad = replaced(kScenario, "  point_loads:", "  earthquake: {record: eq3.csv, units: m/s2, mode: shake}\n  point_loads:");
  try {
    read_df3_scenario(YamlNode::load_string(bad, dir + "/s.yaml"), testing::incline_blocks(points()), "b3.h5");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("loading.earthquake.mode must be one of"), std::string::npos) << e.what();
  }
}

// materials.zones and the initial state (docs/scenario.md, "The 3D forward
// run"). Block 0 is the fixed base, block 1 the free cube (volume 1 m^3).
const std::string kDefault = "  default: {density: 2500, young: 2.0e10, poisson: 0.2}\n";

std::string with_materials(const std::string& lines) { return replaced(kScenario, kDefault, lines); }

TEST(Scenario3d, ZonesAndInitialState) {
  const DfScenario3 s = read(with_materials(
      "  default: {density: 2500, young: 2.0e10, poisson: 0.2, initial_stress: [-1e5, -2e5, -3e5, 4e3, 5e3, 6e3],\n"
      "            initial_velocity: [0, 0, 0.1, 0, 0, 0]}\n"
      "  zones:\n"
      "    - {blocks: [1], density: 2000, young: 3.0e10, initial_velocity: [1, 2, 3, 0.1, 0.2, 0.3]}\n"));
  const Model3& m = s.model;
  EXPECT_EQ(m.block_material, (std::vector<int>{0, 1}));
  ASSERT_EQ(m.materials.size(), 2u);
  EXPECT_EQ(m.material_of(0).density, 2500);
  EXPECT_EQ(m.material_of(1).density, 2000);
  EXPECT_EQ(m.material_of(1).young, 3e10);
  EXPECT_EQ(m.material_of(1).poisson, 0.2);  // not given by the zone: the default's
  // [sx, sy, sz, txy, tyz, tzx] as given; Vector6d holds [sx sy sz tyz tzx txy].
  Vector6d stress;
  stress << -1e5, -2e5, -3e5, 5e3, 6e3, 4e3;
  ASSERT_EQ(m.initial_stress.size(), 2u);
  EXPECT_EQ(m.initial_stress[0], stress);  // a fixed block reports its stress too
  EXPECT_EQ(m.initial_stress[1], stress);  // the zone keeps the default's
  Vector12d velocity = Vector12d::Zero();
  velocity.head<6>() << 1, 2, 3, 0.1, 0.2, 0.3;
  ASSERT_EQ(m.initial_velocity.size(), 2u);
  EXPECT_EQ(m.initial_velocity[0], Vector12d::Zero());  // fixed: no unknowns, at rest
  EXPECT_EQ(m.initial_velocity[1], velocity);
  // The default normal spring takes the largest modulus of the free blocks.
  EXPECT_DOUBLE_EQ(m.normal_penalty, 3e10 * std::cbrt(1.0));
  Simulation3 sim(m);
  EXPECT_EQ(sim.velocities()[1], velocity);
  EXPECT_EQ(sim.stresses()[1], stress);
}

TEST(Scenario3d, FirstZoneThatHoldsABlockWins) {
  const Model3 m = read(with_materials(kDefault +
                                       "  zones:\n"
                                       "    - {blocks: [1], density: 2200}\n"
                                       "    - {box: [-9, -9, -9, 9, 9, 9], density: 2100, young: 9.0e10}\n"))
                       .model;
  EXPECT_EQ(m.block_material, (std::vector<int>{2, 1}));
  EXPECT_EQ(m.material_of(0).density, 2100);
  EXPECT_EQ(m.material_of(1).density, 2200);
  // The stiff zone holds only the fixed base, so the spring stays the cube's.
  EXPECT_DOUBLE_EQ(m.normal_penalty, 2e10);
  // Selections as in `fixed`: by level, body-free blocks by id, outside a box.
  EXPECT_EQ(read(with_materials(kDefault + "  zones: [{below: -0.2, density: 2100}]\n")).model.block_material,
            (std::vector<int>{1, 0}));
  EXPECT_EQ(read(with_materials(kDefault + "  zones: [{outside: [-2, -2, -0.2, 2, 2, 2], density: 2100}]\n"))
                .model.block_material,
            (std::vector<int>{1, 0}));
}

TEST(Scenario3d, MaterialMistakesAreOneSentence) {
  struct Case {
    std::string lines, message;
  };
  const std::string zones = kDefault + "  zones:\n";
  const std::vector<Case> cases{
      {zones + "    - {below: -50, density: 2100}\n", "s.yaml:5: materials.zones[0].below selects no block of b3.h5."},
      {zones + "    - {blocks: [1], density: 2100}\n    - {box: [-1, -1, 0, 1, 1, 1], density: 2200}\n",
       "s.yaml:6: materials.zones[1] holds no block: every block it selects is in an earlier zone"},
      {zones + "    - {blocks: [7], density: 2100}\n",
       "s.yaml:5: materials.zones[0].blocks[0] is block 7, but b3.h5 has 2 blocks (ids 0 to 1)."},
      {zones + "    - {density: 2100}\n",
       "s.yaml:5: materials.zones[0] must select its blocks with at least one of blocks, bodies, below, box or "
       "outside."},
      {zones + "    - {polygon: [[0, 0], [1, 0], [1, 1]], density: 2100}\n",
       "s.yaml:5: materials.zones[0].polygon is a 2D zone selection"},
      {zones + "    - {removability: [falls], density: 2100}\n",
       "s.yaml:5: unknown key 'materials.zones[0].removability'"},
      {zones + "    - {blocks: [1], plane: strain}\n", "s.yaml:5: materials.zones[0].plane is 2D only"},
      {"  default: {density: 2500, plane: stress}\n", "s.yaml:3: materials.default.plane is 2D only"},
      {"  default: {initial_stress: [1e5, 0, 0]}\n",
       "s.yaml:3: materials.default.initial_stress must be [sx, sy, sz, txy, tyz, tzx] (six numbers), got 3."},
      {"  default: {initial_velocity: [1, 0, 0]}\n",
       "s.yaml:3: materials.default.initial_velocity must be [vx, vy, vz, wx, wy, wz] (six numbers), got 3."},
      {zones + "    - {blocks: [1], initial_stress: [1, 2, 3, 4, 5, 6, 7]}\n",
       "s.yaml:5: materials.zones[0].initial_stress must be [sx, sy, sz, txy, tyz, tzx] (six numbers), got 7."},
      {"  zones: [{blocks: [1], density: 2100}]\n", "s.yaml:3: required key 'materials.default' is missing."},
  };
  for (const Case& c : cases) {
    const std::string e = error_of(with_materials(c.lines));
    EXPECT_EQ(e.rfind(c.message, 0), 0u) << "got: " << e << "\nexpected to start with: " << c.message;
  }
  // Mistakes that need no blocks fail before DL runs (dda run).
  EXPECT_THROW(check_df3_scenario(YamlNode::load_string(
                   with_materials("  default: {initial_velocity: [1, 0]}\n"), "s.yaml")),
               InputError);
}

}  // namespace
}  // namespace dda::df3
