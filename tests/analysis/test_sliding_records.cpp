// Newmark analyses of records (SLAMMER's rigid, decoupled and coupled
// options) against closed forms: docs/analytical.md, "Newmark analyses of
// records".
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

#include "dda/analysis/coupled_sliding.hpp"
#include "dda/analysis/response_spectrum.hpp"
#include "dda/analysis/rigid_sliding.hpp"
#include "dda/analysis/shear_beam.hpp"
#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"

using namespace dda::analysis;
using dda::kPi;

namespace {
constexpr double kG = 9.81;

std::vector<double> sine(double amplitude, double freq, double dt, double duration) {
  const auto n = static_cast<std::size_t>(std::llround(duration / dt)) + 1;
  std::vector<double> a(n);
  for (std::size_t i = 0; i < n; ++i) a[i] = amplitude * std::sin(2.0 * kPi * freq * static_cast<double>(i) * dt);
  return a;
}

// Rigid block under a = A sin(w t), sliding while a > a_y, one way. From the
// start t1 = asin(a_y / A) / w the relative velocity is
//   v(t) = (A / w) (cos w t1 - cos w t) - a_y (t - t1),
// zero again at t2 (found by bisection on (t1 + pi / (2 w), t1 + 2 pi / w));
// the slip of one cycle is
//   s = (A / w) [cos(w t1) (t2 - t1) - (sin w t2 - sin w t1) / w] - a_y (t2 - t1)^2 / 2.
// Every cycle slides the same (the block has stopped before the next start).
double analytical_slip_per_cycle(double A, double w, double ay) {
  const double t1 = std::asin(ay / A) / w;
  auto v = [&](double t) { return A / w * (std::cos(w * t1) - std::cos(w * t)) - ay * (t - t1); };
  double lo = t1 + 0.5 * kPi / w, hi = t1 + 2.0 * kPi / w;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (v(mid) > 0.0 ? lo : hi) = mid;
  }
  const double t2 = 0.5 * (lo + hi);
  EXPECT_LT(t2, t1 + 2.0 * kPi / w);  // stopped within the cycle
  return A / w * (std::cos(w * t1) * (t2 - t1) - (std::sin(w * t2) - std::sin(w * t1)) / w) -
         0.5 * ay * (t2 - t1) * (t2 - t1);
}
}  // namespace

// A triangle 0, 2, 0, 0 m/s^2 at dt = 1 s and a_y = 1 m/s^2 (exact for the
// piecewise-linear record), by hand: sliding starts at t = 0.5 s;
// v = t^2 - t + 1/4 to t = 1 (v = 0.25), v = -t^2 + 3 t - 1.75 to t = 2
// (v = 0.25, peak 0.5 at t = 1.5), then v = 0.25 - (t - 2), zero at 2.25 s.
// Slip: 1/24 + 5/12 + 1/32 = 47/96 m.
TEST(RigidSliding, TriangleByHand) {
  const RigidSliding r = rigid_sliding({0.0, 2.0, 0.0, 0.0}, 1.0, 1.0, true);
  EXPECT_NEAR(r.displacement, 47.0 / 96.0, 1e-14);
  EXPECT_NEAR(r.max_velocity, 0.5, 1e-14);
  EXPECT_EQ(r.slip_episodes, 1);
  EXPECT_NEAR(r.velocity[1], 0.25, 1e-14);
  EXPECT_NEAR(r.velocity[2], 0.25, 1e-14);
  EXPECT_EQ(r.velocity[3], 0.0);
}

// A = 0.5 g at 1 Hz, k_y = 0.2, 5 cycles: the exact integration of the
// sampled sine (dt = 1 ms) differs from the analytical slip only by the
// linear interpolation between samples, (w dt)^2 / 12 ~ 3e-6.
TEST(RigidSliding, SineAgainstAnalytical) {
  const double A = 0.5 * kG, w = 2.0 * kPi, ay = 0.2 * kG;
  const double expected = 5.0 * analytical_slip_per_cycle(A, w, ay);
  const RigidSliding r = rigid_sliding(sine(A, 1.0, 1e-3, 5.0), 1e-3, ay);
  EXPECT_NEAR(r.displacement, expected, 2e-5 * expected);
  EXPECT_EQ(r.slip_episodes, 5);
}

