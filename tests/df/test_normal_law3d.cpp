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
#include "dda/df/io/results3d.hpp"
#include "dda/df/io/scenario3d.hpp"
#include "dda/df/2d/simulation.hpp"
#include "dda/df/3d/simulation3d.hpp"
#include "df_io_test_models3d.hpp"
#include "df_test_models3d.hpp"
#include "df_test_models.hpp"

namespace dda::df3 {
namespace {


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
  m.control.dt = 3e-3;
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
// N/m^2.5: g = (4.905e-7)^(2/3) = 6.2196e-5 m. The relaxation's solves
// (pseudo step 10 dt = 0.03 s) carry an inertia term 2 M / (0.03 s)^2 =
// 4.4e6 N/m against the corners' tangent 4 * 2 c_n g = 1.8e7 N/m (m_n = 2;
// 4.7e8 N/m for m_n = 1.5), so each solve leaves at most a fifth of the
// error before it; it stops once a solve moves the prism less than 1e-9
// w0 = 2e-9 m (w0 = 2 m, half the model's largest side), which leaves
// 5e-10 m, 2e-7 of the first g. 1e-6 of g is asked for (measured 9e-9 and
// 1.3e-8).
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
    for (const Contact3& c : sim.contacts()) {
      if (c.state != ContactState3::Open) {
        EXPECT_NEAR(c.normal_force, kCorner, 1e-6 * kCorner);
      }
    }
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
  for (const Contact3& c : sim.contacts()) {
    if (c.state != ContactState3::Open) {
      EXPECT_EQ(c.state, ContactState3::Locked);
    }
  }
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

// Both settle to g = sqrt(4905 / 1e9) = 2.2147e-3 m (as above), each by
// its own relaxation (2D: w0 = 0.5 m, so it stops at 5e-10 m), on a base
// held by fixed points in 2D: the 2D number is asked within 1e-5 of the
// closed form and the two within 1e-6 of g (measured: 2D 3.1e-7 below the
// closed form, 3D 9e-9 above it).
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

// The prism dropped from 5 mm onto the Oden-Martins joint (c_n = 1e9, m_n =
// 2): it lands at sqrt(2 g h) = 0.31 m/s after 0.032 s and is at its
// deepest, about 5.3 mm, near 0.05 s, which is where the run stops: the
// springs then hold most of the energy. The ledger's stored contact energy
// must be the law's E(N) = N g / (m_n + 1) = N^1.5 / (3 sqrt(c_n)) (the
// penalty's N^2 / 2 pn, pn = 1e9, would be a few joules, not about 180).
// The test integrates the work
// the contacts take from the prism itself, from the corners' penetrations
// g (vertex z) and the contacts' forces N after every step: DDA's step
// moves a block under its end-of-step forces (constant acceleration), so
// the contacts take W = sum over steps and corners of N (g_k - g_k-1).
// The balance then says residual = W - sum E(N_end), what the implicit
// step dissipates (k dg^2 / 2 a corner a step, k the law's tangent), to
// what the by-hand sum leaves out: the prism's own strain energy and the
// step's damping of it (E = 1e12 Pa: at the deepest point the corners
// carry 4 c_n g^2 = 1.1e5 N, 5.7e4 Pa over the 2 m^2 bottom, and
// sigma^2 V / 2E = 1.6e-3 J), so to 1e-4 of the work done. That
// dissipation is the step's, not the law's: it goes to zero with dt,
// halving when dt halves.
struct Drop {
  double residual = 0, dissipated_by_hand = 0, stored_by_hand = 0, input = 0, most_created = 0;
  double contact = 0;
};

Drop drop(double dt) {
  const double c_n = 1e9;
  Model3 m = prism_on_base(oden_martins(c_n, 2), 0.005);
  m.control.initial_equilibrium = false;
  Simulation3 sim(m);
  std::vector<double> z(4, 0.005);
  Drop r;
  const int steps = static_cast<int>(std::lround(0.05 / dt));
  for (int s = 0; s < steps; ++s) {
    sim.step(dt);
    for (const Contact3& c : sim.contacts()) {
      if (c.state == ContactState3::Open) continue;
      EXPECT_EQ(c.i, 1);  // the prism's corner on the base's face
      EXPECT_EQ(c.kind, ContactKind3::VertexFace);
      const auto v = static_cast<std::size_t>(c.ids[0]);
      r.dissipated_by_hand += c.normal_force * (z[v] - sim.blocks()[1].vertices[v].z());
    }
    for (std::size_t v = 0; v < 4; ++v) z[v] = sim.blocks()[1].vertices[v].z();
  }
  for (const Contact3& c : sim.contacts())
    if (c.state != ContactState3::Open && c.normal_force > 0)
      r.stored_by_hand += c.normal_force * std::sqrt(c.normal_force / c_n) / 3 + c.shear_force.squaredNorm() / (2 * 1e9);
  r.dissipated_by_hand -= r.stored_by_hand;
  const df::EnergyRecord& e = sim.energy_log().back();
  r.residual = e.residual;
  r.input = e.input();
  r.contact = e.contact;
  r.most_created = std::max(0.0, -df::most_energy_created(sim.energy_log()).residual);
  std::printf("3D Oden-Martins drop, dt = %g s: gravity work %.6f J, kinetic %.6f J, contact %.6f J (by hand "
              "%.6f J), residual %.6f J (by hand %.6f J), most created %.3e J\n",
              dt, e.gravity_work, e.kinetic, e.contact, r.stored_by_hand, e.residual, r.dissipated_by_hand,
              r.most_created);
  return r;
}

TEST(NormalLaw3, EnergyLedgerBalancesForAPrismDroppedOnTheJoint) {
  const Drop a = drop(1e-3), b = drop(5e-4);
  for (const Drop& r : {a, b}) {
    EXPECT_NEAR(r.contact, r.stored_by_hand, 1e-12 * r.input);
    EXPECT_NEAR(r.residual, r.dissipated_by_hand, 1e-4 * r.input);
    EXPECT_GT(r.contact, 0.5 * r.input);  // the springs hold most of the energy: E(N) is what is checked
    EXPECT_LE(r.most_created, 1e-9 * r.input);  // the step never makes energy
  }
  // First order in dt: the ratio of the residuals is about 2 (measured 1.82: the landing falls at
  // another point of a step), asked within 10 %.
  EXPECT_NEAR(a.residual / b.residual, 2.0, 0.2);
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
  // Stopped at step 30, after the landing (about step 20).
  const testing::WholeAndResumed3 runs = testing::run_whole_and_resumed3(model, blocks, 30, "normal_law3");
  ASSERT_GT(closed_contacts(*runs.stopped), 0);
  const Simulation3 &a = *runs.whole, &b = *runs.resumed;
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
