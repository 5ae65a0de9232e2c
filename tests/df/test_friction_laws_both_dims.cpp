// Every registered friction law (friction_laws(), df/src/core/friction_registry.cpp),
// in both dimensions (Simulation and Simulation3):
//   - no frictional strength in tension: the law gives 0 for a pulled
//     contact, and a block pulled off its base moves as a free body;
//   - the law's per-contact state survives a checkpoint bit for bit;
//   - a run stopped half way, written, read and resumed ends bit for bit
//     where the uninterrupted run ends.
// The list of laws comes from the registry, so a new law is tested as soon
// as it is registered; it needs one line of example parameters below.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "dda/df/core/friction.hpp"
#include "dda/df/io/results.hpp"
#include "dda/df/io/results3d.hpp"
#include "df_io_test_models3d.hpp"
#include "df_io_test_models.hpp"
#include "df_test_models.hpp"

namespace dda::df {
namespace {

namespace fs = std::filesystem;

// Valid parameters of each law. rate_state is the example of
// docs/scenario.md ("Friction laws"); the others are within the ranges of
// the laws' specs and give mu <= tan 35 deg = 0.70 at every speed and slip of
// these runs, so a block slides on the 40-degree plane below (tan 40 = 0.84).
const std::map<std::string, JointProperties>& example_joints() {
  static const std::map<std::string, JointProperties> joints = [] {
    std::map<std::string, JointProperties> m;
    m["coulomb"] = test::friction_joint("coulomb", {});  // friction_deg 30 (its default)
    m["log_linear"] = test::friction_joint("log_linear", {{"mu_ref", 0.6}, {"s", -0.01}});
    m["rate_state"] =
        test::friction_joint("rate_state", {{"mu0", 0.6}, {"a", 0.01}, {"b", 0.015}, {"dc", 1e-4}, {"v0", 1e-6}},
                             {{"evolution", "aging"}});
    m["stribeck"] = test::friction_joint("stribeck", {{"mu_s", 0.6}, {"mu_k", 0.4}, {"v_s", 0.01}});
    m["slip_weakening"] = test::friction_joint("slip_weakening", {{"mu_s", 0.6}, {"mu_d", 0.4}, {"dc", 1e-3}});
    m["degradation"] =
        test::friction_joint("degradation", {{"phi_peak", 35}, {"phi_residual", 22}, {"dc", 1e-3}},
                             {{"measure", "slip"}});
    return m;
  }();
  return joints;
}

std::vector<std::string> registered_laws() {
  std::vector<std::string> names;
  for (const FrictionLawEntry& e : friction_laws()) names.push_back(e.name);
  return names;
}

TEST(FrictionLawRegistry, IsNotEmptyAndEveryLawHasExampleParameters) {
  ASSERT_FALSE(friction_laws().empty()) << "the friction law registry lists no law";
  for (const FrictionLawEntry& e : friction_laws()) {
    const auto it = example_joints().find(e.name);
    ASSERT_NE(it, example_joints().end())
        << "friction law '" << e.name << "' has no example parameters in example_joints() of this test";
    EXPECT_NO_THROW(make_friction_law(it->second)) << e.name;
  }
}

class EveryFrictionLaw : public ::testing::TestWithParam<std::string> {
 protected:
  const JointProperties& joint() const {
    const auto it = example_joints().find(GetParam());
    if (it == example_joints().end()) throw std::runtime_error("no example parameters for " + GetParam());
    return it->second;
  }
  fs::path temp(const std::string& what) const {
    return fs::temp_directory_path() / ("dda_every_law_" + GetParam() + "_" + what + ".h5");
  }
};

void expect_same_state(const FrictionState& a, const FrictionState& b, const std::string& where) {
  EXPECT_EQ(a.theta, b.theta) << where;
  EXPECT_EQ(a.slip, b.slip) << where;
  EXPECT_EQ(a.extra, b.extra) << where;
}

// ---- The law itself: a contact in tension (N < 0) has no frictional
// strength, whatever its speed and memory (and no cohesion: it is not bonded).
TEST_P(EveryFrictionLaw, GivesNoStrengthInTension) {
  const std::unique_ptr<FrictionLaw> law = make_friction_law(joint());
  FrictionState state;
  state.theta = 1e-4 / 1e-6;  // the steady state of rate_state at v0 (theta = dc / v0)
  for (const double v : {0.0, 1e-6, 1e-3, 1.0}) {
    FrictionInput in;
    in.normal_force = -1e5;
    in.slip_velocity = v;
    in.contact_length = 1;
    in.dt = 1e-3;
    in.slip_sign = v > 0 ? 1 : 0;
    EXPECT_EQ(law->strength(in, state), 0.0) << "V = " << v;
    law->advance(in, state);  // and after a step of sliding under tension
    EXPECT_EQ(law->strength(in, state), 0.0) << "V = " << v << " after advance";
  }
  // The same law does resist in compression (else the check above proves nothing).
  FrictionInput pressed;
  pressed.normal_force = 1e5;
  pressed.slip_velocity = 1e-3;
  pressed.dt = 1e-3;
  EXPECT_GT(law->strength(pressed, state), 0.0);
}

// ---- 2D models.

// A 1 x 1 m block (2000 kg/m^3: m = 2000 kg per m of thickness) on a fixed
// base, every joint of the law, pulled at its centroid by F = (m g / 2,
// 2 m g): the net force (m g / 2, m g) pulls it off the base and along it.
ModelInput pulled_block_2d(const JointProperties& j) {
  ModelInput in;
  in.geometry.blocks.push_back(test::make_block(test::rectangle(-2, -1, 5, 1), 0));
  in.geometry.blocks.push_back(test::make_block(test::rectangle(0, 0, 1, 1), 0));
  in.geometry.sets = {{"J", "user"}};
  in.materials = {test::rock(2000, 5e9)};
  in.joint_sets = {j};
  in.default_joint = j;
  for (const double x : {-1.5, 0.5, 2.5}) in.fixed_points.push_back({"base", Vec2(x, -0.5), 0, {}});
  const double mg = 2000 * 9.81;
  in.loads.push_back({"pull", Vec2(0.5, 0.5), Vec2(0.5 * mg, 2 * mg), 1, std::nullopt});
  in.measurements.push_back({"centroid", Vec2(0.5, 0.5), 1});
  in.control.dt = 1e-3;
  in.control.steps = 20;
  // A block pulled off its base has no equilibrium to settle into.
  in.control.initial_equilibrium = false;
  return in;
}

// A 1 x 1 m block on a fixed base dipping 40 degrees, all joints of the law:
// it slides (tan 40 = 0.84 > mu of every example law).
ModelInput sliding_block_2d(const JointProperties& j) {
  const double a = deg2rad(40);
  ModelInput in;
  in.geometry.blocks.push_back(test::make_block(test::rotated(test::rectangle(0, -1, 8, 1), a), 0));
  in.geometry.blocks.push_back(test::make_block(test::rotated(test::rectangle(3, 0, 1, 1), a), 0));
  in.geometry.sets = {{"J", "user"}};
  in.materials = {test::rock(2000, 5e9)};
  in.joint_sets = {j};
  in.default_joint = j;
  for (const double x : {0.5, 4.0, 7.5}) in.fixed_points.push_back({"base", test::rotated(Vec2(x, -0.5), a), 0, {}});
  in.measurements.push_back({"slider", test::rotated(Vec2(3.5, 0.5), a), 1});
  in.control.dt = 1e-3;
  in.control.steps = 20;
  // A block on a plane steeper than its friction has no equilibrium either.
  in.control.initial_equilibrium = false;
  return in;
}

TEST_P(EveryFrictionLaw, BlockPulledOffItsBaseMovesFreely2d) {
  const ModelInput in = pulled_block_2d(joint());
  Simulation sim(build_model(in));
  sim.run();
  // Free body under a constant force: DDA's constant-acceleration step is
  // exact for it, u = a t^2 / 2 and v = a t with a = F / m + g =
  // (9.81 / 2, 2 * 9.81 - 9.81) m/s^2, at every step length the run took.
  const double t = sim.time();
  ASSERT_GT(t, 0.0);
  const Vec2 a(0.5 * 9.81, 9.81);
  const MeasurementSample& s = sim.histories()[0].back();
  EXPECT_NEAR(s.displacement.x(), 0.5 * a.x() * t * t, 1e-9 * 0.5 * a.x() * t * t);
  EXPECT_NEAR(s.displacement.y(), 0.5 * a.y() * t * t, 1e-9 * 0.5 * a.y() * t * t);
  EXPECT_NEAR(s.velocity.x(), a.x() * t, 1e-9 * a.x() * t);
  EXPECT_NEAR(s.velocity.y(), a.y() * t, 1e-9 * a.y() * t);
  for (const Contact& c : sim.contacts()) {
    EXPECT_EQ(c.state, ContactState::Open);
    EXPECT_EQ(c.shear_force, 0.0);
  }
}

TEST_P(EveryFrictionLaw, StateRoundTripsAndResumeIsBitIdentical2d) {
  const ModelInput in = sliding_block_2d(joint());
  const std::string whole = temp("2d_whole").string(), part = temp("2d_part").string();
  Simulation a(build_model(in));
  {
    Results r = test::fresh_results(in);
    ASSERT_EQ(run_recorded(a, r, whole, RunControl{}), RunEnd::Finished);
  }
  {  // stopped half way: the checkpoint holds every contact's law state as it was
    Simulation half(build_model(in));
    Results r = test::fresh_results(in);
    RunControl rc;
    rc.stop_at_step = 10;
    ASSERT_EQ(run_recorded(half, r, part, rc), RunEnd::Stopped);
    const Results saved = read_results_h5(part);
    ASSERT_TRUE(saved.checkpoint.has_value());
    const std::vector<Contact>& now = half.contacts();
    ASSERT_EQ(saved.checkpoint->contacts.size(), now.size());
    double slip = 0;
    for (std::size_t k = 0; k < now.size(); ++k) {
      expect_same_state(saved.checkpoint->contacts[k].friction, now[k].friction, "contact " + std::to_string(k));
      EXPECT_EQ(saved.checkpoint->contacts[k].state, now[k].state);
      slip = std::max(slip, now[k].friction.slip);
    }
    EXPECT_GT(slip, 0.0) << "the block has not slid: the state under test is still the initial one";
  }
  Simulation b(build_model(in));
  {  // resumed, as `dda df --resume`
    Results saved = read_results_h5(part);
    b.restore(*saved.checkpoint);
    Results r = test::fresh_results(in);
    r.frames = saved.frames;
    ASSERT_EQ(run_recorded(b, r, part, RunControl{}), RunEnd::Finished);
  }
  ASSERT_EQ(a.log().size(), 20u);
  ASSERT_EQ(b.log().size(), a.log().size());
  EXPECT_EQ(a.time(), b.time());
  ASSERT_EQ(a.blocks().size(), b.blocks().size());
  for (std::size_t i = 0; i < a.blocks().size(); ++i) {
    EXPECT_EQ(a.blocks()[i].vertices, b.blocks()[i].vertices) << "block " << i;
    EXPECT_EQ(a.blocks()[i].velocity, b.blocks()[i].velocity) << "block " << i;
    EXPECT_EQ(a.blocks()[i].stress, b.blocks()[i].stress) << "block " << i;
  }
  ASSERT_EQ(a.contacts().size(), b.contacts().size());
  for (std::size_t k = 0; k < a.contacts().size(); ++k) {
    const Contact &x = a.contacts()[k], &y = b.contacts()[k];
    EXPECT_EQ(x.state, y.state) << "contact " << k;
    EXPECT_EQ(x.normal_force, y.normal_force) << "contact " << k;
    EXPECT_EQ(x.shear_force, y.shear_force) << "contact " << k;
    expect_same_state(x.friction, y.friction, "contact " + std::to_string(k));
  }
  const MeasurementSample &p = a.histories()[0].back(), &q = b.histories()[0].back();
  EXPECT_EQ(p.displacement, q.displacement);
  EXPECT_EQ(p.velocity, q.velocity);
  EXPECT_GT(p.displacement.norm(), 0.0);
  fs::remove(whole);
  fs::remove(part);
}

}  // namespace
}  // namespace dda::df