// A stiff mass (Ts -> 0) slides as the rigid block: the coupled and the
// decoupled results tend to the analytical rigid slip, the error falling
// with Ts (flexibility changes the motion by about (f Ts)^2: 1.8e-3 at
// Ts = 0.03 s, 1.1e-5 at Ts = 0.003 s for this 1 Hz sine).
TEST(SlidingMass, StiffMassTendsToRigid) {
  const double A = 0.5 * kG, ay = 0.2 * kG, dt = 1e-3;
  const double rigid = 5.0 * analytical_slip_per_cycle(A, 2.0 * kPi, ay);
  const std::vector<double> a = sine(A, 1.0, dt, 5.0);
  double previous_coupled = 1.0, previous_decoupled = 1.0;
  for (double ts : {0.1, 0.03, 0.01, 0.003}) {
    const ShearBeam beam{ts, 0.05};
    const double coupled = coupled_sliding(a, dt, ay, beam).displacement;
    const double decoupled = rigid_sliding(average_acceleration(a, dt, beam), dt, ay).displacement;
    const double e_coupled = std::abs(coupled / rigid - 1.0), e_decoupled = std::abs(decoupled / rigid - 1.0);
    EXPECT_LT(e_coupled, previous_coupled) << "Ts = " << ts;
    EXPECT_LT(e_decoupled, previous_decoupled) << "Ts = " << ts;
    previous_coupled = e_coupled;
    previous_decoupled = e_decoupled;
  }
  EXPECT_LT(previous_coupled, 3e-5);
  EXPECT_LT(previous_decoupled, 3e-5);
  // Ts = 0 is the rigid block itself.
  EXPECT_DOUBLE_EQ(coupled_sliding(a, dt, ay, ShearBeam{0.0, 0.05}).displacement,
                   rigid_sliding(a, dt, ay).displacement);
}

// Energy balance of the coupled model per unit mass (coupled_sliding.hpp):
//   E(T) + int xi w q'^2 dt + a_y D(T) = int a_g (D' - alpha q') dt,
//   E = D'^2 / 2 - alpha D' q' + q'^2 / 4 + w^2 q^2 / 4,
// the integrals by the trapezoidal rule on the samples (the scheme's own
// rule, so the balance holds to its truncation error at the splits: 2.4e-6
// of the input here).
TEST(SlidingMass, CoupledEnergyBalance) {
  const double dt = 1e-3, ay = 0.1 * kG;
  const ShearBeam beam{0.3, 0.1};
  std::vector<double> a = sine(0.4 * kG, 1.5, dt, 10.0);
  const std::vector<double> b = sine(0.2 * kG, 3.7, dt, 10.0);
  for (std::size_t i = 0; i < a.size(); ++i) a[i] += b[i];
  const CoupledSliding r = coupled_sliding(a, dt, ay, beam, true);
  ASSERT_EQ(r.q.size(), a.size());
  ASSERT_GT(r.displacement, 0.05);  // it does slide
  const double w = 2.0 * kPi / beam.period, alpha = kMassFraction;
  double input = 0.0, damping = 0.0;
  for (std::size_t i = 1; i < a.size(); ++i) {
    auto power_in = [&](std::size_t j) { return a[j] * (r.sliding_rate[j] - alpha * r.q_rate[j]); };
    auto power_damp = [&](std::size_t j) { return beam.damping * w * r.q_rate[j] * r.q_rate[j]; };
    input += 0.5 * dt * (power_in(i - 1) + power_in(i));
    damping += 0.5 * dt * (power_damp(i - 1) + power_damp(i));
  }
  const std::size_t n = a.size() - 1;
  const double Dd = r.sliding_rate[n], qd = r.q_rate[n], q = r.q[n];
  const double energy = 0.5 * Dd * Dd - alpha * Dd * qd + 0.25 * qd * qd + 0.25 * w * w * q * q;
  const double friction = ay * r.displacement;
  EXPECT_NEAR(energy + damping + friction, input, 2e-5 * input);
  EXPECT_GT(friction, 0.3 * input);  // the balance is not carried by one term
  EXPECT_GT(damping, 0.05 * input);
}

