// Degradation of the friction angle with cumulative slip or with load
// cycles (Goodman & Seed style): phi from phi_peak to phi_residual.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "dda/df/core/friction_laws.hpp"

namespace dda::df {

FrictionLawSpec DegradationFriction::spec() {
  const double required = std::numeric_limits<double>::quiet_NaN();
  return {{{"phi_peak", required, Range::half_open(0, 90), "deg"},
           {"phi_residual", required, Range::half_open(0, 90), "deg"},
           {"dc", required, Range::positive(), "m"},
           {"nc", required, Range::positive(), "cycles"}},
          {{"measure", {"slip", "cycles"}}}};
}

DegradationFriction::DegradationFriction(const JointProperties& joint) : cohesion_(joint.cohesion) {
  const FrictionParameters p("degradation", spec(), joint);
  phi_peak_ = p.number("phi_peak", joint.friction_deg);  // default: the set's friction angle
  phi_residual_ = p.number("phi_residual");
  if (phi_residual_ > phi_peak_)
    p.fail("phi_residual", "must not exceed phi_peak (" + std::to_string(phi_peak_) + " deg)");
  measure_ = p.word("measure") == "cycles" ? Measure::Cycles : Measure::Slip;
  // Exactly the scale of the chosen measure: the other one would be ignored.
  const char* used = measure_ == Measure::Slip ? "dc" : "nc";
  const char* unused = measure_ == Measure::Slip ? "nc" : "dc";
  if (p.given(unused))
    p.fail(unused, std::string("does not apply with measure ") + (measure_ == Measure::Slip ? "slip" : "cycles") +
                       " (give " + used + ")");
  scale_ = p.number(used);
}

double DegradationFriction::phi_deg(double amount) const {
  return phi_residual_ + (phi_peak_ - phi_residual_) * std::exp(-std::max(amount, 0.0) / scale_);
}

double DegradationFriction::strength(const FrictionInput& in, const FrictionState& state) const {
  // Slip at the end of the step (as slip weakening); cycles completed so far.
  const double amount =
      measure_ == Measure::Slip ? state.slip + in.slip_velocity * in.dt : 0.5 * reversals(state);
  return friction_strength(std::tan(deg2rad(phi_deg(amount))), in, cohesion_);
}

void DegradationFriction::advance(const FrictionInput& in, FrictionState& state) const {
  if (measure_ != Measure::Cycles || in.slip_sign == 0) return;
  // extra = [reversals, sign of the last slip]; a slip against the last one
  // is a reversal, two reversals one cycle.
  if (state.extra.size() < 2) state.extra.assign(2, 0.0);
  const double sign = in.slip_sign > 0 ? 1.0 : -1.0;
  if (state.extra[1] != 0 && state.extra[1] != sign) state.extra[0] += 1;
  state.extra[1] = sign;
}

}  // namespace dda::df
