// Energy bookkeeping (energy.hpp), runaway detection (runaway.hpp), stress
// rotation, glued artificial cuts and the friction-law interface.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "df_test_models.hpp"
#include "dda/common/error.hpp"
#include "dda/df/core/block_system.hpp"
#include "dda/df/core/runaway.hpp"
#include "dda/df/2d/simulation.hpp"

namespace dda::df {
namespace {

using test::make_block;
using test::rectangle;

TEST(Energy, FreeFallConservesKineticPlusPotential) {
  // V8 free fall: no contacts, so the work of gravity must equal the
  // kinetic energy at every step (the DDA step is exact for constant
  // acceleration): residual / input <= 1e-9; and m g (g t^2 / 2) at t = 1 s.
  ModelInput in;
  in.geometry.blocks.push_back(make_block(rectangle(0, 0, 1, 1)));
  in.materials = {test::rock()};
  in.control.dt = 0.01;
  Simulation sim(build_model(in));
  sim.run_until(1.0);
  double worst = 0;
  for (const EnergyRecord& e : sim.energy_log())
    if (e.input() > 0) worst = std::max(worst, std::abs(e.residual) / e.input());
  const EnergyRecord& e = sim.energy_log().back();
  const double m = 2000, g = 9.81;
  std::printf("free fall: W_g=%.9f KE=%.9f worst residual/input=%.2e\n", e.gravity_work, e.kinetic, worst);
  EXPECT_LE(worst, 1e-9);
  EXPECT_NEAR(e.gravity_work, m * g * g / 2, 1e-9 * m * g * g / 2);
  EXPECT_NEAR(e.kinetic, e.gravity_work, 1e-9 * e.gravity_work);
  EXPECT_EQ(sim.energy_log().size(), sim.log().size() + 1);
}

TEST(Energy, SlidingBlockDissipatesMuNs) {
  // V1, phi = 20, E = 50 GPa, from equilibrium: the friction dissipation
  // must be mu N s with N = m g cos(30) and s the slide (within 1 %).
  const double a = deg2rad(30.0);
  ModelInput in;
  in.geometry.blocks.push_back(make_block(test::rotated(rectangle(0, -1, 8, 1), a)));
  in.geometry.blocks.push_back(make_block(test::rotated(rectangle(6, 0, 1, 1), a)));
  in.materials = {test::rock(2000, 5e10)};
  JointProperties j;
  j.friction_deg = 20;
  in.joint_sets = {j};
  in.control.dt = 1e-3;
  in.control.initial_equilibrium = true;
  for (const double x : {0.5, 4.0, 7.5}) in.fixed_points.push_back({"base", test::rotated(Vec2(x, -0.5), a), 0, {}});
  in.measurements.push_back({"slider", test::rotated(Vec2(6.5, 0.5), a), 1});
  Simulation sim(build_model(in));
  sim.run_until(1.0);
  const double s = (sim.histories()[0].back().position - sim.histories()[0].front().position).norm();
  const double expected = std::tan(deg2rad(20.0)) * 2000 * 9.81 * std::cos(a) * s;
  const EnergyRecord& e = sim.energy_log().back();
  std::printf("sliding: friction=%.3f J expected mu N s=%.3f J; input %.3f stored change %.3f residual %.3e J\n",
              e.friction, expected, e.input(), e.stored() - sim.energy_log().front().stored(), e.residual);
  EXPECT_NEAR(e.friction, expected, 0.01 * expected);
  // The balance closes up to what the penalty springs dissipate.
  EXPECT_LE(std::abs(e.residual), 1e-3 * e.input());
}

// most_energy_created on a log worked by hand. Record 0: 10 J kinetic.
// 1: gravity 5 J, kinetic 12, friction 1 -> residual 5 - 2 - 1 = 2, scale
// max(5, 2 + 1) = 5. 2: gravity 6, kinetic 30 -> residual 6 - 20 = -14,
// scale max(5, 6, 20) = 20, ratio -0.7. 3: gravity 100, kinetic 20,
// friction 50 -> residual 40, scale 100. Expected: record 2.
TEST(Energy, MostEnergyCreatedIsTheWorstResidualForTheEnergyMoved) {
  std::vector<EnergyRecord> log(4);
  log[0].kinetic = 10;
  log[1] = {.time = 1, .kinetic = 12, .gravity_work = 5, .friction = 1, .residual = 2};
  log[2] = {.time = 2, .kinetic = 30, .gravity_work = 6, .friction = 0, .residual = -14};
  log[3] = {.time = 3, .kinetic = 20, .gravity_work = 100, .friction = 50, .residual = 40};
  const EnergyCreated worst = most_energy_created(log);
  EXPECT_EQ(worst.time, 2);
  EXPECT_EQ(worst.residual, -14);
  EXPECT_EQ(worst.scale, 20);
  EXPECT_DOUBLE_EQ(worst.ratio(), -0.7);
  EXPECT_EQ(most_energy_created({log[0]}).ratio(), 0);
}

// The thin arm of contact detection's test (EntranceEdge.CornerOnAThin-
// ArmIsNotAPenetrationOfTheArmsEnd) in a run: the L-shaped block with its
// 9 mm arm and a block beside the arm's end are held by fixed points, and
// the 1.26 x 1.64 m block above rests on both, its corner on the arm 6 mm
// from the arm's end (the 192k-block tunnel model's mesh, shifted by
// (-290, -125) m; E = 15.3 GPa, rho = 2300, search distance 25 mm as
// there). Before the fix a contact with the arm's end started 6 mm deep
// and threw the upper block up. Expected: the block above starts to settle
// under gravity: no energy created beyond rounding and the penalty's 1 %,
// and after 20 steps of 0.1 ms it moves slower than free fall would make
// it (g t = 0.0196 m/s).
TEST(Energy, CornerOnAThinArmCreatesNoEnergy) {
  ModelInput in;
  const Vec2 shift(-290, -125);
  auto at = [&](std::initializer_list<Vec2> pts) {
    Polygon2 p;
    for (const Vec2& q : pts) p.push_back(q + shift);
    return p;
  };
  in.geometry.blocks.push_back(make_block(at({{295.0, 128.29518},
                                              {295.27006, 128.29518},
                                              {295.27006, 129.00913},
                                              {294.69801, 129.00913},
                                              {294.69801, 129.0},
                                              {295.0, 129.0}})));
  in.geometry.blocks.push_back(
      make_block(at({{293.0, 128.29518}, {294.69801, 128.29518}, {294.69801, 129.00913}, {293.0, 129.00913}})));
  in.geometry.blocks.push_back(
      make_block(at({{293.44099, 129.00913}, {294.70397, 129.00913}, {294.70397, 130.64742}, {293.44099, 130.64742}})));
  in.materials = {test::rock(2300, 15.3e9)};
  in.joint_sets = {JointProperties{}};
  in.joint_sets[0].friction_deg = 30;
  in.control.dt = 1e-4;
  in.control.steps = 20;
  in.control.max_displacement_ratio = 0.0005;
  in.control.w0 = 20;
  for (const Vec2& p : {Vec2(295.05, 128.4), Vec2(295.2, 128.4), Vec2(295.2, 128.9)})
    in.fixed_points.push_back({"arm", p + shift, 0, {}});
  for (const Vec2& p : {Vec2(293.1, 128.4), Vec2(294.6, 128.4), Vec2(293.1, 128.9)})
    in.fixed_points.push_back({"beside", p + shift, 1, {}});
  Simulation sim(build_model(in));
  sim.run();
  const EnergyCreated worst = most_energy_created(sim.energy_log());
  const double speed = sim.blocks()[2].velocity.head<2>().norm();
  std::printf("thin arm: worst residual %.3g J of %.3g J moved at t = %.4g s; upper block at %.3g m/s\n",
              worst.residual, worst.scale, worst.time, speed);
  EXPECT_GT(worst.ratio(), -0.01);
  EXPECT_LT(speed, 9.81 * 20 * 1e-4);
}

TEST(Runaway, AbsurdLoadStopsTheRunWithADiagnosis) {
  // 1e200 N on a 1 x 1 m block: even at the smallest dt it would move
  // 1e190 m in a step, far beyond the model: RunawayError, not garbage.
  ModelInput in;
  in.geometry.blocks.push_back(make_block(rectangle(0, 0, 1, 1)));
  in.materials = {test::rock()};
  in.control.dt = 1e-3;
  in.loads.push_back({"absurd", {0.5, 0.5}, {1e200, 0}, -1});
  Simulation sim(build_model(in));
  try {
    sim.step();
    FAIL() << "no RunawayError";
  } catch (const RunawayError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.step(), 1);
    EXPECT_EQ(e.block(), 0);
    EXPECT_NE(what.find("block 0"), std::string::npos) << what;
    EXPECT_NE(what.find("smaller time step"), std::string::npos) << what;
  }
  EXPECT_EQ(sim.log().size(), 0u);  // nothing was accepted
}

TEST(Runaway, NonFiniteSolutionStopsTheRun) {
  // Two loads of 1e308 N at one point overflow the right-hand side (their
  // sum is infinite): the solution is not finite, the run stops at once.
  ModelInput in;
  in.geometry.blocks.push_back(make_block(rectangle(0, 0, 1, 1)));
  in.geometry.blocks.push_back(make_block(rectangle(3, 0, 1, 1)));
  in.materials = {test::rock()};
  in.control.dt = 1e-3;
  in.loads.push_back({"absurd", {3.5, 0.5}, {1e308, 0}, -1});
  in.loads.push_back({"absurd too", {3.5, 0.5}, {1e308, 0}, -1});
  Simulation sim(build_model(in));
  try {
    sim.step();
    FAIL() << "no RunawayError";
  } catch (const RunawayError& e) {
    EXPECT_EQ(e.block(), 1);
    EXPECT_NE(std::string(e.what()).find("not a finite number"), std::string::npos) << e.what();
  }
}

TEST(StressRotation, TensorTurnsWithTheBlock) {
  // sigma' = R sigma R^T: uniaxial sx turned by 90 degrees becomes sy; by
  // 45 degrees it is (s/2, s/2, s/2); the invariants stay.
  const Vector3d sx(1e6, 0, 0);
  const Vector3d r90 = rotate_stress(sx, M_PI / 2);
  EXPECT_NEAR(r90[0], 0, 1e-9);
  EXPECT_NEAR(r90[1], 1e6, 1e-9);
  EXPECT_NEAR(r90[2], 0, 1e-9);
  const Vector3d r45 = rotate_stress(sx, M_PI / 4);
  EXPECT_NEAR(r45[0], 5e5, 1e-9);
  EXPECT_NEAR(r45[1], 5e5, 1e-9);
  EXPECT_NEAR(r45[2], 5e5, 1e-9);
  const Vector3d s(3e6, -1e6, 2e6), r = rotate_stress(s, 0.3);
  EXPECT_NEAR(r[0] + r[1], s[0] + s[1], 1e-6);
  EXPECT_NEAR(r[0] * r[1] - r[2] * r[2], s[0] * s[1] - s[2] * s[2], 1e-12 * 7e12);
}

// A 3 x 1 m beam cut at x = 1: the left part is held by fixed points, the
// right part (2 x 1 m) sticks out. `set` is the joint set of the cut.
ModelInput cantilever(int set) {
  ModelInput in;
  Block left = make_block(rectangle(0, 0, 1, 1), kBoundarySet);
  Block right = make_block(rectangle(1, 0, 2, 1), kBoundarySet);
  left.edge_set[1] = set;   // (1,0) -> (1,1)
  right.edge_set[3] = set;  // (1,1) -> (1,0)
  in.geometry.blocks = {left, right};
  in.materials = {test::rock(2000, 1e10)};
  in.control.dt = 1e-3;
  for (const Vec2& p : {Vec2(0.2, 0.2), Vec2(0.8, 0.2), Vec2(0.5, 0.8)}) in.fixed_points.push_back({"f", p, 0, {}});
  in.measurements.push_back({"tip", {2.9, 0.5}, 1});
  return in;
}

TEST(Glue, ArtificialCutNeverOpens) {
  // DC's artificial cut (set kArtificialSet) ties the two parts: the right
  // part hangs on it as a cantilever (its tip sags by the penalty
  // compliance only, < 1 mm). The same cut as an ordinary boundary lets it
  // fall (more than 0.1 m in 0.3 s).
  Simulation glued(build_model(cantilever(kArtificialSet)));
  glued.run_until(0.3);
  int locked = 0;
  for (const Contact& c : glued.contacts()) {
    EXPECT_TRUE(c.glued);
    EXPECT_NE(c.state, ContactState::Open);
    locked += c.state == ContactState::Locked;
  }
  EXPECT_GE(locked, 2);
  const double sag = glued.histories()[0].back().displacement.norm();
  Simulation loose(build_model(cantilever(kBoundarySet)));
  loose.run_until(0.3);
  const double fall = loose.histories()[0].back().displacement.norm();
  std::printf("glue: tip sag %.3e m; without glue %.3f m\n", sag, fall);
  EXPECT_LE(sag, 1e-3);
  EXPECT_GE(fall, 0.1);
}

// A law that remembers what it was asked.
class RecordingLaw final : public FrictionLaw {
 public:
  std::string name() const override { return "recording"; }
  double strength(const FrictionInput& in, const FrictionState& /*state*/) const override {
    last = in;
    return 0.1 * in.normal_force;
  }
  mutable FrictionInput last;
};

TEST(FrictionInterface, LawSeesTheSlipVelocityOfTheCurrentIterate) {
  // A block sliding on a base: after update_contact with increments di, dj
  // the law must have been asked with |es.di + gc.dj| / dt (the relative
  // sliding speed of this iterate) and the iterate's normal force.
  const Polygon2 base = rectangle(-1, -1, 3, 1), top = rectangle(0, -1e-4, 1, 1);
  const Vec2 cb = block_geometry(base).centroid, ct = block_geometry(top).centroid;
  Contact c;
  c.vblock = 1, c.vertex = 0, c.eblock = 0, c.edge = 2;
  c.state = ContactState::Sliding;
  c.slip_sign = -1;
  c.geo = contact_geometry(top, ct, base, cb, 0, 2, 0.5);
  RecordingLaw law;
  const ContactLaw cl{1e9, 1e9, 0, &law};
  Vector6d di = Vector6d::Zero(), dj = Vector6d::Zero();
  di[0] = 2e-5;   // P moves +x by 20 um: along -t of the top edge (1,0) -> (-1,0)
  di[1] = -1e-5;  // and 10 um further into the base
  const double dt = 1e-3;
  EXPECT_EQ(update_contact(c, cl, dt, di, dj), ContactState::Sliding);
  EXPECT_NEAR(law.last.slip_velocity, 2e-5 / dt, 1e-12);
  EXPECT_NEAR(law.last.normal_force, 1e9 * (1e-4 + 1e-5), 1e-3);
  EXPECT_NEAR(c.slip_velocity, 2e-5 / dt, 1e-12);
}

TEST(FrictionInterface, StateHasAPlainForm) {
  FrictionState s;
  s.theta = 0.25;
  s.slip = 1.5;
  s.extra = {3, 4};
  const std::vector<double> v = s.to_vector();
  ASSERT_EQ(v.size(), 4u);
  const FrictionState back = FrictionState::from_vector(v);
  EXPECT_EQ(back.theta, 0.25);
  EXPECT_EQ(back.slip, 1.5);
  EXPECT_EQ(back.extra, s.extra);
  EXPECT_THROW(FrictionState::from_vector({1.0}), InputError);
}

}  // namespace
}  // namespace dda::df
