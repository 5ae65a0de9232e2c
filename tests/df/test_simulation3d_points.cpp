// Points of the 3D solver (df/3d/points3d.hpp): measurement points, point
// loads, fixed and moving points, on one free 1 m cube (rho = 2600, so
// m = 2600 kg) without contacts. Expected numbers are Newton's laws for a
// rigid body, which the implicit constant-acceleration step integrates
// exactly for constant forces.
#include <gtest/gtest.h>

#include <cmath>

#include "dda/common/error.hpp"
#include "dda/df/3d/simulation3d.hpp"
#include "df_test_models3d.hpp"

namespace dda::df3 {
namespace {

Model3 one_cube(const Vec3& gravity) {
  Model3 m;
  m.blocks = {testing::box({0, 0, 0}, {1, 1, 1})};
  m.materials = {{2600, 1e10, 0.25}};
  m.gravity = gravity;
  m.control.initial_equilibrium = false;  // gravity switched on at t = 0: what the expected numbers assume
  return m;
}

TimeHistory3 constant(const Vec3& v) { return TimeHistory3{{0.0}, {v}}; }

// Free fall: the measurement point at a corner moves -g t^2 / 2 with speed
// -g t, exactly (no rotation), and its block carries no stress.
TEST(Simulation3Points, MeasurementPointFollowsFreeFall) {
  Model3 m = one_cube({0, 0, -9.81});
  m.measurements = {{"corner", 0, Vec3(1, 1, 1)}};
  Simulation3 sim(m);
  for (int s = 0; s < 100; ++s) sim.step(0.01);
  const auto& h = sim.histories()[0];
  ASSERT_EQ(h.size(), 101u);  // the start plus one sample per step
  const MeasurementSample3& last = h.back();
  EXPECT_NEAR(last.time, 1.0, 1e-12);
  EXPECT_LT((last.displacement - Vec3(0, 0, -9.81 / 2)).norm(), 1e-9);
  EXPECT_LT((last.velocity - Vec3(0, 0, -9.81)).norm(), 1e-9);
  EXPECT_LT((last.position - Vec3(1, 1, 1 - 9.81 / 2)).norm(), 1e-9);
  EXPECT_LT(last.stress.norm(), 1e-6);
}

// Kinetic energy (Simulation3::kinetic_energy, which the results keep with
// each frame): after 1 s of free fall 1/2 m (g t)^2 = 1/2 2600 9.81^2 J;
// then the same cube given a spin of 2 rad/s about the vertical through its
// centroid on top of a velocity (1, -2, 0.5) m/s: 1/2 m |v|^2 + 1/2 I w^2
// with I = m (1 + 1) / 12 for a unit cube, by hand 6825 + 866.67 J.
TEST(Simulation3Points, KineticEnergyIsHalfMV2PlusHalfIW2) {
  Simulation3 sim(one_cube({0, 0, -9.81}));
  EXPECT_EQ(sim.kinetic_energy(), 0.0);
  for (int s = 0; s < 100; ++s) sim.step(0.01);
  EXPECT_NEAR(sim.kinetic_energy(), 0.5 * 2600 * 9.81 * 9.81, 1e-9 * 2600 * 9.81 * 9.81);

  Simulation3 spin(one_cube({0, 0, 0}));
  SimulationState3 state = spin.state();
  state.velocity[0] << 1, -2, 0.5, 0, 0, 2, 0, 0, 0, 0, 0, 0;
  spin.restore(state);
  const double translation = 0.5 * 2600 * (1 + 4 + 0.25), rotation = 0.5 * (2600 * 2.0 / 12) * 4;
  EXPECT_NEAR(spin.kinetic_energy(), translation + rotation, 1e-9 * (translation + rotation));
}

// A constant force through the centroid: u = F t^2 / (2 m); a force that
// grows linearly in time (table 0 -> F over 1 s): u = F t^3 / (6 m).
TEST(Simulation3Points, PointLoadsAccelerateTheBlock) {
  const Vec3 f(2600, -5200, 1300);  // N: accelerations 1, -2, 0.5 m/s^2
  for (const bool ramp : {false, true}) {
    Model3 m = one_cube({0, 0, 0});
    m.loads = {{0, Vec3(0.5, 0.5, 0.5), ramp ? TimeHistory3{{0.0, 1.0}, {Vec3::Zero(), f}} : constant(f)}};
    m.measurements = {{"centre", 0, Vec3(0.5, 0.5, 0.5)}};
    Simulation3 sim(m);
    for (int s = 0; s < 50; ++s) sim.step(0.02);
    const Vec3 expected = ramp ? Vec3(f / 2600 / 6) : Vec3(f / 2600 / 2);
    EXPECT_LT((sim.histories()[0].back().displacement - expected).norm(), 1e-9 + (ramp ? 1e-4 : 0.0))
        << (ramp ? "ramp" : "constant");
  }
}

// A fixed point at the centroid holds the cube against gravity: it comes
// to rest W / p lower, p = 10 x the normal penalty by default (1e10 N/m).
// On the way it oscillates (omega = sqrt(p / m) = 1961 rad/s), less than
// the undamped 0 .. 2 W / p: DDA's step takes the spring force at the end
// of the step (implicit), which damps a mode with omega dt = 0.2 (dt =
// 0.1 ms) by about 15 % each half period (measured), the known numerical
// damping of DDA.
TEST(Simulation3Points, FixedPointHoldsTheBlock) {
  Model3 m = one_cube({0, 0, -9.81});
  m.fixed_points = {{0, Vec3(0.5, 0.5, 0.5), std::nullopt, 0.0}};
  m.measurements = {{"centre", 0, Vec3(0.5, 0.5, 0.5)}};
  Simulation3 sim(m);
  double sag = 0;
  for (int s = 0; s < 6400; ++s) {  // 20 periods
    sim.step(1e-4);
    sag = std::min(sag, sim.histories()[0].back().displacement.z());
  }
  const double w = 2600 * 9.81, p = 1e10;
  EXPECT_NEAR(sim.histories()[0].back().displacement.z(), -w / p, 0.01 * w / p);
  EXPECT_LT(sag, -1.5 * w / p);  // it did swing past the rest position
  EXPECT_GT(sag, -2 * w / p);    // and never beyond the undamped swing
}

// A moving point drags the cube along its path: after 1 s of motion at
// 0.1 m/s east the centre is 0.1 m east, within the spring's lag.
TEST(Simulation3Points, MovingPointCarriesTheBlock) {
  Model3 m = one_cube({0, 0, 0});
  TimeHistory3 path{{0.0, 1.0, 2.0}, {Vec3::Zero(), Vec3(0.1, 0, 0), Vec3(0.1, 0, 0)}};
  m.fixed_points = {{0, Vec3(0.5, 0.5, 0.5), path, 0.0}};
  m.measurements = {{"centre", 0, Vec3(0.5, 0.5, 0.5)}};
  Simulation3 sim(m);
  for (int s = 0; s < 1000; ++s) sim.step(1e-3);
  EXPECT_LT((sim.histories()[0].back().displacement - Vec3(0.1, 0, 0)).norm(), 1e-4);
}

TEST(Simulation3Points, BadPointsAreRefused) {
  Model3 m = one_cube({0, 0, 0});
  m.loads = {{3, Vec3::Zero(), constant(Vec3::Zero())}};
  EXPECT_THROW(Simulation3{m}, InputError);
  m = one_cube({0, 0, 0});
  m.fixed = {true};
  m.fixed_points = {{0, Vec3::Zero(), std::nullopt, 0.0}};
  EXPECT_THROW(Simulation3{m}, InputError);
  m = one_cube({0, 0, 0});
  m.loads = {{0, Vec3::Zero(), TimeHistory3{{1.0, 1.0}, {Vec3::Zero(), Vec3::Zero()}}}};
  EXPECT_THROW(Simulation3{m}, InputError);
}

TEST(TimeHistory3, InterpolatesAndAveragesExactly) {
  const TimeHistory3 h{{0.0, 1.0, 3.0}, {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 4, 0)}};
  EXPECT_LT((h.at(-1) - Vec3(0, 0, 0)).norm(), 1e-15);
  EXPECT_LT((h.at(0.5) - Vec3(1, 0, 0)).norm(), 1e-15);
  EXPECT_LT((h.at(2) - Vec3(2, 2, 0)).norm(), 1e-15);
  EXPECT_LT((h.at(9) - Vec3(2, 4, 0)).norm(), 1e-15);
  // Mean over [0.5, 2]: x: (0.5 * 1.5 + 1 * 2) / 1.5; y: (1 * 1) / 1.5.
  EXPECT_LT((h.average(0.5, 2) - Vec3(2.75 / 1.5, 1.0 / 1.5, 0)).norm(), 1e-14);
}

}  // namespace
}  // namespace dda::df3

