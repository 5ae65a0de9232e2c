// Normal laws and per-joint-set penalties in 3D (issue 28, 3D parity): the
// 3D contacts take the 2D registry's laws (normal_law.hpp) and a joint
// set's own normal_penalty / shear_penalty (ContactSprings3). Checked on a
// prism resting on a fixed base against the closed-form static
// penetration, against the 2D solver on the same prism, through the energy
// ledger of a block dropped on the joint, a resumed run, and the scenario.
//
// The prism: the 2D block [0, 1] x [0, 0.5] (x, z) extruded 2 m along y,
// rho = 2000 kg/m^3, so W = 2000 * 9.81 * (1 * 2 * 0.5) = 19620 N. Its four
// bottom corners are its contacts with the base; by symmetry each carries
// W / 4 = 4905 N.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "../common/input_error_of.hpp"
#include "dda/df/results3d.hpp"
#include "dda/df/scenario3d.hpp"
#include "dda/df/simulation.hpp"
#include "dda/df/simulation3d.hpp"
#include "df3_io_test_models.hpp"
#include "df3_test_models.hpp"
#include "df_test_models.hpp"

namespace dda::df3 {
namespace {

namespace fs = std::filesystem;

constexpr double kRho = 2000, kG = 9.81;
constexpr double kWeight3 = kRho * kG * 1.0;  // 19620 N, the prism's 1 m^3
constexpr double kCorner = kWeight3 / 4;      // 4905 N per bottom corner

df::JointProperties oden_martins(double c_n, double m_n) {
  df::JointProperties j;
  j.friction_deg = 30;
  j.normal_law = "oden_martins";
  j.normal_parameters = {{"c_n", c_n}, {"m_n", m_n}};
  return j;
}

// The prism (block 1) on a fixed 3 x 4 x 0.5 m base (block 0), its bottom
// `lift` above the base's top (z = 0); the touching faces are of joint set
// 0, `joint`; every other face takes the plain default joint. E = 1e12 Pa:
// the prism's own strain is far below the contacts' penetration (and the
// corners' penetration does not depend on it: they are the contact points).
Model3 prism_on_base(const df::JointProperties& joint, double lift = 0) {
  Model3 m;
  m.blocks = {testing::box({-1, -1, -0.5}, {2, 3, 0}), testing::box({0, 0, lift}, {1, 2, 0.5 + lift})};
  m.blocks[0].faces[1].set = 0;  // the base's top
  m.blocks[1].faces[0].set = 0;  // the prism's bottom
  m.fixed = {true, false};
  m.materials = {{kRho, 1e12, 0.25}};
  m.joint_sets = {joint};
  m.gravity = {0, 0, -kG};
  m.normal_penalty = m.shear_penalty = 1e9;  // the run's springs, for joints without their own
  m.contact_reach = 0.02;
  m.control.dt = 1e-3;
  return m;
}

// Penetration of each bottom corner (vertices 0 to 3 of testing::box) into
// the base's top z = 0 (the base is fixed: it stays there).
std::vector<double> corner_penetrations(const Simulation3& sim) {
  std::vector<double> g;
  for (int v = 0; v < 4; ++v) g.push_back(-sim.blocks()[1].vertices[static_cast<std::size_t>(v)].z());
  return g;
}

int closed_contacts(const Simulation3& sim) {
  int n = 0;
  for (const Contact3& c : sim.contacts()) n += c.state != ContactState3::Open ? 1 : 0;
  return n;
}

// The prism settles (the start-up relaxation: static solves under gravity)
// on an Oden-Martins joint N = c_n g^m_n: each corner carries W / 4, so
// g = (W / (4 c_n))^(1/m_n). c_n = 1e9 N/m^3, m_n = 2: g = sqrt(4905 / 1e9)
// = 2.2147e-3 m (by hand); m_n = 1.5 (Hertz's exponent), c_n = 1e10
// N/m^2.5: g = (4.905e-7)^(2/3) = 6.2170e-5 m. The relaxation stops when a
// solve moves the prism less than 1e-9 w0 (w0 = 2 m, half the model's
// largest side): 2e-9 m, 1e-6 of the first g and 3e-5 of the second; it
// converges as Newton's method on the law's tangent, so the error is far
// smaller, and 1e-6 of g is asked for.
TEST(NormalLaw3, PrismSettlesToTheOdenMartinsPenetration) {
  for (const auto& [c_n, m_n] : {std::pair{1e9, 2.0}, std::pair{1e10, 1.5}}) {
    SCOPED_TRACE("m_n = " + std::to_string(m_n));
    Simulation3 sim(prism_on_base(oden_martins(c_n, m_n)));
    sim.start();
    ASSERT_TRUE(sim.start_up().frictional_equilibrium);
    ASSERT_EQ(closed_contacts(sim), 4);
    const double expected = std::pow(kCorner / c_n, 1 / m_n);
    for (const double g : corner_penetrations(sim)) {
      std::printf("3D Oden-Martins m_n = %.1f: corner penetration %.9e m (closed form %.9e)\n", m_n, g, expected);
      EXPECT_NEAR(g, expected, 1e-6 * expected);
    }
    for (const Contact3& c : sim.contacts())
      if (c.state != ContactState3::Open) EXPECT_NEAR(c.normal_force, kCorner, 1e-6 * kCorner);
  }
}

// Per-set penalties: the joint set gives pn = 2e8 and ps = 5e7 N/m, the
// run 1e9 for both. Vertically each corner sinks g = (W / 4) / pn_set =
// 4905 / 2e8 = 2.4525e-5 m (the run's springs would give 4.905e-6 m).
// A horizontal load P = 0.2 W = 3924 N on the middle of the prism's bottom
// (no moment about the contact plane, so the four corners still share W
// equally), held by friction (tan 30 = 0.577 > 0.2): the four locked shear
// springs take P, so the corners move on average P / (4 ps_set) = 3924 /
// 2e8 = 1.962e-5 m along x (3.924e-6 m with the run's springs). Linear
// springs: the relaxation lands on them to 1e-9 of the prism's size
// (2e-9 m), within 1e-4 of either number.
TEST(NormalLaw3, PerSetPenaltiesGiveThePenetrationAndTheShearDisplacement) {
  df::JointProperties joint;
  joint.friction_deg = 30;
  joint.normal_penalty = 2e8;
  joint.shear_penalty = 5e7;
  Model3 m = prism_on_base(joint);
  PointLoad3 push;
  push.block = 1;
  push.position = Vec3(0.5, 1, 0);
  push.force.t = {0, 10};
  push.force.value = {Vec3(0.2 * kWeight3, 0, 0), Vec3(0.2 * kWeight3, 0, 0)};
  m.loads.push_back(push);
  const std::vector<Vec3> start(m.blocks[1].vertices.begin(), m.blocks[1].vertices.begin() + 4);
  Simulation3 sim(m);
  sim.start();
  ASSERT_TRUE(sim.start_up().frictional_equilibrium);
  ASSERT_EQ(closed_contacts(sim), 4);
  for (const Contact3& c : sim.contacts())
    if (c.state != ContactState3::Open) EXPECT_EQ(c.state, ContactState3::Locked);
  const double g_expected = kCorner / 2e8, u_expected = 0.2 * kWeight3 / (4 * 5e7);
  double u = 0;
  for (int v = 0; v < 4; ++v) u += 0.25 * (sim.blocks()[1].vertices[static_cast<std::size_t>(v)].x() - start[v].x());
  std::printf("3D per-set penalties: mean corner slip %.9e m (P / 4 ps = %.9e)\n", u, u_expected);
  for (const double g : corner_penetrations(sim)) {
    std::printf("3D per-set penalties: corner penetration %.9e m (W / 4 pn = %.9e)\n", g, g_expected);
    EXPECT_NEAR(g, g_expected, 1e-4 * g_expected);
  }
  EXPECT_NEAR(u, u_expected, 1e-4 * u_expected);
}

// The 2D solver's prism: the same block [0, 1] x [0, 0.5] on a base held by
// fixed points, the same joint. The 2D contact force is per unit
// thickness and per contact point: its two corners carry W2 / 2 each, W2 =
// 2000 * 9.81 * 0.5 = 9810 N/m, i.e. 4905 N per metre of thickness. The 3D
// prism is 2 m thick and has two corners at each end of the 2D corner's
// line, so each 3D corner stands for 1 m of it and carries 4905 N too: the
// same c_n gives the same penetration in both (for another thickness t,
// the 3D c_n would be t / 2 times the 2D one).
double penetration_2d(const df::JointProperties& joint) {
  df::ModelInput in;
  in.geometry.blocks.push_back(df::test::make_block(df::test::rectangle(-1, -0.5, 3, 0.5)));
  in.geometry.blocks.push_back(df::test::make_block(df::test::rectangle(0, 0, 1, 0.5)));
  in.materials = {df::test::rock(kRho, 1e12)};
  in.joint_sets = {joint};
  in.default_joint = joint;
  in.control.dt = 1e-3;
  for (const double x : {-0.5, 0.5, 1.5}) in.fixed_points.push_back({"base", {x, -0.25}, 0, {}});
  df::Simulation sim(df::build_model(in));
  sim.start();
  // The base is held by springs: the penetration is measured from its top
  // edge (its vertices 2 and 3, x = 2 and -1) under each corner.
  const Polygon2& base = sim.blocks()[0].vertices;
  const Polygon2& block = sim.blocks()[1].vertices;
  double g = 0;
  for (const int v : {0, 1}) {
    const double s = (block[v].x() - base[3].x()) / (base[2].x() - base[3].x());
    const double top = base[3].y() + s * (base[2].y() - base[3].y());
    g += 0.5 * (top - block[v].y());
  }
  return g;
}

// Both settle to g = sqrt(4905 / 1e9) = 2.2147e-3 m (as above); the 2D
// base's fixed-point springs and strain, and the 3D block's strain, are
// below 1e-8 m, so the two agree to 1e-6 of g.
TEST(NormalLaw3, ExtrudedPrismSettlesAsThe2dBlock) {
  const df::JointProperties joint = oden_martins(1e9, 2);
  Simulation3 sim(prism_on_base(joint));
  sim.start();
  double g3 = 0;
  for (const double g : corner_penetrations(sim)) g3 += 0.25 * g;
  const double g2 = penetration_2d(joint);
  const double expected = std::sqrt(kCorner / 1e9);
  std::printf("Oden-Martins prism: 2D penetration %.9e m, 3D %.9e m, closed form %.9e m\n", g2, g3, expected);
  EXPECT_NEAR(g2, expected, 1e-5 * expected);
  EXPECT_NEAR(g3, g2, 1e-6 * expected);
}

// Worst |residual| over the run as a share of the energy moved up to then.
double worst_residual_share(const std::vector<df::EnergyRecord>& log) {
  double worst = 0;
  for (std::size_t k = 1; k < log.size(); ++k) {
    const double moved = df::energy_moved(log.front(), log[k]);
    if (moved > 0) worst = std::max(worst, std::abs(log[k].residual) / moved);
  }
  return worst;
}

// The prism dropped from 5 mm onto the Oden-Martins joint (c_n = 1e9, m_n =
// 2), 0.3 s: it lands at sqrt(2 g h) = 0.31 m/s after 0.032 s and bounces
// on the law's stiffening springs. The ledger's stored contact energy is
// the law's E(N) = N g / (m_n + 1) (not N^2 / 2 pn): with the penalty's
// formula the residual would be of the order of the springs' energy
// itself. The balance must close as the 3D sliding cube's does
// (test_energy3d.cpp: 1e-3 of the work done), and the energy the springs
// hold at the end is checked against E(N) by hand.
TEST(NormalLaw3, EnergyLedgerBalancesForAPrismDroppedOnTheJoint) {
  const double c_n = 1e9;
  Model3 m = prism_on_base(oden_martins(c_n, 2), 0.005);
  m.control.initial_equilibrium = false;
  Simulation3 sim(m);
  for (int s = 0; s < 300; ++s) sim.step(1e-3);
  const std::vector<df::EnergyRecord>& log = sim.energy_log();
  const df::EnergyRecord& e = log.back();
  double by_hand = 0;  // c_n g^3 / 3 at each closed contact's force, g = sqrt(N / c_n)
  for (const Contact3& c : sim.contacts())
    if (c.state != ContactState3::Open && c.normal_force > 0)
      by_hand += c.normal_force * std::sqrt(c.normal_force / c_n) / 3 + c.shear_force.squaredNorm() / (2 * 1e9);
  std::printf("3D Oden-Martins drop: gravity work %.6f J, kinetic %.6f J, contact %.6f J (by hand %.6f J), "
              "residual %.3e J, worst residual share %.2e\n",
              e.gravity_work, e.kinetic, e.contact, by_hand, e.residual, worst_residual_share(log));
  ASSERT_GT(closed_contacts(sim), 0);
  EXPECT_NEAR(e.contact, by_hand, 1e-12 * by_hand);
  EXPECT_GT(e.gravity_work, kWeight3 * 0.005);  // it fell 5 mm and more
  EXPECT_LE(std::abs(e.residual), 1e-3 * e.input());
}

// A run on the Oden-Martins joint stopped and resumed from its checkpoint
// repeats the uninterrupted one bit for bit: the contact keeps no new state
// (the law's spring over a step comes from the gap at its start, which the
// next detection recomputes).
TEST(NormalLaw3, ResumedRunIsBitIdentical) {
  PolyhedronModel blocks;
  {
    const Model3 shape = prism_on_base(oden_martins(1e9, 2), 0.002);
    blocks.blocks = shape.blocks;
    for (Polyhedron& p : blocks.blocks) refresh_geometry(p), p.body = -1;
    blocks.sets = {{"J", "plane"}};
  }
  Model3 model = prism_on_base(oden_martins(1e9, 2), 0.002);
  model.control.initial_equilibrium = false;
  model.control.steps = 60;
  model.measurements.push_back({"prism", 1, Vec3(0.5, 1, 0.252)});
  const std::string whole = (fs::temp_directory_path() / "dda_normal_law3_whole.h5").string();
  const std::string part = (fs::temp_directory_path() / "dda_normal_law3_part.h5").string();
  Simulation3 a(model);
  {
    Results3 r = testing::fresh_results3(blocks);
    ASSERT_EQ(run_recorded(a, r, whole, RunControl3{}), df::RunEnd::Finished);
  }
  {
    Simulation3 half(model);
    Results3 r = testing::fresh_results3(blocks);
    RunControl3 rc;
    rc.stop_at_step = 30;  // after the landing (about step 20)
    ASSERT_EQ(run_recorded(half, r, part, rc), df::RunEnd::Stopped);
    ASSERT_GT(closed_contacts(half), 0);
  }
  Simulation3 b(model);
  {
    Results3 saved = read_results3_h5(part);
    ASSERT_TRUE(saved.checkpoint.has_value());
    b.restore(*saved.checkpoint);
    Results3 r = testing::fresh_results3(blocks);
    r.frames = saved.frames;
    ASSERT_EQ(run_recorded(b, r, part, RunControl3{}), df::RunEnd::Finished);
  }
  ASSERT_EQ(b.log().size(), a.log().size());
  for (std::size_t i = 0; i < a.blocks().size(); ++i) {
    EXPECT_EQ(a.blocks()[i].vertices, b.blocks()[i].vertices) << "block " << i;
    EXPECT_EQ(a.velocities()[i], b.velocities()[i]) << "block " << i;
  }
  ASSERT_EQ(a.contacts().size(), b.contacts().size());
  for (std::size_t k = 0; k < a.contacts().size(); ++k) {
    EXPECT_EQ(a.contacts()[k].normal_force, b.contacts()[k].normal_force) << "contact " << k;
    EXPECT_EQ(a.contacts()[k].state, b.contacts()[k].state) << "contact " << k;
  }
  EXPECT_EQ(a.energy_log().back().residual, b.energy_log().back().residual);
  fs::remove(whole);
  fs::remove(part);
}

// The scenario: the 2D keys, read by the same code, are taken in 3D; a bad
// number names the file, line and key.
DfScenario3 read3(const std::string& joints) {
  const std::string text = "dimension: 3\n" + joints + "control: {dt: 0.002, total_time: 0.5}\n";
  const std::vector<ModelPoint3> points{{"top", PointKind::Measurement, Vec3(0, 0, 0.9)}};
  return read_df3_scenario(YamlNode::load_string(text, "s.yaml"), testing::incline_blocks(points), "b3.h5");
}

TEST(NormalLaw3, ScenarioTakesTheLawAndTheSetsPenalties) {
  const DfScenario3 s = read3(
      "joints:\n  default: {friction_deg: 35, normal_law: {name: oden_martins, c_n: 1.0e12, m_n: 2}}\n"
      "  slide: {friction_deg: 20, normal_penalty: 2.0e8, shear_penalty: 5.0e7}\n");
  ASSERT_EQ(s.model.joint_sets.size(), 1u);
  const df::JointProperties& slide = s.model.joint_sets[0];
  EXPECT_EQ(slide.normal_law, "oden_martins");  // inherited from the default, with its numbers
  EXPECT_EQ(slide.normal_parameters.at("m_n"), 2.0);
  EXPECT_EQ(slide.normal_penalty, 2.0e8);
  EXPECT_EQ(slide.shear_penalty, 5.0e7);
  const std::vector<ContactSprings3> springs = contact_springs3(s.model);
  ASSERT_EQ(springs.size(), 2u);  // the set, then the default
  EXPECT_EQ(springs[0].pn, 2.0e8);
  EXPECT_EQ(springs[0].ps, 5.0e7);
  EXPECT_EQ(springs[0].normal->name(), "oden_martins");
  EXPECT_EQ(springs[1].pn, s.model.normal_penalty);  // the run's
  EXPECT_EQ(springs[1].ps, s.model.shear_penalty);
  const std::string error = dda::testing::input_error_of([] {
    read3("joints:\n  default: {friction_deg: 35, normal_law: {name: oden_martins, c_n: 1.0e12, m_n: 0.5}}\n");
  });
  EXPECT_EQ(error, "s.yaml:3: joints.default.normal_law.m_n must be in [1, 10], got 0.5.");
}

// A set's shear penalty follows its normal penalty by the run's ratio ps /
// pn (2D's shear_ratio): run pn = 1e9, ps = 1e8, a set of pn = 4e8 without
// its own ps gets 4e7 N/m.
TEST(NormalLaw3, SetShearPenaltyFollowsItsNormalPenaltyByTheRunsRatio) {
  df::JointProperties joint;
  joint.normal_penalty = 4e8;
  Model3 m = prism_on_base(joint);
  m.shear_penalty = 1e8;
  const std::vector<ContactSprings3> springs = contact_springs3(m);
  EXPECT_DOUBLE_EQ(springs[0].ps, 4e7);
  EXPECT_EQ(springs[1].pn, 1e9);
  EXPECT_EQ(springs[1].ps, 1e8);
  m.joint_sets[0].normal_penalty = -1;
  EXPECT_EQ(dda::testing::input_error_of([&] { contact_springs3(m); }),
            "The 3D joint set 0's normal_penalty must be a positive number (N/m).");
}

}  // namespace
}  // namespace dda::df3
