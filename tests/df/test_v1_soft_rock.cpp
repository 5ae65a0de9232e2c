// V1 (docs/validation.md) with soft rock: a block on a 30-degree plane, E = 1 GPa and
// E = 15.3 GPa (the tunnel-roof rock of the seed report), default penalty
// 50 E, dt 0.1-1 ms. Expected s(1 s) = g (sin a - cos a tan phi) / 2 (rigid
// block, Coulomb; 0 once tan phi >= tan a).
//
// The block starts in equilibrium (Control::initial_equilibrium): the
// closed form assumes a block at rest on the plane, held and then released.
// Released with no contact force instead, a 1 GPa block slides nearly freely
// while its normal force builds up and keeps a 2.6 mm/s speed excess (2.7 %
// of s(1 s) at phi = 29, measured at dt = 1 ms; 12 % at dt = 0.2 ms, where
// its undamped bounce also makes it creep; see df/src/2d/settle.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "df_test_models.hpp"
#include "dda/df/2d/simulation.hpp"

namespace dda::df {
namespace {

constexpr double kAlpha = 30.0;  // degrees

// The V1 set-up of test_v1_sliding.cpp: 8 x 1 m plane held by three fixed
// points, 1 x 1 m slider 1 m from its upper end.
Simulation v1_model(double young, double dt, double phi_deg) {
  const double a = deg2rad(kAlpha);
  ModelInput in;
  in.geometry.blocks.push_back(test::make_block(test::rotated(test::rectangle(0, -1, 8, 1), a)));
  in.geometry.blocks.push_back(test::make_block(test::rotated(test::rectangle(6, 0, 1, 1), a)));
  in.materials = {test::rock(2000, young)};
  JointProperties j;
  j.friction_deg = phi_deg;
  in.joint_sets = {j};
  in.control.dt = dt;
  in.control.initial_equilibrium = true;
  for (const double x : {0.5, 4.0, 7.5}) in.fixed_points.push_back({"base", test::rotated(Vec2(x, -0.5), a), 0, {}});
  in.measurements.push_back({"slider", test::rotated(Vec2(6.5, 0.5), a), 1});
  return Simulation(build_model(in));
}

double expected_distance(double phi_deg) {
  const double a = deg2rad(kAlpha);
  const double acc = 9.81 * (std::sin(a) - std::cos(a) * std::tan(deg2rad(phi_deg)));
  return acc > 0 ? 0.5 * acc : 0.0;
}

struct SoftCase {
  double young, dt, phi;
};

class V1SoftRock : public ::testing::TestWithParam<SoftCase> {};

TEST_P(V1SoftRock, DistanceAtOneSecondWithinOnePercent) {
  // Measured relative errors (this code): 1 GPa: 9.0e-4 (phi 29, 0.2 ms),
  // 1.8e-4 (29, 1 ms), 1.4e-5 (25, 0.2 ms); 15.3 GPa: 5.5e-5 (29, 0.2 ms),
  // 6.3e-5 (29, 1 ms), 8.9e-5 (29, 0.1 ms).
  const SoftCase c = GetParam();
  Simulation sim = v1_model(c.young, c.dt, c.phi);
  sim.run_until(1.0);
  const double s = sim.histories()[0].back().displacement.norm();
  const double expected = expected_distance(c.phi);
  const double err = std::abs(s - expected) / expected;
  std::printf("V1 soft E=%g dt=%g phi=%g: s=%.6f expected=%.6f rel.err=%.2e (settle %d it.)\n", c.young, c.dt, c.phi,
              s, expected, err, sim.settle_iterations());
  EXPECT_LE(err, 0.01);
}

INSTANTIATE_TEST_SUITE_P(Cases, V1SoftRock,
                         ::testing::Values(SoftCase{1e9, 2e-4, 29}, SoftCase{1e9, 1e-3, 29}, SoftCase{1e9, 2e-4, 25},
                                           SoftCase{15.3e9, 2e-4, 29}, SoftCase{15.3e9, 1e-3, 29},
                                           SoftCase{15.3e9, 1e-4, 29}));

TEST(V1SoftRock, StaysAtThirtyFiveDegrees) {
  // phi = 35 > alpha: the block must stay. Without the initial equilibrium
  // a 1 GPa block at dt = 0.2 ms bounced and walked 8.5 mm down in 1 s.
  // What is left is the settling into the springs (9 um measured).
  Simulation sim = v1_model(1e9, 2e-4, 35);
  sim.run_until(1.0);
  const double s = sim.histories()[0].back().displacement.norm();
  std::printf("V1 soft E=1e9 dt=2e-4 phi=35: s=%.3e m\n", s);
  EXPECT_LE(s, 2e-5);
  EXPECT_LE(std::abs(sim.histories()[0].back().displacement.norm() - sim.histories()[0].front().displacement.norm()),
            1e-6);  // no creep after t = 0
}

TEST(V1SoftRock, RunStartsAtRestAfterTheInitialEquilibrium) {
  // The relaxation into equilibrium takes pseudo-steps (settle.cpp) whose
  // motion must not leak into the run: the first sample of a receiver, at
  // t = 0, shows no velocity and no acceleration ("0 at the start",
  // MeasurementSample). Before the fix the slider started with the
  // acceleration of the last pseudo-step.
  Simulation sim = v1_model(1e9, 2e-4, 29);
  sim.step();
  ASSERT_GT(sim.settle_iterations(), 0);
  const MeasurementSample& first = sim.histories()[0].front();
  EXPECT_EQ(first.time, 0.0);
  EXPECT_EQ(first.velocity, Vec2(0, 0));
  EXPECT_EQ(first.acceleration, Vec2(0, 0));
}

}  // namespace
}  // namespace dda::df
