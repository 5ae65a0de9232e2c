// The seed papers' friction instabilities in the spring-slider
// (docs/friction.md, "Instabilities"; examples/friction_instabilities): a
// slider of m = 1000 kg (N = W = 9810 N) pulled through a spring k by a
// load point moving at vd (tests/df/spring_slider_model.hpp). Each DDA run
// is compared with the linear-stability criterion of its law and with an
// integration of the same equations of motion written in the test
// (spring_slider_ode.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "dda/df/core/friction_laws.hpp"
#include "dda/df/2d/simulation.hpp"
#include "spring_slider_model.hpp"
#include "spring_slider_ode.hpp"

namespace dda::df {
namespace {

using test::kG;
using test::law;
using test::OdeSample;
using test::SliderOde;
using test::SpringSlider;

constexpr double kMass = 1000, kWeight = kMass * kG;

// A DDA run of the spring-slider as (t, x, V, spring force) samples, one per
// step. The load point moves at vd from the driver's u(0); the spring force
// is the bolt's pretension plus k (load point - slider) (the driver's fixed
// point is 10 x 50 E stiff: it lags by F / 5e12 m, nothing next to the
// slider's motion).
std::vector<OdeSample> dda_run(SpringSlider s, double vd, double t_end) {
  const double u0 = s.driver.value.empty() ? 0.0 : s.driver.value[0].x();
  s.driver = TimeHistory{{0, t_end + 1}, {Vec2(u0, 0), Vec2(u0 + vd * (t_end + 1), 0)}};
  Simulation sim(build_model(test::spring_slider(s)));
  sim.run_until(t_end);
  std::vector<OdeSample> out;
  for (const MeasurementSample& m : sim.histories()[0]) {
    const double x = m.displacement.x();
    out.push_back({m.time, x, m.velocity.x(), s.pretension + s.spring * (u0 + vd * m.time - x)});
  }
  return out;
}

SpringSlider slider(const JointProperties& joint, double k, double dt, double u0) {
  SpringSlider s;
  s.joint = joint;
  s.spring = k;
  s.dt = dt;
  s.driver = TimeHistory{{0}, {Vec2(u0, 0)}};
  return s;
}

// The slip events of a run: the times of the speed's peaks above `fast`,
// and over the last whole cycle (between the last two peaks) the range of
// the spring force (the stress drop, times the slider's area).
struct Cycles {
  std::vector<double> peaks;
  double period = 0, drop = 0, peak_speed = 0;
};

Cycles cycles(const std::vector<OdeSample>& run, double fast) {
  Cycles c;
  for (std::size_t i = 1; i + 1 < run.size(); ++i)
    if (run[i].v > fast && run[i].v >= run[i - 1].v && run[i].v > run[i + 1].v) {
      // One peak per event: a later local maximum within the same event
      // (the speed stays above `fast` in between) replaces it if higher.
      bool same_event = !c.peaks.empty();
      if (same_event)
        for (const OdeSample& s : run)
          if (s.t > c.peaks.back() && s.t < run[i].t && s.v < fast) same_event = false;
      if (!same_event) c.peaks.push_back(run[i].t);
    }
  if (c.peaks.size() < 2) return c;
  const double t0 = c.peaks[c.peaks.size() - 2], t1 = c.peaks.back();
  c.period = t1 - t0;
  double lo = 1e300, hi = -1e300;
  for (const OdeSample& s : run)
    if (s.t >= t0 && s.t <= t1) {
      lo = std::min(lo, s.spring_force), hi = std::max(hi, s.spring_force);
      c.peak_speed = std::max(c.peak_speed, s.v);
    }
  c.drop = hi - lo;
  return c;
}

// The speed range over the last `window` seconds.
std::pair<double, double> late_speeds(const std::vector<OdeSample>& run, double window) {
  double lo = 1e300, hi = -1e300;
  for (const OdeSample& s : run)
    if (s.t > run.back().t - window) lo = std::min(lo, s.v), hi = std::max(hi, s.v);
  return {lo, hi};
}


// ---- Rate and state (Ruina; Rice & Ruina): a = 0.01, b = 0.015,
// Dc = 1e-4 m, mu0 = 0.6, V0 = 1e-6 m/s, aging law, load point at 1 mm/s.
// Quasi-static critical stiffness k_c = N (b - a) / Dc = 4.905e5 N/m; the
// slider's inertia raises it to k_c (1 + m vd^2 / (N a Dc)) = 1.102 k_c
// (Rice & Ruina's linear stability with inertia), so 0.5 k_c is unstable
// and 2 k_c stable by a wide margin either way.
constexpr double kA = 0.01, kB = 0.015, kDc = 1e-4, kMu0 = 0.6, kV0 = 1e-6, kVd = 1e-3;
constexpr double kKc = kWeight * (kB - kA) / kDc;

JointProperties rate_state_joint() {
  return law("rate_state", {{"mu0", kMu0}, {"a", kA}, {"b", kB}, {"dc", kDc}, {"v0", kV0}, {"v_init", 1e-4}});
}

// The same law written out for the direct integration: the solver's
// regularised form a asinh(V / (2 V0) exp(psi / a)), psi = mu0 + b ln(V0
// theta / Dc), and the aging law d theta / dt = 1 - V theta / Dc.
SliderOde rate_state_ode(double k, double u0) {
  SliderOde o;
  o.m = kMass, o.n = kWeight, o.k = k, o.vd = kVd, o.u0 = u0;
  o.state0 = {kDc / 1e-4, 0};  // theta = Dc / v_init
  o.mu = [](double v, const std::array<double, 2>& s) {
    return kA * std::asinh(v / (2 * kV0) * std::exp((kMu0 + kB * std::log(kV0 * s[0] / kDc)) / kA));
  };
  o.rates = [](double v, const std::array<double, 2>& s) { return std::array<double, 2>{1 - v * s[0] / kDc, 0}; };
  return o;
}

TEST(FrictionInstability, RateStateBelowCriticalStiffnessSticksAndSlips) {
  // k = 0.5 k_c from rest, the spring at 0.55 W (below the strength of the
  // healed contact, theta = Dc / 1e-4 m/s): slip events, compared over the
  // last whole cycle of 10 s (the third event) with the direct integration
  // of the same equations (RK4, h = 10 us; h = 2 us gives the same to 1e-4).
  // Measured at dt = 0.1 ms: period 3.728 s against 3.929 (-5.1 %),
  // stress drop 0.0801 W against 0.0858 W (-6.6 %), peak speed 23.8 vd
  // against 25.7 vd (-7.3 %). Why DDA is short (examples/
  // friction_instabilities, "Time step", measured when this comment was
  // written): the last cycle's period is 2.903, 3.599 and 3.724 s at dt =
  // 1, 0.3 and 0.1 ms, converging to about 3.74-3.79 s, not 3.93. In the
  // stick phase the direct integration creeps at 0.1-1 % of vd; DDA's
  // fixed-point iteration between mu(V) and the step's speed contracts only
  // above V = N a dt / (2 m) = 0.5 % of vd at 0.1 ms, so there it runs to
  // its limit (576 of 101 927 steps), the slip speed jitters at 1-6 % of vd
  // and theta, aging with |V|, heals at 0.85 instead of 0.99 per second: a
  // weaker healed contact, a smaller event, a shorter cycle. Steps finer
  // than 0.1 ms resolve the slider's rocking on its contact springs (about
  // 3e4 rad/s), which the friction then excites (at 30 us no clean cycle is
  // left), so 0.1 ms is the step to use and 8 % / 10 % are the gaps it
  // leaves (docs/friction.md, "Instabilities").
  const double k = 0.5 * kKc, u0 = 0.55 * kWeight / k, t_end = 10;
  const Cycles dda = cycles(dda_run(slider(rate_state_joint(), k, 1e-4, u0), kVd, t_end), 3 * kVd);
  const Cycles ode = cycles(test::integrate(rate_state_ode(k, u0), t_end, 1e-5, 1e-4), 3 * kVd);
  std::printf("rate-state k = 0.5 k_c: period %.4f s (direct integration %.4f), stress drop %.5f N/N (%.5f), "
              "peak speed %.2f vd (%.2f), %zu events (%zu)\n",
              dda.period, ode.period, dda.drop / kWeight, ode.drop / kWeight, dda.peak_speed / kVd,
              ode.peak_speed / kVd, dda.peaks.size(), ode.peaks.size());
  ASSERT_GE(ode.peaks.size(), 3u);
  ASSERT_EQ(dda.peaks.size(), ode.peaks.size());
  EXPECT_NEAR(dda.period, ode.period, 0.08 * ode.period);
  EXPECT_NEAR(dda.drop, ode.drop, 0.08 * ode.drop);
  EXPECT_NEAR(dda.peak_speed, ode.peak_speed, 0.10 * ode.peak_speed);
}

TEST(FrictionInstability, RateStateAboveCriticalStiffnessSlidesSteadily) {
  // k = 2 k_c from the same start: one damped burst, then steady sliding
  // at vd with the steady-state friction mu0 + (a - b) ln(vd / V0) =
  // 0.565461 (hand-computed), as the direct integration does.
  const double k = 2 * kKc, u0 = 0.55 * kWeight / k, t_end = 8;
  const std::vector<OdeSample> run = dda_run(slider(rate_state_joint(), k, 1e-4, u0), kVd, t_end);
  const auto [lo, hi] = late_speeds(run, 1.0);
  const auto [ode_lo, ode_hi] = late_speeds(test::integrate(rate_state_ode(k, u0), t_end, 1e-5, 1e-4), 1.0);
  const double mu_ss = kMu0 + (kA - kB) * std::log(kVd / kV0);
  std::printf("rate-state k = 2 k_c: speed in the last second %.6f..%.6f vd (direct integration %.6f..%.6f), "
              "friction %.6f (steady state %.6f)\n",
              lo / kVd, hi / kVd, ode_lo / kVd, ode_hi / kVd, run.back().spring_force / kWeight, mu_ss);
  EXPECT_GT(lo, 0.99 * kVd);
  EXPECT_LT(hi, 1.01 * kVd);
  EXPECT_GT(ode_lo, 0.99 * kVd);
  EXPECT_LT(ode_hi, 1.01 * kVd);
  EXPECT_NEAR(run.back().spring_force / kWeight, mu_ss, 1e-4);
}

// ---- Stribeck with a viscous branch: mu = 0.5 + 0.1 exp(-V / 0.01 m/s) +
// 1 s/m V, k = 1e5 N/m. Linearised about steady sliding at vd, the slider
// is m x'' + N mu'(vd) x' + k x = 0: the oscillation grows or decays as
// exp(sigma t), sigma = -N mu'(vd) / (2 m), mu'(V) = 1 - 10 exp(-V / 0.01);
// steady sliding is stable above V_cr = v_s ln((mu_s - mu_k) / (mu_v v_s))
// = 0.01 ln 10 = 0.023026 m/s.
constexpr double kVs = 0.01, kMuV = 1.0, kStribeckK = 1e5;
JointProperties stribeck_joint() {
  return law("stribeck", {{"mu_s", 0.6}, {"mu_k", 0.5}, {"v_s", kVs}, {"mu_v", kMuV}});
}
// 0.023026 m/s (test_friction_laws.cpp checks the formula by hand).
const double kVcr = StribeckFriction(stribeck_joint()).critical_speed();
double stribeck_mu(double v) { return 0.5 + 0.1 * std::exp(-v / kVs) + kMuV * v; }

// The growth rate of the slider's oscillation about steady sliding at vd,
// started with the spring 0.1 % off its steady force: a least-squares fit
// of ln |V - vd| at the speed's extremes, while the oscillation is below
// 20 % of vd (linear) and after the first 0.2 s.
double growth_rate(double vd) {
  SpringSlider s = slider(stribeck_joint(), kStribeckK, 1e-3, 0);
  s.pretension = 1.001 * stribeck_mu(vd) * kWeight;
  s.slider_speed = vd;
  s.settle = false;  // it starts sliding
  const std::vector<OdeSample> run = dda_run(s, vd, 4.0);
  double n = 0, st = 0, sa = 0, stt = 0, sta = 0;
  for (std::size_t i = 1; i + 1 < run.size(); ++i) {
    const double d = run[i].v - vd, a = std::abs(d);
    if (run[i].t < 0.2 || a > 0.2 * vd || a < std::abs(run[i - 1].v - vd) || a < std::abs(run[i + 1].v - vd)) continue;
    const double t = run[i].t, la = std::log(a);
    n += 1, st += t, sa += la, stt += t * t, sta += t * la;
  }
  return n > 3 ? (n * sta - st * sa) / (n * stt - st * st) : std::nan("");
}

TEST(FrictionInstability, StribeckOnsetFollowsTheLinearStabilityCriterion) {
  // At 0.9 and 1.1 V_cr: sigma = -N mu'(vd) / (2 m) = +1.2702 and
  // -1.0090 1/s (hand-computed from the formula above). The oscillation
  // (omega = 10 rad/s) is resolved by 600 steps a period; 5 % is asked.
  for (const double ratio : {0.9, 1.1}) {
    const double vd = ratio * kVcr;
    const double slope = kMuV - 0.1 / kVs * std::exp(-vd / kVs);
    const double expected = -kWeight * slope / (2 * kMass), measured = growth_rate(vd);
    std::printf("Stribeck at %.1f V_cr: growth rate %.4f 1/s (linear stability %.4f)\n", ratio, measured, expected);
    EXPECT_NEAR(measured, expected, 0.05 * std::abs(expected));
  }
}

SliderOde sticking_ode(double k, double vd, double u0, std::function<double(double, const std::array<double, 2>&)> mu) {
  SliderOde o;
  o.m = kMass, o.n = kWeight, o.k = k, o.vd = vd, o.u0 = u0;
  o.sticks = true;
  o.mu = std::move(mu);
  o.rates = [](double v, const std::array<double, 2>&) { return std::array<double, 2>{std::abs(v), 0}; };
  return o;
}

TEST(FrictionInstability, StribeckBelowCriticalSpeedSticksAndSlips) {
  // Driven at 0.5 V_cr from rest (spring at 0.59 W, below mu_s W): stick-
  // slip with the period, force range and peak speed of the direct
  // integration; at 2 V_cr it slides steadily (the same start).
  const double u0 = 0.59 * kWeight / kStribeckK;
  for (const double ratio : {0.5, 2.0}) {
    const double vd = ratio * kVcr;
    const std::vector<OdeSample> run = dda_run(slider(stribeck_joint(), kStribeckK, 1e-3, u0), vd, 6);
    const std::vector<OdeSample> direct = test::integrate(
        sticking_ode(kStribeckK, vd, u0, [](double v, const std::array<double, 2>&) { return stribeck_mu(v); }), 6,
        1e-5, 1e-3);
    const Cycles dda = cycles(run, 2 * vd), ode = cycles(direct, 2 * vd);
    const auto [lo, hi] = late_speeds(run, 1.0);
    std::printf("Stribeck at %.1f V_cr: period %.4f s (direct integration %.4f), force range %.5f W (%.5f), peak "
                "speed %.3f vd (%.3f); last second's speed %.4f..%.4f vd\n",
                ratio, dda.period, ode.period, dda.drop / kWeight, ode.drop / kWeight, dda.peak_speed / vd,
                ode.peak_speed / vd, lo / vd, hi / vd);
    if (ratio < 1) {
      ASSERT_GE(ode.peaks.size(), 3u);
      EXPECT_NEAR(dda.period, ode.period, 0.02 * ode.period);
      EXPECT_NEAR(dda.drop, ode.drop, 0.02 * ode.drop);
      EXPECT_NEAR(dda.peak_speed, ode.peak_speed, 0.02 * ode.peak_speed);
      EXPECT_LT(lo, 0.01 * vd);  // it sticks
    } else {
      EXPECT_GT(lo, 0.99 * vd);
      EXPECT_LT(hi, 1.01 * vd);
    }
  }
}

// ---- Linear slip weakening: mu from 0.6 to 0.5 over Dc = 1 cm. The spring
// unloads by k per metre of slip while the strength drops by N (mu_s -
// mu_d) / Dc: slip is unstable below k_c = N (mu_s - mu_d) / Dc =
// 98 100 N/m. Above it, the slip while weakening is quasi-static at
// k vd / (k - k_c): 2 vd at 2 k_c (hand-derived from k (vd - V) = -k_c V).
constexpr double kSwDc = 0.01, kSwVd = 2e-3;
constexpr double kSwKc = kWeight * 0.1 / kSwDc;

double weakening_mu(double slip) { return 0.6 - 0.1 * std::min(slip / kSwDc, 1.0); }

TEST(FrictionInstability, SlipWeakeningCriticalStiffness) {
  const JointProperties joint = law("slip_weakening", {{"mu_s", 0.6}, {"mu_d", 0.5}, {"dc", kSwDc}});
  for (const double ratio : {0.5, 2.0}) {
    const double k = ratio * kSwKc, u0 = 0.59 * kWeight / k, t_end = 4;
    const std::vector<OdeSample> run = dda_run(slider(joint, k, 1e-3, u0), kSwVd, t_end);
    const std::vector<OdeSample> direct = test::integrate(
        sticking_ode(k, kSwVd, u0, [](double, const std::array<double, 2>& s) { return weakening_mu(s[0]); }), t_end,
        1e-5, 1e-3);
    // The mean slip speed while the slip goes from 0.1 Dc to 0.9 Dc, and the peak speed.
    auto weakening = [](const std::vector<OdeSample>& r) {
      const OdeSample *a = nullptr, *b = nullptr;
      double peak = 0;
      for (const OdeSample& s : r) {
        if (!a && s.x > 0.1 * kSwDc) a = &s;
        if (!b && s.x > 0.9 * kSwDc) b = &s;
        peak = std::max(peak, s.v);
      }
      return std::pair<double, double>{a && b ? (b->x - a->x) / (b->t - a->t) : 0.0, peak};
    };
    const auto [mean, peak] = weakening(run);
    const auto [ode_mean, ode_peak] = weakening(direct);
    std::printf("slip weakening k = %.1f k_c: mean speed while weakening %.4f vd (direct integration %.4f, "
                "quasi-static %s), peak %.3f vd (%.3f), slip at the end %.5f m (%.5f)\n",
                ratio, mean / kSwVd, ode_mean / kSwVd, ratio > 1 ? "2" : "none", peak / kSwVd, ode_peak / kSwVd,
                run.back().x, direct.back().x);
    EXPECT_NEAR(mean, ode_mean, 0.03 * ode_mean);
    EXPECT_NEAR(peak, ode_peak, 0.03 * ode_peak);
    EXPECT_NEAR(run.back().x, direct.back().x, 0.02 * direct.back().x);
    if (ratio > 1) {
      EXPECT_NEAR(mean, 2 * kSwVd, 0.05 * 2 * kSwVd);  // quasi-static, within the slider's ringing
    } else {
      EXPECT_GT(peak, 20 * kSwVd);  // a dynamic slip event
    }
  }
}

}  // namespace
}  // namespace dda::df
