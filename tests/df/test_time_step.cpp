// The default time step (time_step.hpp): the P-wave crossing time of the
// median block, or the loading's sample interval if that is shorter. The
// expected numbers are worked by hand from the formulas in the header.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "df_test_models.hpp"
#include "dda/common/error.hpp"
#include "dda/df/2d/model.hpp"
#include "dda/df/core/time_step.hpp"

namespace dda::df {
namespace {

TEST(DefaultTimeStep, PWaveSpeedOfTheDimension) {
  // E 1 GPa, nu 0.25, rho 2500: M = E (1 - nu) / ((1 + nu)(1 - 2 nu)) =
  // 1.2 GPa, c = sqrt(1.2e9 / 2500) = 692.82 m/s; plane stress
  // M = E / (1 - nu^2) = 1.0667 GPa, c = 653.20 m/s.
  EXPECT_NEAR(p_wave_speed(1e9, 0.25, 2500, false), 692.820323, 1e-6);
  EXPECT_NEAR(p_wave_speed(1e9, 0.25, 2500, true), 653.197265, 1e-6);
  // nu = 0: both are sqrt(E / rho).
  EXPECT_NEAR(p_wave_speed(1e9, 0.0, 2500, true), std::sqrt(4e5), 1e-9);
}

TEST(DefaultTimeStep, MedianBlockNotTheSliver) {
  // Crossing times 1, 2 and 0.01 ms: one sliver must not set the step.
  const TimeStepChoice c = default_time_step({{1.0, 1000}, {2.0, 1000}, {0.01, 1000}}, 0.0);
  EXPECT_DOUBLE_EQ(c.dt, 1e-3);
  EXPECT_NE(c.basis.find("crosses the median block (1 m) in 0.001 s"), std::string::npos) << c.basis;
  // Of two, the lower.
  EXPECT_DOUBLE_EQ(default_time_step({{1.0, 1000}, {2.0, 1000}}, 0.0).dt, 1e-3);
}

TEST(DefaultTimeStep, LoadingSampledFinerWins) {
  const TimeStepChoice c = default_time_step({{1.0, 1000}}, 2e-4);
  EXPECT_DOUBLE_EQ(c.dt, 2e-4);
  EXPECT_NE(c.basis.find("the loading's sample interval, 0.0002 s"), std::string::npos) << c.basis;
  // A coarser table (a load ramp over 10 s) does not lengthen the step.
  EXPECT_DOUBLE_EQ(default_time_step({{1.0, 1000}}, 10.0).dt, 1e-3);
  EXPECT_DOUBLE_EQ(shortest_interval({0.0, 0.01, 0.015, 0.03}), 0.005);
  EXPECT_EQ(shortest_interval({1.0}), 0.0);
  // Times read as decimals: the interval as written, exactly (0.3 - 0.2 is
  // 0.09999999999999998 in doubles; a 12 s record at 1 kHz written with three
  // decimals has a shortest difference of 0.0009999999999994458).
  EXPECT_EQ(shortest_interval({0.2, 0.3, 0.4}), 0.1);
  std::vector<double> kilohertz;
  for (int k = 0; k <= 12000; ++k) kilohertz.push_back(std::stod(std::to_string(k / 1000.0).substr(0, 6)));
  EXPECT_EQ(shortest_interval(kilohertz), 0.001);
  EXPECT_THROW(default_time_step({}, 0.0), InputError);
}

TEST(DefaultTimeStep, BuildModelTakesItWhenDtIsNotGiven) {
  // A 2 x 2 m block of the test rock (rho 2000, E 1 GPa, nu 0.25, plane
  // stress): c = sqrt(1.0667e9 / 2000) = 730.30 m/s, size 2 m, dt = 2.7386 ms.
  ModelInput in;
  in.geometry.blocks.push_back(test::make_block(test::rectangle(0, 0, 2, 2)));
  in.materials = {test::rock()};
  in.control.dt = 0;
  const Model m = build_model(in);
  EXPECT_NEAR(m.control.dt, 2.0 / std::sqrt(1e9 / (1 - 0.0625) / 2000), 1e-12);
  EXPECT_NEAR(m.control.dt, 2.7386e-3, 1e-7);
  EXPECT_FALSE(m.control.dt_basis.empty());
  // With an earthquake sampled every 1 ms (body acceleration table), 1 ms.
  BodyAcceleration quake;
  quake.history.t = {0, 0.001, 0.002};
  quake.history.value = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 0)};
  quake.blocks = {0};
  in.body_acceleration = quake;
  EXPECT_DOUBLE_EQ(build_model(in).control.dt, 0.001);
  // Given, it is kept and no reason is made up.
  in.control.dt = 0.01;
  EXPECT_DOUBLE_EQ(build_model(in).control.dt, 0.01);
  EXPECT_TRUE(build_model(in).control.dt_basis.empty());
}

}  // namespace
}  // namespace dda::df
