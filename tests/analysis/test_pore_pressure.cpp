// Pore pressure on the sliding plane in the dynamic analytical tools:
// `dda newmark --ru` (Bishop's pore-pressure ratio, water force
// ru W / cos(alpha)) and `dda sliding3d --water` (a water force per plane as
// a fraction of W). Under gravity alone a block whose effective-stress
// factor of safety is below 1 slides with the constant acceleration of the
// effective-stress balance, which the trapezoidal integration follows
// exactly: s(t) = a t^2 / 2.
#include <gtest/gtest.h>

#include <cmath>

#include "dda/analysis/newmark.hpp"
#include "dda/analysis/sliding3d.hpp"
#include "dda/analysis/wedge.hpp"
#include "dda/analysis/wedge_body.hpp"

namespace dda::analysis {
namespace {

constexpr double kG = 9.81;
double rad(double deg) { return deg * M_PI / 180; }

TEST(PorePressure, NewmarkBlockSlidesWithTheEffectiveStressAcceleration) {
  // alpha 30, phi 35, ru 0.3: N/(m g) = cos a - ru / cos a = 0.86603 - 0.34641
  // = 0.51962, FS = 0.51962 tan 35 / sin 30 = 0.7277 < 1 (dry: 1.2128),
  // a = g (sin a - 0.51962 tan 35) = 1.3358 m/s^2, s(1 s) = 0.6679 m.
  NewmarkInput in;
  in.dip_deg = 30;
  in.phi_deg = 35;
  in.ru = 0.3;
  in.duration = 1.0;
  const NewmarkResult r = run_newmark(in, no_input());
  const double a = kG * (std::sin(rad(30)) - (std::cos(rad(30)) - 0.3 / std::cos(rad(30))) * std::tan(rad(35)));
  EXPECT_NEAR(a, 1.3358, 1e-4);
  EXPECT_NEAR(r.s.back(), a / 2, 1e-9);
  // Dry, the same block holds.
  in.ru = 0;
  EXPECT_EQ(run_newmark(in, no_input()).s.back(), 0.0);
}

TEST(PorePressure, NewmarkYieldAccelerationBalancesDrivingAndResistance) {
  // ru 0.1 on alpha 30, phi 35: the yield acceleration 0.2061 m/s^2 (hand:
  // g (mu c - s - mu ru / c) / (c + mu s) with c = 0.86603, s = 0.5,
  // mu = 0.70021). A constant horizontal body acceleration 1 % above it
  // along the dip direction (east) slides the block, 1 % below does not.
  NewmarkInput in;
  in.dip_deg = 30;
  in.phi_deg = 35;
  in.ru = 0.1;
  in.duration = 1.0;
  const double ky = run_newmark(in, no_input()).yield_down;
  EXPECT_NEAR(ky, 0.2061, 1e-4);
  for (const double f : {0.99, 1.01}) {
    Excitation e;
    e.body = [=](double) { return Vec3(f * ky, 0, 0); };
    const double s = run_newmark(in, e).s.back();
    if (f < 1)
      EXPECT_EQ(s, 0.0);
    else
      EXPECT_GT(s, 0.0);
  }
}

TEST(PorePressure, Sliding3dSingleFaceWithWater) {
  // Plane 30/090, phi 30, water force 0.2 W: N/W = cos 30 - 0.2 = 0.66603,
  // a = g (0.5 - 0.66603 tan 30) = 1.1327 m/s^2 down the dip (east and
  // down), s(1 s) = a / 2.
  SlidingModel m;
  m.planes = {Plane{30, 90}};
  m.friction = {FrictionLaw::constant_angle(30)};
  m.water = {0.2};
  const SlidingRun run = run_sliding(m, 1e-4, 1.0);
  const double a = kG * (0.5 - (std::cos(rad(30)) - 0.2) * std::tan(rad(30)));
  EXPECT_NEAR(a, 1.1327, 1e-4);
  EXPECT_NEAR(run.samples.back().u.norm(), a / 2, 1e-6);
  EXPECT_NEAR(run.samples.back().n1 / kG, std::cos(rad(30)) - 0.2, 1e-12);
}

TEST(PorePressure, Sliding3dWedgeAgreesWithTheWedgeFactorOfSafety) {
  // Hoek & Bray's saturated wedge (tests/analysis/test_wedge_water.cpp,
  // friction only): FS = 0.4754 from `dda wedge`. Given the same water
  // forces per unit weight, the dynamic analysis slides it down the line
  // of intersection with a = g D (1 - FS), D = sin(plunge) the driving per
  // unit weight, since FS = resistance / D.
  const Plane pa{45, 105}, pb{70, 235};
  const WedgeBody body = wedge_body(pa, pb, SlopeFaces{Plane{65, 185}, Plane{12, 195}, 40});
  const WedgeWaterForces u = hoek_bray_water(body, 9.81);
  const double w = 25 * body.volume_m3;
  WedgeSpec spec;
  spec.plane1 = pa;
  spec.plane2 = pb;
  spec.phi1_deg = 20;
  spec.phi2_deg = 30;
  spec.water1 = u.u1 / w;
  spec.water2 = u.u2 / w;
  const WedgeEquilibrium e = wedge_equilibrium(spec, Vec3(0, 0, -1));
  EXPECT_NEAR(e.fs, 0.4754, 1e-4);

  SlidingModel m;
  m.planes = {pa, pb};
  m.friction = {FrictionLaw::constant_angle(20), FrictionLaw::constant_angle(30)};
  m.water = {spec.water1, spec.water2};
  const SlidingRun run = run_sliding(m, 1e-4, 1.0);
  const double a = kG * e.driving * (1 - e.fs);
  EXPECT_NEAR(run.samples.back().u.norm(), a / 2, 1e-6 * a);
}

}  // namespace
}  // namespace dda::analysis
