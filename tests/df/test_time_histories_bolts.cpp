// Time histories of loads and fixed points, and rock bolts (model.hpp,
// bolts.hpp). Expected values are closed forms given in each test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "df_test_models.hpp"
#include "dda/common/error.hpp"
#include "dda/df/2d/simulation.hpp"

namespace dda::df {
namespace {

using test::make_block;
using test::rectangle;

TEST(TimeHistory, InterpolatesAndAveragesExactly) {
  // Table (0, 0) -> (1, 10) -> (3, 10) in x: a ramp then a plateau.
  TimeHistory h{{0, 1, 3}, {{0, 0}, {10, -2}, {10, -2}}};
  EXPECT_NEAR(h.at(-1).x(), 0, 1e-15);     // before the first time: the first value
  EXPECT_NEAR(h.at(0.25).x(), 2.5, 1e-12);
  EXPECT_NEAR(h.at(0.25).y(), -0.5, 1e-12);
  EXPECT_NEAR(h.at(7).x(), 10, 1e-15);     // after the last: the last value
  // Mean over [0.5, 2]: (integral 0.5..1 of 10 t = 3.75) + (10 * 1) = 13.75, / 1.5.
  EXPECT_NEAR(h.average(0.5, 2).x(), 13.75 / 1.5, 1e-12);
  EXPECT_NEAR(h.average(2, 2).x(), 10, 1e-15);
}

TEST(TimeHistory, BadTablesAreInputErrors) {
  ModelInput in;
  in.geometry.blocks.push_back(make_block(rectangle(0, 0, 1, 1)));
  in.control.dt = 1e-3;
  in.loads.push_back({"p", {0.5, 0.5}, {0, 0}, -1, TimeHistory{{0, 1, 1}, {{0, 0}, {1, 0}, {2, 0}}}});
  EXPECT_THROW(build_model(in), InputError);  // times do not increase
  in.loads[0].history = TimeHistory{{0, 1}, {{0, 0}}};
  EXPECT_THROW(build_model(in), InputError);  // fewer values than times
}

TEST(TimeHistory, LoadRampMovesFreeBlockAsT3Over6m) {
  // V8-style pushed block, with a ramp F = a t (a = 1000 N/s) at the
  // centroid of a free 1 x 1 m block of mass m = 2000 kg (no gravity):
  // s(t) = a t^3 / (6 m) = 0.0833333 m at t = 1 s. Each step applies the
  // table's mean over the step, so velocities are exact; the constant force
  // within a step leaves a displacement error of a dt^3 / (12 m) per step,
  // a t dt^2 / (12 m) = 4.2e-6 m in all (measured: 4.17e-6, 5.0e-5 relative).
  ModelInput in;
  in.geometry.blocks.push_back(make_block(rectangle(0, 0, 1, 1)));
  in.materials = {test::rock(2000, 1e10)};
  in.gravity = {0, 0};
  in.control.dt = 1e-2;
  const double a = 1000, m = 2000;
  in.loads.push_back({"ramp", {0.5, 0.5}, {0, 0}, -1, TimeHistory{{0, 2}, {{0, 0}, {2 * a, 0}}}});
  in.measurements.push_back({"c", {0.5, 0.5}, -1});
  Simulation sim(build_model(in));
  sim.run_until(1.0);
  const MeasurementSample& s = sim.histories()[0].back();
  const double expected = a / (6 * m);
  std::printf("load ramp: s=%.9f expected=%.9f\n", s.displacement.x(), expected);
  EXPECT_NEAR(s.displacement.x(), expected, 1e-4 * expected);
  EXPECT_NEAR(s.velocity.x(), a / (2 * m), 1e-9);  // v = a t^2 / (2 m), exact
  EXPECT_NEAR(s.displacement.y(), 0, 1e-12);
}

TEST(TimeHistory, BlockDraggedByMovingFixedPointFollowsIt) {
  // A 1 x 1 m block (2000 kg, E = 10 GPa) resting on a fixed base under
  // gravity; a fixed point at its centre moves u(t) = (0.2 t, 0) for 1 s,
  // then stays. The point's spring (p = 10 * 50 E = 5e12 N/m, both
  // directions) carries the block, which follows within its compliance:
  // the weight stretches it m g / p = 4 nm, and the sudden start of the
  // motion shakes it by v / omega = 0.2 / sqrt(p / m) = 4 um (measured
  // 3.0 um), which the integrator damps out. Bound: 10 um, and 1 um at the end.
  ModelInput in;
  in.geometry.blocks.push_back(make_block(rectangle(-2, -1, 5, 1)));
  in.geometry.blocks.push_back(make_block(rectangle(0, 0, 1, 1)));
  in.materials = {test::rock(2000, 1e10)};
  JointProperties j;
  j.friction_deg = 30;
  in.joint_sets = {j};
  in.control.dt = 1e-3;
  in.control.initial_equilibrium = true;
  for (const double x : {-1.5, 0.5, 2.5}) in.fixed_points.push_back({"base", {x, -0.5}, 0, {}});
  in.fixed_points.push_back({"drag", {0.5, 0.5}, 1, {}, TimeHistory{{0, 1}, {{0, 0}, {0.2, 0}}}});
  in.measurements.push_back({"c", {0.5, 0.5}, 1});
  Simulation sim(build_model(in));
  double worst = 0;
  while (sim.time() < 1.5 - 1e-9) {
    sim.step();
    const MeasurementSample& s = sim.histories()[0].back();
    const Vec2 u(0.2 * std::min(s.time, 1.0), 0);
    worst = std::max(worst, (s.displacement - u).norm());
  }
  std::printf("dragged block: worst |s - u| = %.3e m\n", worst);
  EXPECT_LE(worst, 1e-5);
  EXPECT_NEAR(sim.histories()[0].back().displacement.x(), 0.2, 1e-6);
}

// Two 1 x 1 m blocks (2000 kg each, E = 10 GPa), 1 m apart, no gravity, a
// bolt between their centres (L0 = 2 m), stiffness k = 1e6 N/m,
// pretension T0 = 1e4 N.
ModelInput two_bolted_blocks(double dt, double dynamic) {
  ModelInput in;
  in.geometry.blocks.push_back(make_block(rectangle(0, 0, 1, 1)));
  in.geometry.blocks.push_back(make_block(rectangle(2, 0, 1, 1)));
  in.materials = {test::rock(2000, 1e10)};
  in.gravity = {0, 0};
  in.control.dt = dt;
  in.control.dynamic = dynamic;
  in.control.max_displacement_ratio = 0.1;
  // The pretension acts from t = 0: the tests follow the bolt through what
  // it does then (the start-up relaxation would take it up before t = 0).
  in.control.initial_equilibrium = false;
  Bolt b;
  b.name = "b";
  b.anchor = {0.5, 0.5};
  b.head = {2.5, 0.5};
  b.stiffness = 1e6;
  b.pretension = 1e4;
  in.bolts.push_back(b);
  return in;
}

TEST(Bolts, PretensionedBoltSettlesAtItsFreeLength) {
  // Static analysis (k = 0): the bolt shortens until its force vanishes,
  // L = L0 - T0 / k = 1.99 m.
  Simulation sim(build_model(two_bolted_blocks(0.1, 0.0)));
  for (int s = 0; s < 60; ++s) sim.step();
  const BoltSample& last = sim.bolt_histories()[0].back();
  std::printf("bolt static: L=%.9f T=%.3e\n", last.length, last.force);
  EXPECT_NEAR(last.length, 1.99, 1e-6);
  EXPECT_NEAR(last.force, 0, 1.0);  // N (1e-4 of T0)
  EXPECT_NEAR(sim.bolt_histories()[0].front().force, 1e4, 1e-9);
}

TEST(Bolts, PretensionedBoltOscillatesAboutItsFreeLength) {
  // Fully dynamic: two masses on a spring released with force T0 oscillate
  // between L0 = 2 and L0 - 2 T0 / k = 1.98 m with period 2 pi sqrt(mu / k),
  // mu = m / 2 = 1000 kg: first minimum at t = pi sqrt(mu / k) = 0.09935 s.
  // The integrator's damping is (omega dt) / 4 = 0.16 % at dt = 0.2 ms.
  Simulation sim(build_model(two_bolted_blocks(2e-4, 1.0)));
  sim.run_until(0.15);
  double lmin = 10, tmin = 0;
  for (const BoltSample& s : sim.bolt_histories()[0])
    if (s.length < lmin) lmin = s.length, tmin = s.time;
  std::printf("bolt dynamic: Lmin=%.7f at t=%.5f\n", lmin, tmin);
  EXPECT_NEAR(2.0 - lmin, 0.02, 0.01 * 0.02);
  EXPECT_NEAR(tmin, M_PI * std::sqrt(1000 / 1e6), 0.02 * 0.09935);
}

// A 1 x 1 m block (2000 kg) hanging 0.5 m under a fixed 3 x 1 m roof block,
// a vertical bolt from the roof's centre to the block's centre, k = 1e7 N/m.
ModelInput hanging_block(double dynamic, std::optional<double> breaking) {
  ModelInput in;
  in.geometry.blocks.push_back(make_block(rectangle(-1, 1.5, 3, 1)));
  in.geometry.blocks.push_back(make_block(rectangle(0, 0, 1, 1)));
  in.materials = {test::rock(2000, 1e10)};
  in.control.dt = 1e-2;
  in.control.dynamic = dynamic;
  in.control.initial_equilibrium = false;  // the weight is taken up from t = 0, in the run
  for (const double x : {-0.5, 0.5, 1.5}) in.fixed_points.push_back({"roof", {x, 2.0}, 0, {}});
  Bolt b;
  b.name = "b";
  b.anchor = {0.5, 2.0};
  b.head = {0.5, 0.5};
  b.stiffness = 1e7;
  b.breaking_force = breaking;
  in.bolts.push_back(b);
  in.measurements.push_back({"c", {0.5, 0.5}, 1});
  return in;
}

TEST(Bolts, HangingBlockBoltCarriesItsWeight) {
  // Static analysis: T = m g = 2000 * 9.81 = 19620 N.
  Simulation sim(build_model(hanging_block(0.0, std::nullopt)));
  for (int s = 0; s < 100; ++s) sim.step();
  const double t = sim.bolts()[0].force, w = 2000 * 9.81;
  std::printf("hanging block: T=%.3f N, m g=%.3f N\n", t, w);
  EXPECT_NEAR(t, w, 0.01 * w);
  EXPECT_FALSE(sim.bolts()[0].broken);
}

TEST(Bolts, BoltWeakerThanTheWeightBreaksOnceAndTheBlockFalls) {
  // Breaking force m g / 2: the bolt breaks while taking up the weight,
  // stays broken, and the block then falls freely (0.3 s after release it
  // has fallen more than 0.3 m; g t^2 / 2 = 0.44 m).
  const double w = 2000 * 9.81;
  Simulation sim(build_model(hanging_block(1.0, 0.5 * w)));
  sim.run_until(0.3);
  const auto& h = sim.bolt_histories()[0];
  int breaks = 0;
  for (std::size_t k = 1; k < h.size(); ++k) {
    if (h[k].broken && !h[k - 1].broken) {
      ++breaks;
      EXPECT_GT(h[k - 1].force, 0.0);
    }
    if (h[k - 1].broken) {
      EXPECT_TRUE(h[k].broken);  // once broken, always broken
      EXPECT_EQ(h[k].force, 0.0);
    }
    if (!h[k].broken) {
      EXPECT_LE(h[k].force, 0.5 * w);
    }
  }
  EXPECT_EQ(breaks, 1);
  EXPECT_LT(sim.histories()[0].back().displacement.y(), -0.3);
}

TEST(Bolts, BadBoltsAreInputErrors) {
  ModelInput in = two_bolted_blocks(1e-3, 1.0);
  in.bolts[0].stiffness = 0;
  EXPECT_THROW(build_model(in), InputError);
  in = two_bolted_blocks(1e-3, 1.0);
  in.bolts[0].head = {0.6, 0.5};  // both ends in block 0
  EXPECT_THROW(build_model(in), InputError);
}

}  // namespace
}  // namespace dda::df
