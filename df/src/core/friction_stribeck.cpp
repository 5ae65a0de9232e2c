// Stribeck friction: mu = mu_k + (mu_s - mu_k) exp(-V / v_s) + mu_v V.
#include <algorithm>
#include <cmath>
#include <limits>

#include "dda/df/core/friction_laws.hpp"

namespace dda::df {

FrictionLawSpec StribeckFriction::spec() {
  const double required = std::numeric_limits<double>::quiet_NaN();
  return {{{"mu_s", required, Range::non_negative(), "1"},
           {"mu_k", required, Range::non_negative(), "1"},
           {"v_s", required, Range::positive(), "m/s"},
           {"mu_v", 0.0, Range::non_negative(), "s/m"}},
          {}};
}

StribeckFriction::StribeckFriction(const JointProperties& joint) : cohesion_(joint.cohesion) {
  const FrictionParameters p("stribeck", spec(), joint);
  mu_s_ = p.number("mu_s");
  mu_k_ = p.number("mu_k");
  v_s_ = p.number("v_s");
  mu_v_ = p.number("mu_v");
  // mu_k > mu_s would be a strengthening law under a misleading name.
  if (mu_k_ > mu_s_) p.fail("mu_k", "must not exceed mu_s (" + std::to_string(mu_s_) + ")");
}

double StribeckFriction::mu(double v) const {
  return mu_k_ + (mu_s_ - mu_k_) * std::exp(-std::abs(v) / v_s_) + mu_v_ * std::abs(v);
}

double StribeckFriction::critical_speed() const {
  // The slope of mu is mu_v - (mu_s - mu_k) / v_s exp(-V / v_s): negative
  // (a negative dashpot, steady sliding unstable) below this speed.
  const double drop = mu_s_ - mu_k_;
  if (drop <= 0) return 0.0;
  if (mu_v_ <= 0) return std::numeric_limits<double>::infinity();
  return std::max(0.0, v_s_ * std::log(drop / (mu_v_ * v_s_)));
}

double StribeckFriction::strength(const FrictionInput& in, const FrictionState& /*state*/) const {
  // A locked contact sees the tiny speed of its shear spring, so it holds
  // mu_s; a sliding one drops toward mu_k within a few v_s.
  return friction_strength(mu(in.slip_velocity), in, cohesion_);
}

}  // namespace dda::df
