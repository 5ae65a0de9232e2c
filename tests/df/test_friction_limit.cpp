// Friction at its limit (issue: "friction that holds at its limit"): a block
// on a plane whose friction angle is 0.1 degree above the slope angle must
// stay where it is. A rigid block at rest on such a plane has a factor of
// safety tan(phi) / tan(alpha) = 1.005 and does not move (docs/validation.md V1: no
// sliding once tan phi >= tan alpha), so the expected motion is the elastic
// compliance only, micrometres; the bound 1e-4 m over 2 s is the issue's.
//
// The block is b x b on a 30-degree plane, built in the slope frame and
// turned (as V1). Two rocks: E = 50 GPa (hard) and E = 1 GPa (the default
// Young's modulus of a scenario), both with the default penalty 50 E and
// dt = 1 ms.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "df_test_models.hpp"
#include "dda/df/2d/simulation.hpp"

namespace dda::df {
namespace {

constexpr double kAlpha = 30.0;  // degrees

// Slip along the slope between t = 0 and t = t_end, m (downhill negative).
// The run's histories start at t = 0, after the start-up relaxation, so
// this is the motion of the dynamic run alone.
double slip(double young, double block, bool initial_equilibrium, double t_end = 2.0, double dt = 1e-3,
            ViscousDamping damping = {}) {
  const double a = deg2rad(kAlpha);
  ModelInput in;
  in.geometry.blocks.push_back(test::make_block(test::rotated(test::rectangle(0, -2, 16, 2), a)));
  in.geometry.blocks.push_back(test::make_block(test::rotated(test::rectangle(8, 0, block, block), a)));
  in.materials = {test::rock(2600, young)};
  JointProperties j;
  j.friction_deg = kAlpha + 0.1;
  in.joint_sets = {j};
  in.control.dt = dt;
  in.control.initial_equilibrium = initial_equilibrium;
  in.control.damping = damping;
  for (const double x : {1.0, 8.0, 15.0}) in.fixed_points.push_back({"base", test::rotated(Vec2(x, -1), a), 0, {}});
  in.measurements.push_back({"slider", test::rotated(Vec2(8 + block / 2, block / 2), a), 1});
  Simulation sim(build_model(in));
  sim.start();
  if (initial_equilibrium) {
    EXPECT_TRUE(sim.start_up().frictional_equilibrium);
  }
  sim.run_until(t_end);
  const auto& h = sim.histories()[0];
  const Vec2 down = test::rotated(Vec2(1, 0), a);
  return (h.back().displacement - h.front().displacement).dot(down);
}

struct Rock {
  double young, block;
};

class FrictionLimit : public ::testing::TestWithParam<Rock> {};

// initial_equilibrium: the start-up relaxation lets the contacts that carry
// more shear than their friction allows slip before t = 0 (settle.cpp), so
// the run starts in frictional equilibrium and nothing moves. Before that
// relaxation the 5 m block of 1 GPa rock walked 0.44 m down the plane.
TEST_P(FrictionLimit, BlockStaysAfterTheStartUpRelaxation) {
  const Rock r = GetParam();
  const double s = slip(r.young, r.block, true);
  std::printf("E %.0e, block %.0f m, initial_equilibrium: slip %.3e m in 2 s\n", r.young, r.block, s);
  EXPECT_LT(std::abs(s), 1e-4);
}

INSTANTIATE_TEST_SUITE_P(Rocks, FrictionLimit,
                         ::testing::Values(Rock{5e10, 1}, Rock{5e10, 5}, Rock{1e9, 1}, Rock{1e9, 5}));

// Loads switched on at t = 0 make the 5 m block of 1 GPa rock walk 0.24 m
// down the plane (docs/solver2d.md, "Friction at its limit"): the undamped
// bounce into its springs. Viscous damping of the blocks' deformation
// (control.damping) takes the energy out of that bounce, so the walk must
// shrink as the ratio grows (measured at 5 Hz, near the block's rocking on
// its springs: 0.243 m, 16 mm, 8.3 mm, 2.1 mm for 0, 2, 5, 20 %), and 5 %
// must cut it at least tenfold.
TEST(FrictionLimitDamped, ViscousDampingHoldsBackTheWalkOfSuddenLoads) {
  std::vector<double> walk;
  for (const double ratio : {0.0, 0.02, 0.05, 0.2}) {
    walk.push_back(std::abs(slip(1e9, 5, false, 2.0, 1e-3, {ratio, 5.0})));
    std::printf("loads at t = 0, damping %.2f at 5 Hz: slip %.3e m in 2 s\n", ratio, walk.back());
  }
  for (std::size_t k = 1; k < walk.size(); ++k) EXPECT_LT(walk[k], walk[k - 1]) << "ratio " << k;
  EXPECT_LT(walk[2], 0.1 * walk[0]);
}

}  // namespace
}  // namespace dda::df
