// The friction laws on their own (friction_laws.hpp): closed forms of each
// law, the V7 velocity step of rate and state (docs/validation.md V7) integrated with
// the laws' own exact state update, and the checks of their parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "dda/common/error.hpp"
#include "dda/df/core/friction_laws.hpp"
#include "df_test_models.hpp"

namespace dda::df {
namespace {

using test::friction_joint;

// mu0 = 0.6, a = 0.01, b = 0.015, Dc = 1e-4 m, V0 = 1e-6 m/s (typical
// laboratory values, velocity weakening: a - b = -0.005).
JointProperties rate_state(const std::string& evolution) {
  return friction_joint("rate_state", {{"mu0", 0.6}, {"a", 0.01}, {"b", 0.015}, {"dc", 1e-4}, {"v0", 1e-6}},
               {{"evolution", evolution}});
}

FrictionInput at_speed(double v, double dt, double n = 1.0) {
  FrictionInput in;
  in.normal_force = n;
  in.slip_velocity = v;
  in.dt = dt;
  return in;
}

TEST(FrictionLaws, RateStateSteadyStateIsMu0PlusAMinusBLog) {
  // At theta = Dc / V: mu = mu0 + (a - b) ln(V / V0) (docs/formulation.md);
  // the regularised form differs by a exp(-2 mu/a)-small terms, so to 1e-12.
  const RateStateFriction law(rate_state("aging"));
  for (const double v : {1e-9, 1e-6, 1e-4, 1e-2, 1.0}) {
    const double expected = 0.6 - 0.005 * std::log(v / 1e-6);
    EXPECT_NEAR(law.mu(v, 1e-4 / v), expected, 1e-12) << "V = " << v;
    EXPECT_NEAR(law.steady_state_mu(v), expected, 1e-15);
  }
  // A fresh contact (theta = 0 in its state) starts at Dc / v_init, v_init = V0 by default.
  EXPECT_NEAR(law.initial_theta(), 100.0, 1e-12);
}

TEST(FrictionLaws, RateStateIsRegularisedAtRest) {
  // asinh form: 0 at V = 0 (not -infinity), increasing in V, finite everywhere.
  const RateStateFriction law(rate_state("aging"));
  EXPECT_EQ(law.mu(0.0, 100.0), 0.0);
  double last = 0;
  for (double v = 1e-30; v < 10; v *= 10) {
    const double mu = law.mu(v, 100.0);
    EXPECT_TRUE(std::isfinite(mu));
    EXPECT_GT(mu, last);
    last = mu;
  }
}

TEST(FrictionLaws, AgingLawUpdateIsExact) {
  // theta' = 1 - V theta / Dc integrated with 1e5 RK4 steps against the
  // law's one-step closed form over the same interval.
  const RateStateFriction law(rate_state("aging"));
  const double v = 3e-5, dc = 1e-4, t = 10.0;
  double theta = 100.0;
  const int n = 100000;
  const double h = t / n;
  auto f = [&](double th) { return 1 - v * th / dc; };
  for (int k = 0; k < n; ++k) {
    const double k1 = f(theta), k2 = f(theta + h / 2 * k1), k3 = f(theta + h / 2 * k2), k4 = f(theta + h * k3);
    theta += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  EXPECT_NEAR(law.evolve(100.0, v, t), theta, 1e-10 * theta);
  EXPECT_NEAR(law.evolve(5.0, 0.0, 2.0), 7.0, 1e-15);  // at rest it ages: theta + t
}

// A velocity step V1 -> V2 after steady sliding at V1: the friction right
// after the step and the friction after `slip` at V2, stepping the state by
// the law's exact update in steps of slip Dc / 1000.
struct StepResponse {
  double before, peak, at_dc, after;
};
StepResponse velocity_step(const RateStateFriction& law, double v1, double v2, double slip) {
  const double dc = 1e-4, dt = 1e-3 * dc / v2;
  FrictionState s;
  s.theta = dc / v1;
  StepResponse r{};
  r.before = law.mu(v1, s.theta);
  // The friction the law gives over the first step at V2 (the state evolved
  // over that step, Dc / 1000 of slip: an offset of b / 1000 at most).
  r.peak = law.strength(at_speed(v2, dt), s);
  const int n = static_cast<int>(std::lround(slip / (v2 * dt)));
  for (int k = 0; k < n; ++k) {
    law.advance(at_speed(v2, dt), s);
    if (k + 1 == 1000) r.at_dc = law.mu(v2, s.theta);
  }
  r.after = law.mu(v2, s.theta);
  return r;
}

TEST(FrictionLaws, V7VelocityStepDirectEffectAndSteadyShift) {
  // docs/validation.md V7: V1 = 1e-6 -> V2 = 1e-5 m/s. The friction jumps by
  // a ln(V2/V1) = 0.023026 and settles, after a slip of ~Dc, at the new
  // steady value, shifted by (a - b) ln(V2/V1) = -0.011513. Both to 1 %.
  const double v1 = 1e-6, v2 = 1e-5, ln = std::log(v2 / v1);
  for (const char* evolution : {"aging", "slip"}) {
    const RateStateFriction law(rate_state(evolution));
    const StepResponse r = velocity_step(law, v1, v2, 20 * 1e-4);
    const double direct = r.peak - r.before, shift = r.after - r.before;
    std::printf("V7 law (%s): direct %.6f (expected %.6f), shift %.6f (expected %.6f)\n", evolution, direct,
                0.01 * ln, shift, -0.005 * ln);
    EXPECT_NEAR(direct, 0.01 * ln, 0.01 * 0.01 * ln) << evolution;
    EXPECT_NEAR(shift, -0.005 * ln, 0.01 * 0.005 * ln) << evolution;
    // Relaxation over ~Dc: after a slip of Dc the excess over the new steady
    // value is, for the slip law, b ln(V2/V1) e^-1 (ln(V theta / Dc) decays
    // as e^(-slip/Dc)); for the aging law b ln(1 + (V2/V1 - 1) e^-1) (theta
    // - Dc/V2 decays as e^(-slip/Dc)).
    const double left = std::string(evolution) == "slip" ? 0.015 * ln * std::exp(-1.0)
                                                         : 0.015 * std::log(1 + (v2 / v1 - 1) * std::exp(-1.0));
    EXPECT_NEAR(r.at_dc - r.after, left, 0.01 * left) << evolution;
  }
}

TEST(FrictionLaws, AgingAndSlipLawsReachTheSameSteadyState) {
  // From far from steady (theta = 1 s, a long-healed contact) at V = 1e-4
  // m/s, 30 Dc of slip: both forms end at mu0 + (a - b) ln(V/V0).
  const double v = 1e-4;
  for (const char* evolution : {"aging", "slip"}) {
    const RateStateFriction law(rate_state(evolution));
    double theta = 1.0;
    for (int k = 0; k < 3000; ++k) theta = law.evolve(theta, v, 1e-2 * 1e-4 / v);
    EXPECT_NEAR(law.mu(v, theta), law.steady_state_mu(v), 1e-9) << evolution;
  }
}

TEST(FrictionLaws, StribeckLimits) {
  // mu(0) = mu_s, mu(v_s) = mu_k + (mu_s - mu_k) / e, mu(20 v_s) = mu_k to 2e-10.
  const StribeckFriction law(friction_joint("stribeck", {{"mu_s", 0.6}, {"mu_k", 0.5}, {"v_s", 1e-3}}));
  EXPECT_DOUBLE_EQ(law.mu(0), 0.6);
  EXPECT_NEAR(law.mu(1e-3), 0.5 + 0.1 / std::exp(1.0), 1e-15);
  EXPECT_NEAR(law.mu(2e-2), 0.5, 1e-9);
  EXPECT_NEAR(law.strength(at_speed(0, 1e-3, 1000), {}), 600, 1e-9);  // mu_s N
}

TEST(FrictionLaws, StribeckViscousBranch) {
  // mu_v = 1 s/m: mu(0.1 m/s) = 0.5 + 0.1 e^-10 + 0.1 = 0.6000045; the
  // slope mu_v - (mu_s - mu_k)/v_s e^(-V/v_s) vanishes at
  // V_cr = 0.01 ln(0.1 / (1 x 0.01)) = 0.0230259 m/s (hand-computed).
  const StribeckFriction law(friction_joint("stribeck", {{"mu_s", 0.6}, {"mu_k", 0.5}, {"v_s", 1e-2}, {"mu_v", 1.0}}));
  EXPECT_NEAR(law.mu(0.1), 0.5 + 0.1 * std::exp(-10.0) + 0.1, 1e-15);
  EXPECT_NEAR(law.critical_speed(), 0.0230259, 1e-7);
  const double h = 1e-7, v = law.critical_speed();
  EXPECT_NEAR((law.mu(v + h) - law.mu(v - h)) / (2 * h), 0.0, 1e-6);
  // Without the viscous branch the slope never turns: no stable speed.
  const StribeckFriction plain(friction_joint("stribeck", {{"mu_s", 0.6}, {"mu_k", 0.5}, {"v_s", 1e-2}}));
  EXPECT_TRUE(std::isinf(plain.critical_speed()));
}

TEST(FrictionLaws, LogLinearIsFlooredAndNeverNegative) {
  // mu = 0.5 + s ln(V / 1e-3), floored at v_min = 1e-6.
  const LogLinearFriction weak(
      friction_joint("log_linear", {{"mu_ref", 0.5}, {"s", -0.02}, {"v_ref", 1e-3}, {"v_min", 1e-6}}));
  EXPECT_NEAR(weak.mu(1e-3), 0.5, 1e-15);
  EXPECT_NEAR(weak.mu(1e-1), 0.5 - 0.02 * std::log(100.0), 1e-15);
  EXPECT_NEAR(weak.mu(0), 0.5 + 0.02 * std::log(1000.0), 1e-15);  // floor
  EXPECT_EQ(weak.mu(1e30), 0.0);                                   // weakening stops at 0
  const LogLinearFriction strong(friction_joint("log_linear", {{"mu_ref", 0.5}, {"s", 0.02}, {"v_ref", 1e-3}}));
  EXPECT_GT(strong.mu(1e-2), strong.mu(1e-3));
}

TEST(FrictionLaws, SlipWeakeningReachesMuDAtDc) {
  // mu_s = 0.7 -> mu_d = 0.4 over Dc = 0.01 m: 0.55 half way, 0.4 at and beyond Dc.
  const SlipWeakeningFriction law(friction_joint("slip_weakening", {{"mu_s", 0.7}, {"mu_d", 0.4}, {"dc", 0.01}}));
  EXPECT_DOUBLE_EQ(law.mu(0), 0.7);
  EXPECT_NEAR(law.mu(0.005), 0.55, 1e-15);
  EXPECT_NEAR(law.mu(0.01), 0.4, 1e-15);
  EXPECT_NEAR(law.mu(0.5), 0.4, 1e-15);
  FrictionState s;
  s.slip = 0.004;  // plus this step's 0.001 (V dt): 0.005
  EXPECT_NEAR(law.strength(at_speed(0.1, 0.01, 100), s), 55, 1e-12);
}

TEST(FrictionLaws, DegradationIsMonotoneToResidual) {
  // With slip: phi = 20 + 20 exp(-D / 0.05) (degrees), from 40 to 20.
  JointProperties j = friction_joint("degradation", {{"phi_residual", 20}, {"dc", 0.05}});
  j.friction_deg = 40;  // phi_peak defaults to the set's friction angle
  const DegradationFriction by_slip(j);
  double last = 90;
  for (double d = 0; d < 1.0; d += 0.01) {
    const double phi = by_slip.phi_deg(d);
    EXPECT_LT(phi, last);
    EXPECT_GE(phi, 20.0);
    last = phi;
  }
  EXPECT_DOUBLE_EQ(by_slip.phi_deg(0), 40.0);
  EXPECT_NEAR(by_slip.phi_deg(0.05), 20 + 20 / std::exp(1.0), 1e-12);
  EXPECT_NEAR(by_slip.phi_deg(10), 20, 1e-12);

  // With cycles (nc = 2): slip +, -, +, - is 3 reversals = 1.5 cycles;
  // sticking (sign 0) and sliding on in the same direction are not reversals.
  const DegradationFriction by_cycles(friction_joint("degradation", {{"phi_peak", 40}, {"phi_residual", 20}, {"nc", 2}},
                                            {{"measure", "cycles"}}));
  FrictionState s;
  FrictionInput in = at_speed(0.1, 1e-3, 1.0);
  for (const int sign : {1, 1, 0, 1, -1, 0, -1, 1, -1}) {
    in.slip_sign = sign;
    by_cycles.advance(in, s);
  }
  EXPECT_EQ(DegradationFriction::reversals(s), 3.0);
  EXPECT_NEAR(by_cycles.strength(at_speed(0, 1e-3, 1.0), s), std::tan(deg2rad(20 + 20 * std::exp(-0.75))), 1e-12);
  // The state round-trips through its plain (checkpoint) form.
  const FrictionState back = FrictionState::from_vector(s.to_vector());
  EXPECT_EQ(back.extra, s.extra);
}

TEST(FrictionLaws, CohesionAndTensionAreTheSameForEveryLaw) {
  // Strength = mu N + c l while bonded; nothing frictional in tension.
  for (JointProperties j : {friction_joint("stribeck", {{"mu_s", 0.6}, {"mu_k", 0.5}, {"v_s", 1e-3}}),
                           rate_state("aging"),
                           friction_joint("slip_weakening", {{"mu_s", 0.6}, {"mu_d", 0.4}, {"dc", 0.01}})}) {
    j.cohesion = 1000;
    const auto law = make_friction_law(j);
    FrictionInput in = at_speed(0, 1e-3, -50);
    in.contact_length = 0.5;
    in.bonded = true;
    EXPECT_NEAR(law->strength(in, {}), 500, 1e-12) << j.friction_law;
    in.bonded = false;
    EXPECT_EQ(law->strength(in, {}), 0.0) << j.friction_law;
  }
}

TEST(FrictionLaws, BadParametersAreInputErrors) {
  auto error_of = [](const JointProperties& j) -> std::string {
    try {
      make_friction_law(j);
    } catch (const FrictionParameterError& e) {
      return e.key() + ": " + e.what();
    }
    return "(no error)";
  };
  JointProperties j = rate_state("aging");
  j.friction_parameters["dc"] = -1e-4;
  EXPECT_EQ(error_of(j), "dc: Friction law rate_state: parameter dc must be > 0, got -0.0001.");
  j = rate_state("healing");
  EXPECT_EQ(error_of(j), "evolution: Friction law rate_state: parameter evolution must be one of aging, slip, got "
                         "'healing'.");
  j = rate_state("aging");
  j.friction_parameters.erase("a");
  EXPECT_EQ(error_of(j), "a: Friction law rate_state: parameter a is required (1).");
  j.friction_parameters["A"] = 0.01;
  EXPECT_NE(error_of(j).find("is not a number the law reads"), std::string::npos);
  EXPECT_NE(error_of(friction_joint("stribeck", {{"mu_s", 0.5}, {"mu_k", 0.6}, {"v_s", 1}}))
                .find("mu_k must not exceed mu_s"),
            std::string::npos);
  EXPECT_NE(error_of(friction_joint("degradation", {{"phi_peak", 30}, {"phi_residual", 20}, {"dc", 1}, {"nc", 2}}))
                .find("nc does not apply with measure slip"),
            std::string::npos);
  JointProperties unknown;
  unknown.friction_law = "mohr";
  EXPECT_THROW(make_friction_law(unknown), InputError);
  // build_model() checks the law of every joint set.
  ModelInput in;
  in.geometry.blocks.push_back(test::make_block(test::rectangle(0, 0, 1, 1)));
  in.control.dt = 1e-3;
  in.joint_sets = {rate_state("aging")};
  EXPECT_NO_THROW(build_model(in));
  in.joint_sets[0].friction_parameters["b"] = -0.1;
  EXPECT_THROW(build_model(in), InputError);
}

}  // namespace
}  // namespace dda::df
