// Dieterich-Ruina rate-and-state friction (aging or slip law), regularised
// at V = 0 (see friction_laws.hpp and docs/friction.md).
#include <cmath>
#include <limits>

#include "dda/df/core/friction_laws.hpp"

namespace dda::df {

FrictionLawSpec RateStateFriction::spec() {
  const double required = std::numeric_limits<double>::quiet_NaN();
  return {{{"mu0", required, Range::non_negative(), "1"},
           {"a", required, Range::positive(), "1"},
           {"b", required, Range::non_negative(), "1"},
           {"dc", required, Range::positive(), "m"},
           {"v0", 1e-6, Range::positive(), "m/s"},
           {"v_init", required, Range::positive(), "m/s"}},
          {{"evolution", {"aging", "slip"}}}};
}

RateStateFriction::RateStateFriction(double mu0, double a, double b, double dc, double v0, double v_init,
                                     Evolution evolution)
    : mu0_(mu0), a_(a), b_(b), dc_(dc), v0_(v0), v_init_(v_init), evolution_(evolution) {}

RateStateFriction::RateStateFriction(const JointProperties& joint) : cohesion_(joint.cohesion) {
  const FrictionParameters p("rate_state", spec(), joint);
  mu0_ = p.number("mu0");
  a_ = p.number("a");
  b_ = p.number("b");
  dc_ = p.number("dc");
  v0_ = p.number("v0");
  v_init_ = p.number("v_init", v0_);  // default: a contact starts at steady state for V0
  evolution_ = p.word("evolution") == "slip" ? Evolution::Slip : Evolution::Aging;
}

double RateStateFriction::mu(double v, double theta) const {
  if (!(v > 0)) return 0.0;
  // ln of the asinh argument, V/(2 V0) exp(psi/a), kept in logs: psi/a is
  // mu0/a = 60 for typical rock values and can overflow exp() for small a.
  const double log_arg = std::log(v / (2 * v0_)) + (mu0_ + b_ * std::log(v0_ * theta / dc_)) / a_;
  // asinh(y) = ln(2y) + O(1/y^2): past y = e^20 the two agree to 1e-17.
  if (log_arg > 20) return a_ * (log_arg + std::log(2.0));
  return a_ * std::asinh(std::exp(log_arg));
}

double RateStateFriction::steady_state_mu(double v) const { return mu0_ + (a_ - b_) * std::log(v / v0_); }

double RateStateFriction::evolve(double theta, double v, double dt) const {
  const double x = v * dt / dc_;  // slip over the step in units of Dc
  if (evolution_ == Evolution::Aging) {
    // d(theta)/dt = 1 - V theta / Dc at constant V:
    // theta(dt) = theta e^-x + Dc/V (1 - e^-x), with Dc/V = dt / x; at V = 0
    // the contact just ages, theta + dt.
    if (!(x > 1e-300)) return theta + dt;
    return theta * std::exp(-x) - dt * std::expm1(-x) / x;
  }
  // Slip law: phi = ln(V theta / Dc) obeys d(phi)/dt = -(V/Dc) phi, so
  // phi(dt) = phi e^-x and theta(dt) = theta exp(phi (e^-x - 1)). It does
  // not age at V = 0.
  const double r = v * theta / dc_;
  if (!(x > 1e-300) || !(r > 0)) return theta;
  return theta * std::exp(std::log(r) * std::expm1(-x));
}

double RateStateFriction::strength(const FrictionInput& in, const FrictionState& state) const {
  // theta at the end of the step at the iterate's speed: the state evolves
  // implicitly with the step, and advance() then stores the same value.
  const double theta = evolve(theta_of(state), in.slip_velocity, in.dt);
  return friction_strength(mu(in.slip_velocity, theta), in, cohesion_);
}

void RateStateFriction::advance(const FrictionInput& in, FrictionState& state) const {
  state.theta = evolve(theta_of(state), in.slip_velocity, in.dt);
}

}  // namespace dda::df
