// Coulomb-Mohr friction, and the plain form of FrictionState.
#include <cmath>

#include "dda/common/error.hpp"
#include "dda/df/core/friction.hpp"

namespace dda::df {

CoulombFriction::CoulombFriction(double friction_deg, double cohesion)
    : tan_phi_(std::tan(deg2rad(friction_deg))), cohesion_(cohesion) {}

double CoulombFriction::strength(const FrictionInput& in, const FrictionState& /*state*/) const {
  // A contact in tension (N < 0) has no frictional strength; its bond, if
  // any, is handled by the tensile check before friction is asked.
  const double frictional = in.normal_force > 0 ? in.normal_force * tan_phi_ : 0.0;
  return frictional + (in.bonded ? cohesion_ * in.contact_length : 0.0);
}

std::vector<double> FrictionState::to_vector() const {
  std::vector<double> v{theta, slip};
  v.insert(v.end(), extra.begin(), extra.end());
  return v;
}

FrictionState FrictionState::from_vector(const std::vector<double>& v) {
  if (v.size() < 2) throw InputError("A saved friction state needs at least two numbers (theta, slip).");
  FrictionState s;
  s.theta = v[0];
  s.slip = v[1];
  s.extra.assign(v.begin() + 2, v.end());
  return s;
}

}  // namespace dda::df
