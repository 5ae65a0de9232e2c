// Stribeck friction: mu = mu_k + (mu_s - mu_k) exp(-V / v_s).
#include <cmath>
#include <limits>

#include "dda/df/friction_laws.hpp"

namespace dda::df {

FrictionLawSpec StribeckFriction::spec() {
  const double required = std::numeric_limits<double>::quiet_NaN();
  return {{{"mu_s", required, Range::non_negative(), "1"},
           {"mu_k", required, Range::non_negative(), "1"},
           {"v_s", required, Range::positive(), "m/s"}},
          {}};
}

StribeckFriction::StribeckFriction(const JointProperties& joint) : cohesion_(joint.cohesion) {
  const FrictionParameters p("stribeck", spec(), joint);
  mu_s_ = p.number("mu_s");
  mu_k_ = p.number("mu_k");
  v_s_ = p.number("v_s");
  // mu_k > mu_s would be a strengthening law under a misleading name.
  if (mu_k_ > mu_s_) p.fail("mu_k", "must not exceed mu_s (" + std::to_string(mu_s_) + ")");
}

double StribeckFriction::mu(double v) const { return mu_k_ + (mu_s_ - mu_k_) * std::exp(-std::abs(v) / v_s_); }

double StribeckFriction::strength(const FrictionInput& in, const FrictionState& /*state*/) const {
  // A locked contact sees the tiny speed of its shear spring, so it holds
  // mu_s; a sliding one drops toward mu_k within a few v_s.
  return friction_strength(mu(in.slip_velocity), in, cohesion_);
}

}  // namespace dda::df
