// Joint water in the 3D solver (df/core/water.hpp, df/src/3d/water_faces3d.cpp):
// V1's 1 m cube on a fixed plane dipping 20 degrees (tests/df/
// test_simulation3d.cpp), with a water table that loads the joint under it,
// against the effective-stress limit equilibrium
//   FS = (W cos a - U) tan phi / (W sin a),
// U the water force on the cube's base (its free faces are not loaded:
// docs/formulation.md, "Joint water").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "dda/df/3d/simulation3d.hpp"
#include "df_test_models3d.hpp"

namespace dda::df3 {
namespace {

constexpr double kDeg = std::numbers::pi / 180;
constexpr double kAlpha = 20, kRho = 2600, kG = 9.81, kGammaW = 9810;
// The cube's base is centred on the origin (the plane through it is turned
// about the origin), so its depths below a level of 0.5 m run from
// 0.5 - 0.171 to 0.5 + 0.171 m, linearly: U = gamma_w * 1 m^2 * 0.5 m.
constexpr double kLevel = 0.5;
constexpr double kU = kGammaW * 0.5;

double weight() { return kRho * kG; }  // N, the 1 m^3 cube
double critical_phi() {                // FS = 1: tan phi = W sin a / (W cos a - U), 24.59 degrees
  return std::atan(weight() * std::sin(kAlpha * kDeg) / (weight() * std::cos(kAlpha * kDeg) - kU)) / kDeg;
}

// The model of test_simulation3d.cpp's V1 (base fixed, pn = ps = 1e9 N/m,
// dt 1 ms), relaxed before t = 0, with the water table at `level`.
Model3 cube(double phi_deg, double level) {
  const Matrix3d r = testing::plane_rotation(kAlpha, 90);
  Model3 m;
  m.blocks = {testing::box({-5, -5, -1}, {5, 5, 0}, r), testing::box({-0.5, -0.5, 0}, {0.5, 0.5, 1}, r)};
  m.fixed = {true, false};
  m.materials = {{kRho, 1e10, 0.25}};
  m.default_joint.friction_deg = phi_deg;
  m.normal_penalty = 1e9;
  m.shear_penalty = 1e9;
  m.contact_reach = 0.01;
  df::WaterTable<3> w;
  w.level = level;
  m.water = w;
  return m;
}

// Down-dip displacement of the cube's centroid from t = 0 to t_end.
double slide(const Model3& m, double t_end, double* normal_sum = nullptr) {
  Simulation3 sim(m);
  sim.start();
  const Vec3 c0 = sim.blocks()[1].centroid;
  const int steps = static_cast<int>(std::lround(t_end / 1e-3));
  for (int s = 0; s < steps; ++s) sim.step(1e-3);
  if (normal_sum) {
    *normal_sum = 0;
    for (const Contact3& c : sim.contacts()) *normal_sum += c.normal_force;
  }
  const Vec3 dip = testing::plane_rotation(kAlpha, 90) * Vec3(1, 0, 0);
  return (sim.blocks()[1].centroid - c0).dot(dip);
}

TEST(Water3d, CriticalAngleOfTheHandNumbers) {
  // W = 25 506 N, W sin a = 8723.6 N, W cos a = 23 967.8 N, U = 4905 N:
  // tan phi = 8723.6 / 19 062.8 = 0.45763, phi = 24.59 degrees (dry: 20).
  EXPECT_NEAR(critical_phi(), 24.59, 0.01);
}

TEST(Water3d, CubeHoldsAboveTheCriticalAngleOnTheEffectiveNormalForce) {
  // phi_c + 1 degree: FS = 1.05; the cube stays (V1-3D's bound), and its
  // four contacts carry W cos a - U = 19 063 N, not W cos a.
  double normal = 0;
  const double s = slide(cube(critical_phi() + 1, kLevel), 1.0, &normal);
  const double expected = weight() * std::cos(kAlpha * kDeg) - kU;
  std::printf("3D water, phi_c + 1: slip %.2e m, sum N %.1f N (expected %.1f)\n", s, normal, expected);
  EXPECT_LT(std::abs(s), 1e-4);
  EXPECT_NEAR(normal, expected, 1e-3 * expected);
}

TEST(Water3d, CubeSlidesBelowTheCriticalAngleWithTheEffectiveStressBalance) {
  // phi_c - 1 degree slides. At phi_c - 5 the slide follows the
  // effective-stress balance with the water deepening as the cube goes
  // down (its base drops by s sin a, U grows by gamma_w A s sin a):
  // m s'' = m (a0 + k s), k = gamma_w A sin a tan phi / m, so from rest
  // s(t) = a0 / k (cosh(sqrt(k) t) - 1) (tests/df/test_water.cpp, 2D),
  // 0.3875 m at 1 s; within 0.2 %.
  EXPECT_GT(slide(cube(critical_phi() - 1, kLevel), 1.0), 1e-3);
  const double phi = critical_phi() - 5, mu = std::tan(phi * kDeg);
  const double a0 = (weight() * std::sin(kAlpha * kDeg) - (weight() * std::cos(kAlpha * kDeg) - kU) * mu) / kRho;
  const double k = kGammaW * 1.0 * std::sin(kAlpha * kDeg) * mu / kRho;
  const double expected = a0 / k * (std::cosh(std::sqrt(k) * 1.0) - 1);
  const double s = slide(cube(phi, kLevel), 1.0);
  std::printf("3D water, phi_c - 5: s %.5f m, expected %.5f m\n", s, expected);
  EXPECT_NEAR(s, expected, 0.002 * expected);  // measured within 0.03 %
}

// The 3D energy ledger books the water's work with the loads. The cube on
// a flat base under 3 m of water (U = 9810 x 3 = 29 430 N on its base
// against W = 25 506 N) is lifted off: the water's work is what the cube
// gains in kinetic and potential energy, and the balance closes to 1e-3 of
// that work, as the dry cube's does (test_energy3d.cpp); left out, the
// water's work would show as energy created, all of it.
TEST(Water3d, LedgerBooksTheWatersWork) {
  Model3 m = cube(30, 3.0);
  const Matrix3d flat = Matrix3d::Identity();
  m.blocks = {testing::box({-5, -5, -1}, {5, 5, 0}, flat), testing::box({-0.5, -0.5, 0}, {0.5, 0.5, 1}, flat)};
  Simulation3 sim(m);
  sim.start();
  for (int s = 0; s < 200; ++s) sim.step(1e-3);
  const df::EnergyRecord& e = sim.energy_log().back();
  const double moved = df::energy_moved(sim.energy_log().front(), e);
  std::printf("3D water lift: water's work %.1f J, gravity %.1f J, kinetic %.1f J, residual %.3e J of %.1f J moved\n",
              e.load_work, e.gravity_work, e.kinetic, e.residual, moved);
  EXPECT_GT(sim.blocks()[1].centroid.z(), 0.5 + 1e-3);  // lifted
  EXPECT_GT(e.load_work, 0.0);
  EXPECT_GT(e.kinetic + e.gravity_work * -1, 0.5 * e.load_work);  // most of it went into the cube
  EXPECT_LE(std::abs(e.residual), 1e-3 * e.load_work);
}

TEST(Water3d, DryTableIsTheDryRun) {
  // A table below the whole model loads nothing: the same slide as without water.
  Model3 low = cube(10, -100), none = low;
  none.water.reset();
  EXPECT_EQ(slide(low, 0.2), slide(none, 0.2));
}

}  // namespace
}  // namespace dda::df3
