#pragma once
// Friction laws behind one interface.
//
// The contact code asks a law for the shear strength of a closed contact; a
// law with memory (rate and state, slip weakening) keeps it in the contact's
// FrictionState and updates it once per accepted step. A new law is one new
// file with a FrictionLaw subclass and one line in make_friction_law().
#include <memory>
#include <string>
#include <vector>

#include "dda/df/model.hpp"

namespace dda::df {

// What a law may depend on at one contact. Inside the open-close iteration
// normal_force and slip_velocity are those of the current iterate (the last
// solve), so a velocity-dependent law is iterated to agreement with the
// solution (the iteration goes on until the strength stops changing, see
// update_contact); advance() gets the values of the accepted solution.
struct FrictionInput {
  double normal_force = 0;     // N (compression positive), per unit thickness
  double slip_velocity = 0;    // m/s, |relative sliding speed| at the contact, current iterate
  double contact_length = 0;   // m, length of joint the contact stands for
  double dt = 0;               // s, current step
  bool bonded = false;         // cohesion counts only while the contact is intact
};

// Per-contact memory of a law (unused by Coulomb), carried from step to step
// with its contact (also when the vertex slides onto the next edge of the
// same block). Its plain form, to_vector() / from_vector(), is what a
// checkpoint stores: [theta, slip, extra...].
struct FrictionState {
  double theta = 0;            // state variable (rate and state), s
  double slip = 0;             // cumulative slip, m (updated by the solver while sliding)
  std::vector<double> extra;   // further law-specific variables

  std::vector<double> to_vector() const;
  // Inverse of to_vector(); InputError for fewer than two numbers.
  static FrictionState from_vector(const std::vector<double>& v);
};

class FrictionLaw {
 public:
  virtual ~FrictionLaw() = default;
  virtual std::string name() const = 0;
  // Largest shear force (N, >= 0) the contact carries before it slides.
  virtual double strength(const FrictionInput& in, const FrictionState& state) const = 0;
  // Advances the state over an accepted step (default: no memory).
  virtual void advance(const FrictionInput& /*in*/, FrictionState& /*state*/) const {}
};

// Coulomb-Mohr: c * l (while bonded) + N tan(phi); nothing for tension.
class CoulombFriction final : public FrictionLaw {
 public:
  CoulombFriction(double friction_deg, double cohesion);
  std::string name() const override { return "coulomb"; }
  double strength(const FrictionInput& in, const FrictionState& state) const override;

 private:
  double tan_phi_;
  double cohesion_;
};

// The law named in the joint properties; InputError for an unknown name.
std::unique_ptr<FrictionLaw> make_friction_law(const JointProperties& joint);

// A law that never lets go (strength without limit): contacts stick while
// the model settles into equilibrium (Control::initial_equilibrium).
const FrictionLaw* stuck_friction();

}  // namespace dda::df
