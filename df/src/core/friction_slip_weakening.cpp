// Linear slip weakening: mu from mu_s down to mu_d over a slip of dc.
#include <algorithm>
#include <limits>
#include <string>

#include "dda/df/core/friction_laws.hpp"

namespace dda::df {

FrictionLawSpec SlipWeakeningFriction::spec() {
  const double required = std::numeric_limits<double>::quiet_NaN();
  return {{{"mu_s", required, Range::non_negative(), "1"},
           {"mu_d", required, Range::non_negative(), "1"},
           {"dc", required, Range::positive(), "m"}},
          {}};
}

SlipWeakeningFriction::SlipWeakeningFriction(const JointProperties& joint) : cohesion_(joint.cohesion) {
  const FrictionParameters p("slip_weakening", spec(), joint);
  mu_s_ = p.number("mu_s");
  mu_d_ = p.number("mu_d");
  dc_ = p.number("dc");
  if (mu_d_ > mu_s_) p.fail("mu_d", "must not exceed mu_s (" + std::to_string(mu_s_) + ")");
}

double SlipWeakeningFriction::mu(double slip) const {
  return mu_s_ - (mu_s_ - mu_d_) * std::min(std::max(slip, 0.0) / dc_, 1.0);
}

double SlipWeakeningFriction::strength(const FrictionInput& in, const FrictionState& state) const {
  // The slip at the end of the step (the solver adds V dt to state.slip once
  // the step is accepted): the weakening is implicit in the step's slip.
  return friction_strength(mu(state.slip + in.slip_velocity * in.dt), in, cohesion_);
}

}  // namespace dda::df
