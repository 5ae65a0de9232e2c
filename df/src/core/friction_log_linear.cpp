// Log-linear velocity dependence: mu = mu_ref + s ln(max(V, v_min) / v_ref).
#include <algorithm>
#include <cmath>
#include <limits>

#include "dda/df/core/friction_laws.hpp"

namespace dda::df {

FrictionLawSpec LogLinearFriction::spec() {
  const double required = std::numeric_limits<double>::quiet_NaN();
  return {{{"mu_ref", required, Range::non_negative(), "1"},
           {"s", required, Range::any(), "1"},
           {"v_ref", 1e-6, Range::positive(), "m/s"},
           {"v_min", 1e-9, Range::positive(), "m/s"}},
          {}};
}

LogLinearFriction::LogLinearFriction(const JointProperties& joint) : cohesion_(joint.cohesion) {
  const FrictionParameters p("log_linear", spec(), joint);
  mu_ref_ = p.number("mu_ref");
  s_ = p.number("s");
  v_ref_ = p.number("v_ref");
  v_min_ = p.number("v_min");
}

double LogLinearFriction::mu(double v) const {
  // The floor keeps mu finite for a contact at rest (ln 0); below it the law
  // is flat, which also keeps the open-close iteration from chasing the
  // logarithm's infinite slope at V -> 0. Weakening can drive mu below 0 at
  // high speed: friction never pushes, so it stops at 0.
  return std::max(0.0, mu_ref_ + s_ * std::log(std::max(v, v_min_) / v_ref_));
}

double LogLinearFriction::strength(const FrictionInput& in, const FrictionState& /*state*/) const {
  return friction_strength(mu(in.slip_velocity), in, cohesion_);
}

}  // namespace dda::df
