// The 3D energy ledger (simulation3d_energy.cpp, df/core/energy.hpp): the same
// checks as the 2D ledger's (test_energy_runaway.cpp), on a 1 m cube
// (rho = 2600, m = 2600 kg) in free fall, sliding on a 20 deg plane, and
// carried by a shaking ground in both earthquake modes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

#include "dda/df/3d/simulation3d.hpp"
#include "df_test_models3d.hpp"

namespace dda::df3 {
namespace {

constexpr double kG = 9.81, kMass = 2600, kDeg = std::numbers::pi / 180;

// The cube on a 10 x 10 x 1 m fixed base, tilted `alpha_deg` about y (dip
// direction 90), gravity switched on at t = 0 unless relaxed first.
Model3 cube_on_plane(double alpha_deg, double phi_deg, bool initial_equilibrium) {
  const Eigen::Matrix3d r = testing::plane_rotation(alpha_deg, 90);
  Model3 m;
  m.blocks = {testing::box({-5, -5, -1}, {5, 5, 0}, r), testing::box({-0.5, -0.5, 0}, {0.5, 0.5, 1}, r)};
  m.fixed = {true, false};
  m.materials = {{kMass, 1e10, 0.25}};
  m.default_joint.friction_deg = phi_deg;
  m.normal_penalty = m.shear_penalty = 1e9;
  m.gravity = {0, 0, -kG};
  m.contact_reach = 0.01;
  m.control.initial_equilibrium = initial_equilibrium;
  return m;
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

// V8 free fall: no contacts, so gravity's work is the kinetic energy at
// every step (the constant-acceleration step is exact), and after 1 s both
// are m g (g t^2 / 2).
TEST(Energy3, FreeFallWorkIsTheKineticEnergy) {
  Model3 m;
  m.blocks = {testing::box({0, 0, 0}, {1, 1, 1})};
  m.materials = {{kMass, 1e10, 0.25}};
  m.gravity = {0, 0, -kG};
  m.control.initial_equilibrium = false;
  Simulation3 sim(m);
  for (int s = 0; s < 100; ++s) sim.step(0.01);
  const std::vector<df::EnergyRecord>& log = sim.energy_log();
  ASSERT_EQ(log.size(), sim.log().size() + 1);
  const df::EnergyRecord& e = log.back();
  const double expected = kMass * kG * kG / 2;
  std::printf("3D free fall: W_g = %.9f J, KE = %.9f J (m g^2 t^2 / 2 = %.9f), worst residual share %.2e\n",
              e.gravity_work, e.kinetic, expected, worst_residual_share(log));
  EXPECT_NEAR(e.gravity_work, expected, 1e-9 * expected);
  EXPECT_NEAR(e.kinetic, expected, 1e-9 * expected);
  EXPECT_LE(worst_residual_share(log), 1e-9);
}

// V1 in 3D, phi 10 on 20 deg, from the relaxed state: friction dissipates
// mu N s, N = m g cos 20 and s the slide (within 1 %), and the balance
// closes to what the penalty springs dissipate (the 2D test's 1e-3 of the
// work done).
TEST(Energy3, SlidingCubeDissipatesMuNs) {
  Simulation3 sim(cube_on_plane(20, 10, true));
  sim.start();
  const Vec3 c0 = sim.blocks()[1].centroid;
  for (int s = 0; s < 1000; ++s) sim.step(1e-3);
  const double slide = (sim.blocks()[1].centroid - c0).norm();
  const double expected = std::tan(10 * kDeg) * kMass * kG * std::cos(20 * kDeg) * slide;
  const df::EnergyRecord& e = sim.energy_log().back();
  std::printf("3D sliding: slide %.6f m, friction %.3f J (mu N s = %.3f J), work %.3f J, stored change %.3f J, "
              "residual %.3e J\n",
              slide, e.friction, expected, e.input(), e.stored() - sim.energy_log().front().stored(), e.residual);
  EXPECT_NEAR(e.friction, expected, 0.01 * expected);
  EXPECT_LE(std::abs(e.residual), 1e-3 * e.input());
  // Kinetic energy 1/2 m v^2 with v = a t of V1.
  const double v = kG * (std::sin(20 * kDeg) - std::cos(20 * kDeg) * std::tan(10 * kDeg)) * 1.0;
  EXPECT_NEAR(e.kinetic, 0.5 * kMass * v * v, 0.02 * 0.5 * kMass * v * v);
}

// A cube that holds (phi 40 on a flat base) on a ground shaking 0.3 g at
// 2 Hz along x, a = a0 sin(w t), for 1 s. It rides with the ground.
// Displacement mode moves the base, which does work on the contact springs:
// the cube's kinetic energy peaks at 1/2 m (2 a0 / w)^2 = 285.2 J (by hand)
// at t = 0.25 s, and the ground's work equals it plus the springs' change.
// Loading mode shakes the cube instead (the frame of the ground): it barely
// moves. The springs see the same forces either way, so the two ledgers
// must leave the same residual, what the penalty springs dissipate; an
// error in the ground's work would show there against 285 J.
TEST(Energy3, GroundShakingIsCountedInBothModes) {
  const double a0 = 0.3 * kG, w = 2 * std::numbers::pi * 2;
  double residual[2] = {0, 0};
  int run = 0;
  for (const char* mode : {"displacement", "loading"}) {
    SCOPED_TRACE(mode);
    Model3 m = cube_on_plane(0, 40, true);
    std::vector<double> t;
    std::vector<Vec3> a;
    for (int k = 0; k <= 1100; ++k) {
      t.push_back(k * 1e-3);
      a.push_back(Vec3(a0 * std::sin(w * k * 1e-3), 0, 0));
    }
    m.earthquake = {std::make_shared<GroundMotion3>(t, a), &df::ground_motion_mode(mode)};
    Simulation3 sim(m);
    sim.start();
    for (int s = 0; s < 1000; ++s) sim.step(1e-3);
    const std::vector<df::EnergyRecord>& log = sim.energy_log();
    const df::EnergyRecord& peak = log[250];  // t = 0.25 s
    const df::EnergyRecord& e = log.back();
    const df::EnergyCreated created = df::most_energy_created(log);
    std::printf("3D shaking (%s): at 0.25 s ground work %.4f J, kinetic %.4f J; at 1 s residual %.4e J; "
                "most created %.2e of the energy moved\n",
                mode, peak.load_work, peak.kinetic, e.residual, created.ratio());
    ASSERT_NEAR(peak.time, 0.25, 1e-9);
    if (run == 0) {
      const double expected = 0.5 * kMass * std::pow(2 * a0 / w, 2);
      EXPECT_NEAR(peak.kinetic, expected, 1e-3 * expected);
      EXPECT_LT(std::abs(peak.residual), 1e-5 * peak.load_work);
    }
    EXPECT_GE(created.ratio(), -1e-6);  // nothing created
    EXPECT_GT(e.residual, 0.0);         // the springs dissipate
    residual[run++] = e.residual;
  }
  EXPECT_NEAR(residual[0], residual[1], 0.01 * residual[1]);
}

// The ledger survives a checkpoint: a run restored half way ends with the
// uninterrupted run's records, bit for bit.
TEST(Energy3, LedgerRoundTripsThroughACheckpoint) {
  Simulation3 whole(cube_on_plane(20, 10, true));
  for (int s = 0; s < 200; ++s) whole.step(1e-3);
  Simulation3 first(cube_on_plane(20, 10, true));
  for (int s = 0; s < 100; ++s) first.step(1e-3);
  Simulation3 second(cube_on_plane(20, 10, true));
  second.restore(first.state());
  for (int s = 0; s < 100; ++s) second.step(1e-3);
  ASSERT_EQ(second.energy_log().size(), whole.energy_log().size());
  const df::EnergyRecord &a = whole.energy_log().back(), &b = second.energy_log().back();
  EXPECT_EQ(a.kinetic, b.kinetic);
  EXPECT_EQ(a.friction, b.friction);
  EXPECT_EQ(a.residual, b.residual);
}

}  // namespace
}  // namespace dda::df3
