// docs/validation.md V6 (spring-slider with static/kinetic friction; velocity
// weakening vs strengthening) and V7 (rate-and-state velocity step) run
// through the DF solver. The spring is a rock bolt between the slider and a
// driver block that a moving fixed point carries along a prescribed
// displacement history (the "load point" of a spring-slider experiment).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "dda/df/2d/simulation.hpp"
#include "df_test_models.hpp"
#include "spring_slider_model.hpp"

namespace dda::df {
namespace {

using test::kG;
using test::law;
using test::spring_slider;
using test::SpringSlider;

TEST(FrictionV6, StaticKineticSpringSliderSlipAndDuration) {
  // m = 1000 kg, k = 1e5 N/m, W = m g = 9810 N, Stribeck mu_s = 0.6,
  // mu_k = 0.5, v_s = 1 mm/s (docs/validation.md V6): slip per event
  // 2 (mu_s - mu_k) W / k = 0.019620 m, duration pi sqrt(m/k) = 0.31416 s,
  // peak speed (mu_s - mu_k) W / sqrt(k m) = 0.0981 m/s.
  // v_s is 1 % of the peak speed, so friction is mu_k for all but the
  // first and last ~1 ms of the slip; dt = 0.1 ms keeps the open-close
  // iteration on the Stribeck curve convergent (its contraction factor is
  // (mu_s - mu_k) W / v_s * dt / (2 m) = 0.05) and resolves the
  // oscillation (omega dt = 1e-3).
  // Driver: the load point is pulled in 0.5 s to 98 % of the breakaway
  // stretch mu_s W / k (the slider stays stuck), then slowly (6 mm/s) to
  // 100.05 %, then held, so the slip starts from rest at F = mu_s W with the
  // load point still (the analytical assumption); it moves 3e-5 m, 0.15 %
  // of the slip, after the slip has begun.
  const double m = 1000, k = 1e5, w = m * kG, us = 0.6 * w / k;
  SpringSlider s;
  s.joint = law("stribeck", {{"mu_s", 0.6}, {"mu_k", 0.5}, {"v_s", 1e-3}});
  s.driver = TimeHistory{{0, 0.5, 0.7}, {Vec2(0, 0), Vec2(0.98 * us, 0), Vec2(1.0005 * us, 0)}};
  Simulation sim(build_model(spring_slider(s)));
  sim.run_until(1.15);
  const auto& h = sim.histories()[0];
  // Slipping: faster than v_th = 1 mm/s. The sine solution is above v_th
  // for pi/omega - 2 asin(v_th / v_peak) / omega = 0.3121 s (0.65 % short
  // of the full duration), well inside the 2 % asked for.
  const double v_th = 1e-3;
  std::size_t start = 0, end = 0;
  double vmax = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double v = h[i].velocity.x();
    vmax = std::max(vmax, v);
    if (!start && v > v_th) start = i;
    if (start && !end && v < v_th) end = i;
  }
  ASSERT_GT(start, 0u);
  ASSERT_GT(end, start);
  const double slip = h.back().displacement.x() - h[start - 1].displacement.x();
  const double duration = h[end].time - h[start].time;
  const double slip_expected = 2 * (0.6 - 0.5) * w / k, duration_expected = M_PI * std::sqrt(m / k);
  std::printf("V6 stick-slip: slip %.6f m (expected %.6f, error %.2f %%), duration %.5f s (expected %.5f, error "
              "%.2f %%), peak speed %.5f m/s (expected %.5f), onset at t = %.4f s\n",
              slip, slip_expected, 100 * (slip - slip_expected) / slip_expected, duration, duration_expected,
              100 * (duration - duration_expected) / duration_expected, vmax, 0.1 * w / std::sqrt(k * m),
              h[start].time);
  EXPECT_NEAR(slip, slip_expected, 0.02 * slip_expected);
  EXPECT_NEAR(duration, duration_expected, 0.02 * duration_expected);
  EXPECT_NEAR(vmax, 0.1 * w / std::sqrt(k * m), 0.03 * 0.0981);
  // One event only: the slider is stuck again at the end (spring force
  // (2 mu_k - mu_s) W = 0.4 W is below mu_s W).
  EXPECT_LT(std::abs(h.back().velocity.x()), v_th);
}

// The slider's speed over the last `window` seconds of a log-linear run
// driven at 5 cm/s: mu = 0.5 + s ln(V / 0.05 m/s), floored at 0.1 mm/s.
struct SpeedRange {
  double lo, hi;
};
SpeedRange log_linear_run(double s_value) {
  const double k = 1e5, w = 1000 * kG, vd = 0.05, t_end = 3.0, window = 1.0;
  SpringSlider s;
  s.joint = law("log_linear", {{"mu_ref", 0.5}, {"s", s_value}, {"v_ref", vd}, {"v_min", 1e-4}});
  // dt = 0.2 ms: the iteration's contraction factor |s| W / V dt / (2 m) is
  // at most 0.2 (at the floor speed).
  s.dt = 2e-4;
  // The spring starts at 0.35 W (below breakaway: 0.376 W for s > 0,
  // 0.624 W for s < 0) and the load point then moves at vd.
  const double u0 = 0.35 * w / k;
  s.driver = TimeHistory{{0, t_end + 1}, {Vec2(u0, 0), Vec2(u0 + vd * (t_end + 1), 0)}};
  Simulation sim(build_model(spring_slider(s)));
  sim.run_until(t_end);
  SpeedRange r{1e9, -1e9};
  for (const MeasurementSample& m : sim.histories()[0])
    if (m.time > t_end - window) r.lo = std::min(r.lo, m.velocity.x()), r.hi = std::max(r.hi, m.velocity.x());
  std::printf("V6 log-linear s = %+.3f: slider speed in the last %.1f s between %.5f and %.5f m/s (drive %.3f)\n",
              s_value, window, r.lo, r.hi, vd);
  return r;
}

TEST(FrictionV6, VelocityWeakeningGivesStickSlip) {
  // s = -0.02: the friction's slope s W / V acts as a negative dashpot of
  // 3900 N s/m at V = 5 cm/s (damping ratio -0.2); with no other damping,
  // steady sliding is unstable (docs/validation.md V6): the slider alternates between
  // sticking (speed ~0) and slipping well faster than the drive.
  const SpeedRange r = log_linear_run(-0.02);
  EXPECT_LT(r.lo, 0.1 * 0.05);
  EXPECT_GT(r.hi, 2 * 0.05);
}

TEST(FrictionV6, VelocityStrengtheningGivesSteadySliding) {
  // s = +0.02: a positive dashpot s W / V = 3900 N s/m (damping ratio
  // 0.2 of sqrt(k m)), so after breakaway the slider settles to slide
  // steadily at the drive speed.
  const SpeedRange r = log_linear_run(0.02);
  EXPECT_GT(r.lo, 0.95 * 0.05);
  EXPECT_LT(r.hi, 1.05 * 0.05);
}

TEST(FrictionV7, RateStateVelocityStepInTheSolver) {
  // docs/validation.md V7 with mu0 = 0.6, a = 0.01, b = 0.015, Dc = 1e-4 m,
  // V0 = 1e-6 m/s, the load point moving at V1 = 1 mm/s for 0.2 s (2 Dc of
  // slip), then at V2 = 10 mm/s for 0.1 s (10 Dc). Expected: steady
  // mu(V1) = mu0 + (a - b) ln(V1/V0) = 0.56546; direct effect
  // a ln(V2/V1) = 0.023026; steady shift (a - b) ln(V2/V1) = -0.011513.
  // Choices, each to stay close to the analytical assumptions:
  // * quasi-static (dynamic = 0): the slider has no inertia to ring with,
  //   and a light slider (1 kg) keeps the step's inertia term 2 m V / dt
  //   small;
  // * a stiff spring (1e10 N/m, far above k_c = (b - a) N / Dc = 5e4 N/m,
  //   so sliding is stable): the slider's speed follows the load point's
  //   within a step, so the state has no time to evolve during the jump;
  // * steps of 2e-3 Dc of slip (dt = 0.2 ms at V1, 20 us at V2: the run is
  //   driven with run_until in steps of 20 us after the jump), so the state
  //   evolves by b * 2e-3 = 3e-5 of friction per step;
  // * N = 1000 N (a point load; the slider's weight adds 9.81 N): the
  //   open-close iteration is a fixed point between the friction and the
  //   slip speed, whose contraction factor is a N / (V k dt) = 0.005 here
  //   (at N = 1e5 N it is 0.5 and slow to settle).
  // The state starts at steady state for V1 (v_init = V1), and the spring
  // reaches the friction force within the first step.
  const double v1 = 1e-3, v2 = 1e-2, t1 = 0.2, t2 = 0.3;
  const double mu1 = 0.6 - 0.005 * std::log(v1 / 1e-6), ln = std::log(v2 / v1);
  SpringSlider s;
  s.slider_density = 2;
  s.normal_load = 1000;
  s.spring = 1e10;
  s.dt = 2e-4;
  s.dynamic = 0.0;
  s.joint = law("rate_state", {{"mu0", 0.6}, {"a", 0.01}, {"b", 0.015}, {"dc", 1e-4}, {"v0", 1e-6}, {"v_init", v1}});
  s.driver = TimeHistory{{0, t1, t2}, {Vec2(0, 0), Vec2(v1 * t1, 0), Vec2(v1 * t1 + v2 * (t2 - t1), 0)}};
  Simulation sim(build_model(spring_slider(s)));
  // Friction as measured: total shear over total normal force of the
  // slider's contacts with the base.
  auto measured_mu = [&]() {
    double shear = 0, normal = 0;
    for (const Contact& c : sim.contacts())
      if ((c.vblock == 1 && c.eblock == 0) || (c.vblock == 0 && c.eblock == 1))
        shear += c.shear_force, normal += c.normal_force;
    return std::abs(shear) / normal;
  };
  double mu_before = 0, peak = 0;
  int unsettled = 0;
  while (sim.time() < t1 - 1e-9) {
    sim.run_until(std::min(t1, sim.time() + s.dt));
    mu_before = measured_mu();
  }
  while (sim.time() < t2 - 1e-9) {
    sim.run_until(std::min(t2, sim.time() + 2e-5));
    peak = std::max(peak, measured_mu());
    unsettled += sim.log().back().open_close_iterations == sim.model().control.max_open_close;
  }
  const double mu_after = measured_mu();
  const double direct = peak - mu_before, shift = mu_after - mu_before;
  std::printf("V7 solver: mu(V1) %.5f (expected %.5f), direct effect %.6f (expected %.6f, error %.2f %%), steady "
              "shift %.6f (expected %.6f, error %.2f %%), %d steps\n",
              mu_before, mu1, direct, 0.01 * ln, 100 * (direct - 0.01 * ln) / (0.01 * ln), shift, -0.005 * ln,
              100 * (shift + 0.005 * ln) / (0.005 * ln), static_cast<int>(sim.log().size()));
  EXPECT_EQ(unsettled, 0);
  EXPECT_NEAR(mu_before, mu1, 0.01 * mu1);
  EXPECT_NEAR(direct, 0.01 * ln, 0.03 * 0.01 * ln);
  EXPECT_NEAR(shift, -0.005 * ln, 0.03 * 0.005 * ln);
}

}  // namespace
}  // namespace dda::df
