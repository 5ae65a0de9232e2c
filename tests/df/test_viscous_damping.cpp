// Viscous damping with a stated damping ratio (control.damping, damping.hpp),
// 2D and 3D: a free square (cube) vibrating in its stretch mode must lose
// amplitude at the stated ratio, rigid motion must not be slowed, and in 2D
// the energy ledger must book the dissipated work.
//
// The mode: a block of side a, Poisson's ratio 0, no gravity, no contacts,
// started with a strain rate ex only. The displacement field is u = ex x
// (x from the centroid), so its mass is rho * integral of x^2 = rho a^4 / 12
// (2D, per unit thickness; rho a^5 / 12 in 3D) against the stiffness E a^2
// (E a^3): omega^2 = 12 E / (rho a^2), independent of the dimension, and
// ex decouples from every other unknown (a square's product moment is 0
// and nu = 0 uncouples the strains). With C = beta K_e the mode's damping
// ratio is beta omega / 2 (Chopra, Dynamics of Structures, Rayleigh
// damping), so giving the ratio at the mode's own frequency must give it.
//
// DDA's step (constant acceleration, v1 = 2 d / dt - v0, equilibrium at the
// end) damps too: about omega dt / 4 of critical for omega dt << 1 (a
// Newmark step with gamma = 1). At 1,000 steps a period that is 0.16 %,
// measured here with no viscous damping and subtracted; the difference must
// be the stated ratio within 0.2 % of it (the step's discretisation of the
// dashpot is second order: (omega dt)^2 = 4e-5; measured: equal to 5 digits).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "df_test_models3d.hpp"
#include "df_test_models.hpp"
#include "dda/df/core/damping.hpp"
#include "dda/df/2d/simulation.hpp"
#include "dda/df/3d/simulation3d.hpp"

