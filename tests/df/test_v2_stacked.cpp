// V2 (docs/validation.md): two stacked blocks of equal mass on a 30-degree plane,
// base friction phi1 = 20, interface friction phi2 = 10. Rigid-block values:
// a_B = g (sin a - tan phi2 cos a) = 3.40698 m/s^2,
// a_A = g [sin a - tan phi1 cos a - (tan phi1 - tan phi2) cos a] = 0.21865 m/s^2,
// so s = a t^2 / 2 at t = 1 s: 1.70349 m (B) and 0.10933 m (A).
#include <gtest/gtest.h>

#include "df_test_models.hpp"
#include "dda/df/2d/simulation.hpp"

namespace dda::df {
namespace {

TEST(V2, StackedBlocksSlideAtTheirOwnAccelerations) {
  const double a = deg2rad(30.0);
  ModelInput in;
  // Slope frame, downhill = local -x. Plane edges: joint set 0 (phi1); block
  // A (4 m x 0.25 m, area 1) and block B (1 m x 1 m, area 1): set 1 (phi2).
  // A contact takes the joint set of its edge, so A on the plane uses phi1
  // and B on A uses phi2. A is long enough for B to stay on it for 1 s.
  in.geometry.blocks.push_back(test::make_block(test::rotated(test::rectangle(0, -1, 8, 1), a), 0));
  in.geometry.blocks.push_back(test::make_block(test::rotated(test::rectangle(3, 0, 4, 0.25), a), 1));
  in.geometry.blocks.push_back(test::make_block(test::rotated(test::rectangle(5.8, 0.25, 1, 1), a), 1));
  in.materials = {test::rock(2000, 5e10)};
  JointProperties phi1, phi2;
  phi1.friction_deg = 20;
  phi2.friction_deg = 10;
  in.joint_sets = {phi1, phi2};
  in.control.dt = 1e-3;
  for (const double x : {0.5, 4.0, 7.5}) in.fixed_points.push_back({"base", test::rotated(Vec2(x, -0.5), a), 0, {}});
  in.measurements.push_back({"A", test::rotated(Vec2(5.0, 0.125), a), 1});
  in.measurements.push_back({"B", test::rotated(Vec2(6.3, 0.75), a), 2});
  Simulation sim(build_model(in));
  sim.run_until(1.0);
  const double sa = sim.histories()[0].back().displacement.norm();
  const double sb = sim.histories()[1].back().displacement.norm();
  const double ea = 0.21865 / 2, eb = 3.40698 / 2;
  std::printf("V2: s_A=%.6f (expected %.6f, rel.err %.2e)  s_B=%.6f (expected %.6f, rel.err %.2e)\n", sa, ea,
              std::abs(sa - ea) / ea, sb, eb, std::abs(sb - eb) / eb);
  EXPECT_LE(std::abs(sa - ea) / ea, 0.01);
  EXPECT_LE(std::abs(sb - eb) / eb, 0.01);
}

}  // namespace
}  // namespace dda::df