// Resonance: a sine at f = 1 / Ts drives the first mode at resonance. In the
// steady state, with q'' = Gamma u'' and u'' = a_g / (2 i xi) at w = wn, the
// average acceleration is a_g (1 + alpha Gamma / (2 i xi)):
//   |HEA| / A = sqrt(1 + (alpha Gamma / (2 xi))^2) = sqrt(1 + (8 / pi^2 / 0.1)^2) = 8.1671.
// The continuous damped shear beam (complex modulus G (1 + 2 i xi)) has the
// average-acceleration transfer function tan(kH) / (kH), k H = (pi / 2) /
// sqrt(1 + 2 i xi) at f = 1 / Ts: its modulus differs from the first mode's
// by the higher modes' share: 8.1702, 0.04 % above the first mode's.
// The peak read at the samples (dt = 1 ms, 2 Hz) misses the crest by at most
// 1 - cos(pi f dt) = 2e-5.
TEST(SlidingMass, DecoupledResonanceMatchesTransferFunction) {
  const double ts = 0.5, xi = 0.05, A = 0.1 * kG, dt = 1e-3;
  const std::vector<double> a = sine(A, 1.0 / ts, dt, 40.0);
  const std::vector<double> hea = average_acceleration(a, dt, ShearBeam{ts, xi});
  double steady = 0.0;  // the last 5 s; the transient has decayed by exp(-xi wn 35 s) ~ 1e-10
  for (std::size_t i = hea.size() - 5000; i < hea.size(); ++i) steady = std::max(steady, std::abs(hea[i]));
  const double one_mode = std::sqrt(1.0 + std::pow(kMassFraction * kParticipation / (2.0 * xi), 2));
  EXPECT_NEAR(one_mode, 8.1671, 1e-4);
  EXPECT_NEAR(steady / A, one_mode, 5e-5 * one_mode);
  const std::complex<double> kH = (kPi / 2.0) / std::sqrt(std::complex<double>(1.0, 2.0 * xi));
  const double beam = std::abs(std::tan(kH) / kH);
  EXPECT_NEAR(beam, 8.1702, 1e-4);
  EXPECT_NEAR(steady / A, beam, 1e-3 * beam);
}

// The equivalent-linear properties are a fixed point: the strain of the
// beam with the returned Ts and damping gives back the returned G / Gmax
// through the hyperbolic curve (to the iteration's tolerance, 1e-4 in
// G / Gmax). Stronger shaking softens the beam more.
TEST(SlidingMass, EquivalentLinearFixedPoint) {
  const double dt = 2e-3, height = 20.0, vs = 200.0;  // Ts = 4 H / Vs = 0.4 s
  const ShearBeam small{4.0 * height / vs, 0.05};
  const EquivalentLinearCurve curve{5e-4, 0.2};
  double previous_ratio = 1.0;
  for (double amplitude : {0.05, 0.2, 0.5}) {
    const std::vector<double> a = sine(amplitude * kG, 2.0, dt, 10.0);
    const EquivalentLinearResult r = equivalent_linear(a, dt, small, height, curve);
    ASSERT_TRUE(r.converged);
    const OscillatorHistory h = oscillator_response(a, dt, r.beam.period, r.beam.damping);
    double umax = 0.0;
    for (double u : h.u) umax = std::max(umax, std::abs(u));
    const double strain = 0.65 * 2.0 * umax / height;  // 0.65 (pi / 2H) Gamma max|u|
    EXPECT_NEAR(r.modulus_ratio, 1.0 / (1.0 + strain / curve.reference_strain), 1e-4);
    EXPECT_NEAR(r.beam.period, small.period / std::sqrt(r.modulus_ratio), 1e-12);
    EXPECT_NEAR(r.beam.damping, 0.05 + 0.15 * (1.0 - r.modulus_ratio), 1e-12);
    EXPECT_LT(r.modulus_ratio, previous_ratio);
    previous_ratio = r.modulus_ratio;
  }
}

TEST(SlidingMass, RejectsBadInput) {
  EXPECT_THROW(rigid_sliding({1.0}, 0.01, 1.0), dda::InputError);
  EXPECT_THROW(rigid_sliding({1.0, 2.0}, 0.01, -1.0), dda::InputError);
  EXPECT_THROW(coupled_sliding({1.0, 2.0}, 0.01, 1.0, ShearBeam{-0.1, 0.05}), dda::InputError);
  EXPECT_THROW(average_acceleration({1.0, 2.0}, 0.01, ShearBeam{0.1, 1.5}), dda::InputError);
}