namespace dda::df {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kE = 1e9, kRho = 2600, kSide = 1.0;
const double kOmega = std::sqrt(12 * kE / (kRho * kSide * kSide));  // 2148 rad/s
const double kHz = kOmega / (2 * kPi);                               // 342 Hz
const double kDt = 2 * kPi / kOmega / 1000;                          // 1,000 steps a period
constexpr int kPeriods = 6;

// Damping ratio from the positive peaks of a free vibration: the mean
// logarithmic decrement delta per cycle, zeta = delta / sqrt(4 pi^2 + delta^2).
double damping_ratio_of(const std::vector<double>& s, int periods = kPeriods) {
  std::vector<double> peaks;
  for (std::size_t k = 1; k + 1 < s.size(); ++k)
    if (s[k] > 0 && s[k] > s[k - 1] && s[k] >= s[k + 1]) peaks.push_back(s[k]);
  EXPECT_GE(peaks.size(), static_cast<std::size_t>(periods - 1));
  if (peaks.size() < 2) return -1;
  const double delta = std::log(peaks.front() / peaks.back()) / static_cast<double>(peaks.size() - 1);
  return delta / std::sqrt(4 * kPi * kPi + delta * delta);
}

ModelInput square(const ViscousDamping& damping) {
  ModelInput in;
  in.geometry.blocks.push_back(test::make_block(test::rectangle(0, 0, kSide, kSide)));
  Material rock = test::rock(kRho, kE);
  rock.poisson = 0;
  in.materials = {rock};
  in.gravity = {0, 0};
  in.control.dt = kDt;
  in.control.damping = damping;
  Vector6d v0 = Vector6d::Zero();
  v0[3] = 1e-3;  // ex rate, 1/s: an amplitude of 5e-7 (0.2 um)
  in.initial_velocity = {v0};
  return in;
}

// sx of the block after every step of kPeriods periods.
std::vector<double> stress_history_2d(Simulation& sim) {
  std::vector<double> sx;
  for (int s = 0; s < 1000 * kPeriods; ++s) sx.push_back(sim.step().step > 0 ? sim.blocks()[0].stress[0] : 0.0);
  return sx;
}

std::vector<double> stress_history_2d(const ViscousDamping& damping) {
  Simulation sim(build_model(square(damping)));
  return stress_history_2d(sim);
}

TEST(ViscousDamping, RatioIsBetaOmegaOverTwo) {
  const ViscousDamping d{0.05, 10.0};
  EXPECT_NEAR(d.beta(), 0.05 / (kPi * 10.0), 1e-18);
  EXPECT_NEAR(d.beta() * 2 * kPi * 10.0 / 2, 0.05, 1e-15);  // beta omega / 2 at the stated frequency
  EXPECT_NEAR(d.ratio_at(20.0), 0.10, 1e-15);              // stiffness-proportional: twice at twice
  EXPECT_EQ(ViscousDamping{}.beta(), 0.0);
}

TEST(ViscousDamping, FreeSquareLosesAmplitudeAtTheStatedRatio2D) {
  const double numerical = damping_ratio_of(stress_history_2d({}));
  // The step's own damping, about omega dt / 4 = 0.16 % here.
  EXPECT_NEAR(numerical, 2 * kPi / 1000 / 4, 0.1 * 2 * kPi / 1000 / 4);  // omega dt / 4
  for (const double stated : {0.02, 0.05, 0.10}) {
    const double total = damping_ratio_of(stress_history_2d({stated, kHz}));
    std::printf("2D: stated %.3f, measured %.6f (numerical %.6f)\n", stated, total - numerical, numerical);
    EXPECT_NEAR(total - numerical, stated, 0.002 * stated);
  }
  // Stated at twice the mode's frequency, the mode gets half of it.
  const double half = damping_ratio_of(stress_history_2d({0.10, 2 * kHz})) - numerical;
  EXPECT_NEAR(half, 0.05, 0.002 * 0.05);
}

TEST(ViscousDamping, LedgerBooksTheDampedWork2D) {
  // The work of the damping stress is the energy the mode loses beyond the
  // step's own loss: damping + residual = the fall of kinetic + elastic
  // energy, and the residual is the undamped run's (the step's numerical
  // dissipation) scaled by the energy left, so it stays a small part.
  Simulation sim(build_model(square({0.05, kHz})));
  stress_history_2d(sim);
  const EnergyRecord& start = sim.energy_log().front();
  const EnergyRecord& end = sim.energy_log().back();
  const double lost = start.stored() - end.stored();
  std::printf("2D ledger: stored %.4e -> %.4e J, damping %.4e J, residual %.4e J\n", start.stored(), end.stored(),
              end.damping, end.residual);
  // After 6 periods at 5 % the energy left is exp(-4 pi 0.05 6) = 2.3 %.
  EXPECT_NEAR(end.stored() / start.stored(), std::exp(-4 * kPi * 0.05 * kPeriods), 0.01);
  EXPECT_NEAR(end.damping + end.residual, lost, 1e-9 * start.stored());
  // The viscous share: 0.05 of the 0.0516 total ratio (measured above).
  EXPECT_GT(end.damping, 0.9 * lost);
  EXPECT_LT(end.damping, lost);
}

TEST(ViscousDamping, RigidMotionIsNotSlowed2D) {
  // A spinning, translating block keeps its speed exactly: the damping
  // acts on strain rates only (dynamic < 1 or mass-proportional damping
  // would slow it).
  ModelInput in = square({0.2, 1.0});
  Vector6d v0 = Vector6d::Zero();
  v0 << 1.0, -2.0, 3.0, 0, 0, 0;
  in.initial_velocity = {v0};
  in.control.dt = 1e-3;
  Simulation sim(build_model(in));
  for (int s = 0; s < 200; ++s) sim.step();
  EXPECT_NEAR(sim.blocks()[0].velocity[0], 1.0, 1e-9);
  EXPECT_NEAR(sim.blocks()[0].velocity[1], -2.0, 1e-9);
  EXPECT_NEAR(sim.blocks()[0].velocity[2], 3.0, 1e-9);
  EXPECT_NEAR(sim.energy_log().back().damping, 0.0, 1e-12);
}

// 3D: the same mode in a cube. A 3D step costs more than a 2D one (a
// factorisation of 12 unknowns with its set-up), so 200 steps a period and 4
// periods: the step's own damping is then 0.8 % and the dashpot's
// discretisation error (omega dt)^2 = 1e-3 of the ratio.
constexpr int kSteps3 = 200, kPeriods3 = 4;

std::vector<double> stress_history_3d(const ViscousDamping& damping) {
  const double dt = 2 * kPi / kOmega / kSteps3;
  df3::Model3 m;
  m.blocks = {df3::testing::box({-kSide / 2, -kSide / 2, -kSide / 2}, {kSide / 2, kSide / 2, kSide / 2})};
  m.materials = {df3::Material3{kRho, kE, 0.0}};
  m.gravity = Vec3::Zero();
  m.control.dt = dt;
  m.control.damping = damping;
  df3::Vector12d v0 = df3::Vector12d::Zero();
  v0[df3::kStrain] = 1e-3;  // ex rate
  m.initial_velocity = {v0};
  df3::Simulation3 sim(m);
  std::vector<double> sx;
  for (int s = 0; s < kSteps3 * kPeriods3; ++s) {
    sim.step(dt);
    sx.push_back(sim.stresses()[0][0]);
  }
  return sx;
}

TEST(ViscousDamping, FreeCubeLosesAmplitudeAtTheStatedRatio3D) {
  const double numerical = damping_ratio_of(stress_history_3d({}), kPeriods3);
  EXPECT_NEAR(numerical, 2 * kPi / kSteps3 / 4, 0.1 * 2 * kPi / kSteps3 / 4);  // omega dt / 4
  const double total = damping_ratio_of(stress_history_3d({0.05, kHz}), kPeriods3);
  std::printf("3D: stated 0.05, measured %.6f (numerical %.6f)\n", total - numerical, numerical);
  EXPECT_NEAR(total - numerical, 0.05, 0.005 * 0.05);
}

}  // namespace
}  // namespace dda::df