namespace dda::df3 {
namespace {

// Step control (Control3, Simulation3::advance): a free cube falls for 1 s
// with dt = 0.05 s asked for. w0 = 0.5 m (half the model's largest side), so
// no vertex may move more than 0.005 m in a step: dt is cut as the cube
// speeds up, every accepted step keeps the limit, and the run ends exactly
// at total_time with the exact free fall (constant acceleration is
// integrated exactly at any dt).
TEST(Simulation3Control, StepsAreCutToTheDisplacementLimit) {
  Model3 m = one_cube({0, 0, -9.81});
  m.measurements = {{"centre", 0, Vec3(0.5, 0.5, 0.5)}};
  m.control.dt = 0.05;
  m.control.total_time = 1.0;
  Simulation3 sim(m);
  sim.run();
  EXPECT_NEAR(sim.time(), 1.0, 1e-12);
  EXPECT_LT((sim.histories()[0].back().displacement - Vec3(0, 0, -9.81 / 2)).norm(), 1e-9);
  int cuts = 0;
  for (const StepRecord3& s : sim.log()) {
    EXPECT_LE(s.max_displacement, 0.005 * (1 + 1e-9));
    cuts += s.dt_cuts;
  }
  EXPECT_GT(cuts, 0);
  // The step it ends with: 0.005 m at 9.81 m/s.
  EXPECT_LT(sim.log().back().dt, 0.0006);
}

TEST(Simulation3Control, BadControlIsRefused) {
  Model3 m = one_cube({0, 0, 0});
  m.control.dt = 0;
  EXPECT_THROW(Simulation3{m}, InputError);
}

}  // namespace
}  // namespace dda::df3
