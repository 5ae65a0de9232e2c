#pragma once
// The friction laws beyond Coulomb (each defined in df/src/core/friction_<name>.cpp
// and listed in friction_registry.cpp). Every law gives a friction
// coefficient mu >= 0; the strength of a contact is then
//   mu * N (N > 0, compression) + cohesion * l (while bonded),
// so cohesion and tensile strength stay per joint set whatever the law.
// Parameters, units and defaults: docs/scenario.md (joints); physics:
// docs/friction.md.
#include <string>

#include "dda/df/core/friction.hpp"

namespace dda::df {

// mu * N + c l (bonded); shared by the laws below.
double friction_strength(double mu, const FrictionInput& in, double cohesion);

// Log-linear velocity dependence: mu = mu_ref + s ln(max(V, v_min) / v_ref),
// never below 0. s < 0 weakens with speed, s > 0 strengthens. No memory.
class LogLinearFriction final : public FrictionLaw {
 public:
  explicit LogLinearFriction(const JointProperties& joint);
  static FrictionLawSpec spec();
  std::string name() const override { return "log_linear"; }
  double mu(double v) const;
  double strength(const FrictionInput& in, const FrictionState& state) const override;

 private:
  double mu_ref_, s_, v_ref_, v_min_, cohesion_;
};

// Dieterich-Ruina rate and state, regularised near V = 0:
//   mu = a asinh( V / (2 V0) exp((mu0 + b ln(V0 theta / Dc)) / a) ),
// which is mu0 + a ln(V/V0) + b ln(V0 theta/Dc) to within exp(-2 x / a)
// once that is well above a (any sliding speed of interest), and 0 at V = 0
// instead of -infinity. theta evolves by the aging law dtheta/dt =
// 1 - V theta / Dc or the slip law dtheta/dt = -(V theta / Dc) ln(V theta / Dc),
// each integrated exactly over a step at constant V. A state of 0 (a fresh
// contact) stands for theta = Dc / v_init.
class RateStateFriction final : public FrictionLaw {
 public:
  enum class Evolution { Aging, Slip };
  explicit RateStateFriction(const JointProperties& joint);
  RateStateFriction(double mu0, double a, double b, double dc, double v0, double v_init, Evolution evolution);
  static FrictionLawSpec spec();
  std::string name() const override { return "rate_state"; }
  double mu(double v, double theta) const;
  double steady_state_mu(double v) const;                   // mu0 + (a - b) ln(V / V0)
  double evolve(double theta, double v, double dt) const;  // theta after dt at constant V
  double initial_theta() const { return dc_ / v_init_; }
  double strength(const FrictionInput& in, const FrictionState& state) const override;
  void advance(const FrictionInput& in, FrictionState& state) const override;

 private:
  double theta_of(const FrictionState& s) const { return s.theta > 0 ? s.theta : initial_theta(); }
  double mu0_, a_, b_, dc_, v0_, v_init_, cohesion_ = 0;
  Evolution evolution_;
};

// Stribeck: mu = mu_k + (mu_s - mu_k) exp(-V / v_s) + mu_v V, the viscous
// term (default 0) being the rising branch of the full Stribeck curve. No
// memory.
class StribeckFriction final : public FrictionLaw {
 public:
  explicit StribeckFriction(const JointProperties& joint);
  static FrictionLawSpec spec();
  std::string name() const override { return "stribeck"; }
  double mu(double v) const;
  // The driving speed below which steady sliding is unstable (mu falls with
  // V): v_s ln((mu_s - mu_k) / (mu_v v_s)), at least 0; infinite for mu_v = 0.
  double critical_speed() const;
  double strength(const FrictionInput& in, const FrictionState& state) const override;

 private:
  double mu_s_, mu_k_, v_s_, mu_v_, cohesion_;
};

// Linear slip weakening: mu = mu_s - (mu_s - mu_d) min(D / Dc, 1), D the
// contact's cumulative slip (FrictionState::slip) at the end of the step.
class SlipWeakeningFriction final : public FrictionLaw {
 public:
  explicit SlipWeakeningFriction(const JointProperties& joint);
  static FrictionLawSpec spec();
  std::string name() const override { return "slip_weakening"; }
  double mu(double slip) const;
  double strength(const FrictionInput& in, const FrictionState& state) const override;

 private:
  double mu_s_, mu_d_, dc_, cohesion_;
};

// Degradation of the friction angle (Goodman & Seed style):
//   phi = phi_residual + (phi_peak - phi_residual) exp(-D / dc)   (measure: slip)
//   phi = phi_residual + (phi_peak - phi_residual) exp(-n / nc)   (measure: cycles)
// D the cumulative slip, n the number of load cycles = half the number of
// slip reversals the contact has gone through. The cycle count and the last
// slip direction are the state: FrictionState::extra = [reversals, last sign].
class DegradationFriction final : public FrictionLaw {
 public:
  enum class Measure { Slip, Cycles };
  explicit DegradationFriction(const JointProperties& joint);
  static FrictionLawSpec spec();
  std::string name() const override { return "degradation"; }
  double phi_deg(double amount) const;  // amount: slip (m) or cycles
  static double reversals(const FrictionState& s) { return s.extra.empty() ? 0.0 : s.extra[0]; }
  double strength(const FrictionInput& in, const FrictionState& state) const override;
  void advance(const FrictionInput& in, FrictionState& state) const override;

 private:
  double phi_peak_, phi_residual_, scale_, cohesion_;
  Measure measure_;
};

}  // namespace dda::df