namespace dda::df3 {
namespace {

namespace fs = std::filesystem;
using df::EveryFrictionLaw;

// ---- 3D models: a 1 m cube (2600 kg) on a fixed 10 x 10 x 1 m base, the
// touching faces of set 0, all joints of the law.
PolyhedronModel cube_on_base(double dip_deg) {
  const Eigen::Matrix3d r = testing::plane_rotation(dip_deg, 90);
  PolyhedronModel m;
  m.blocks = {testing::box({-5, -5, -1}, {5, 5, 0}, r), testing::box({-0.5, -0.5, 0}, {0.5, 0.5, 1}, r)};
  m.blocks[0].faces[1].set = 0;  // the base's top
  m.blocks[1].faces[0].set = 0;  // the cube's bottom
  for (Polyhedron& p : m.blocks) refresh_geometry(p), p.body = -1;
  m.sets = {{"J", "plane"}};
  return m;
}

Model3 model_of(const PolyhedronModel& blocks, const df::JointProperties& j) {
  Model3 m;
  m.blocks = blocks.blocks;
  m.fixed = {true, false};
  m.materials = {{2600, 1e10, 0.25}};
  m.joint_sets = {j};
  m.default_joint = j;
  m.control.dt = 1e-3;
  m.control.steps = 20;
  // Neither model has an equilibrium to settle into (see the 2D models).
  m.control.initial_equilibrium = false;
  return m;
}

// The cube pulled at its centroid by F = (m g / 2, 0, 2 m g): net force
// (m g / 2, 0, m g), off the base and along it.
Model3 pulled_cube(const df::JointProperties& j) {
  Model3 m = model_of(cube_on_base(0), j);
  const double mg = 2600 * 9.81;
  PointLoad3 pull;
  pull.block = 1;
  pull.position = Vec3(0, 0, 0.5);
  pull.force.t = {0, 1};
  pull.force.value = {Vec3(0.5 * mg, 0, 2 * mg), Vec3(0.5 * mg, 0, 2 * mg)};
  m.loads.push_back(pull);
  m.measurements.push_back({"centroid", 1, Vec3(0, 0, 0.5)});
  return m;
}

TEST_P(EveryFrictionLaw, BlockPulledOffItsBaseMovesFreely3d) {
  Simulation3 sim(pulled_cube(joint()));
  sim.run();
  // As in 2D: u = a t^2 / 2, v = a t, a = (9.81 / 2, 0, 9.81) m/s^2.
  const double t = sim.time();
  ASSERT_GT(t, 0.0);
  const Vec3 a(0.5 * 9.81, 0, 9.81);
  const MeasurementSample3& s = sim.histories()[0].back();
  EXPECT_NEAR(s.displacement.x(), 0.5 * a.x() * t * t, 1e-9 * 0.5 * a.x() * t * t);
  EXPECT_NEAR(s.displacement.y(), 0.0, 1e-15);
  EXPECT_NEAR(s.displacement.z(), 0.5 * a.z() * t * t, 1e-9 * 0.5 * a.z() * t * t);
  EXPECT_NEAR(s.velocity.x(), a.x() * t, 1e-9 * a.x() * t);
  EXPECT_NEAR(s.velocity.z(), a.z() * t, 1e-9 * a.z() * t);
  for (const Contact3& c : sim.contacts()) {
    EXPECT_EQ(c.state, ContactState3::Open);
    EXPECT_EQ(c.shear_force.norm(), 0.0);
  }
}

TEST_P(EveryFrictionLaw, StateRoundTripsAndResumeIsBitIdentical3d) {
  const PolyhedronModel blocks = cube_on_base(40);
  Model3 model = model_of(blocks, joint());
  model.measurements.push_back({"cube", 1, testing::plane_rotation(40, 90) * Vec3(0, 0, 0.5)});
  const std::string whole = temp("3d_whole").string(), part = temp("3d_part").string();
  Simulation3 a(model);
  {
    Results3 r = testing::fresh_results3(blocks);
    ASSERT_EQ(run_recorded(a, r, whole, RunControl3{}), df::RunEnd::Finished);
  }
  {  // stopped half way: the checkpoint holds every contact's law state
    Simulation3 half(model);
    Results3 r = testing::fresh_results3(blocks);
    RunControl3 rc;
    rc.stop_at_step = 10;
    ASSERT_EQ(run_recorded(half, r, part, rc), df::RunEnd::Stopped);
    const Results3 saved = read_results3_h5(part);
    ASSERT_TRUE(saved.checkpoint.has_value());
    const std::vector<Contact3>& now = half.contacts();
    ASSERT_EQ(saved.checkpoint->contacts.size(), now.size());
    double slip = 0;
    for (std::size_t k = 0; k < now.size(); ++k) {
      df::expect_same_state(saved.checkpoint->contacts[k].friction, now[k].friction,
                            "contact " + std::to_string(k));
      EXPECT_EQ(saved.checkpoint->contacts[k].state, now[k].state);
      slip = std::max(slip, now[k].friction.slip);
    }
    EXPECT_GT(slip, 0.0) << "the cube has not slid: the state under test is still the initial one";
  }
  Simulation3 b(model);
  {  // resumed, as `dda df --resume`
    Results3 saved = read_results3_h5(part);
    b.restore(*saved.checkpoint);
    Results3 r = testing::fresh_results3(blocks);
    r.frames = saved.frames;
    ASSERT_EQ(run_recorded(b, r, part, RunControl3{}), df::RunEnd::Finished);
  }
  ASSERT_EQ(a.log().size(), 20u);
  ASSERT_EQ(b.log().size(), a.log().size());
  EXPECT_EQ(a.time(), b.time());
  for (std::size_t i = 0; i < a.blocks().size(); ++i) {
    EXPECT_EQ(a.blocks()[i].vertices, b.blocks()[i].vertices) << "block " << i;
    EXPECT_EQ(a.velocities()[i], b.velocities()[i]) << "block " << i;
    EXPECT_EQ(a.stresses()[i], b.stresses()[i]) << "block " << i;
  }
  ASSERT_EQ(a.contacts().size(), b.contacts().size());
  for (std::size_t k = 0; k < a.contacts().size(); ++k) {
    const Contact3 &x = a.contacts()[k], &y = b.contacts()[k];
    EXPECT_EQ(x.state, y.state) << "contact " << k;
    EXPECT_EQ(x.normal_force, y.normal_force) << "contact " << k;
    EXPECT_EQ(x.shear_force, y.shear_force) << "contact " << k;
    df::expect_same_state(x.friction, y.friction, "contact " + std::to_string(k));
  }
  EXPECT_EQ(a.histories()[0].back().displacement, b.histories()[0].back().displacement);
  EXPECT_GT(a.histories()[0].back().displacement.norm(), 0.0);
  fs::remove(whole);
  fs::remove(part);
}

}  // namespace
}  // namespace dda::df3

namespace dda::df {
namespace {

INSTANTIATE_TEST_SUITE_P(Registered, EveryFrictionLaw, ::testing::ValuesIn(registered_laws()),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });

}  // namespace
}  // namespace dda::df
