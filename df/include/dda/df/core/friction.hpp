#pragma once
// Friction laws behind one interface.
//
// The contact code asks a law for the shear strength of a closed contact; a
// law with memory (rate and state, slip weakening) keeps it in the contact's
// FrictionState and updates it once per accepted step. A new law is one new
// file with a FrictionLaw subclass and one line in friction_laws()
// (df/src/core/friction_registry.cpp); the laws built in are in friction_laws.hpp.
#include <memory>
#include <string>
#include <vector>

#include "dda/common/error.hpp"
#include "dda/common/yaml_reader.hpp"
#include "dda/df/core/joint_properties.hpp"

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
  int slip_sign = 0;           // advance(): +1 / -1 while sliding (direction along the edge), 0 otherwise
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

// ---- Parameters of a law (JointProperties::friction_parameters / _options).

// One number a law reads; `fallback` NaN means required.
struct FrictionParameter {
  std::string key;
  double fallback;
  Range range;
  std::string unit;  // for messages and docs: "1", "m", "m/s", "deg"
};

// One word a law reads; the first choice is the default.
struct FrictionOption {
  std::string key;
  std::vector<std::string> choices;
};

struct FrictionLawSpec {
  std::vector<FrictionParameter> numbers;
  std::vector<FrictionOption> words;
};

// A bad friction parameter: key() names it, phrase() says what is wrong as
// a verb phrase ("must be > 0, got -1"), so the scenario reader can point at
// the key's line; what() is a whole sentence for input built in code.
class FrictionParameterError : public InputError {
 public:
  FrictionParameterError(const std::string& law, const std::string& key, const std::string& phrase)
      : InputError("Friction law " + law + ": parameter " + key + " " + phrase + "."), key_(key), phrase_(phrase) {}
  const std::string& key() const { return key_; }
  const std::string& phrase() const { return phrase_; }

 private:
  std::string key_, phrase_;
};

// Reads a law's parameters from a joint, with the defaults and ranges of its
// spec; anything unknown, missing or out of range is a FrictionParameterError.
class FrictionParameters {
 public:
  FrictionParameters(const std::string& law, const FrictionLawSpec& spec, const JointProperties& joint);
  bool given(const std::string& key) const;
  double number(const std::string& key) const;                    // given, else the spec's fallback
  double number(const std::string& key, double fallback) const;   // given, else `fallback` (range-checked)
  std::string word(const std::string& key) const;
  [[noreturn]] void fail(const std::string& key, const std::string& phrase) const;

 private:
  const FrictionParameter& spec_of(const std::string& key) const;
  std::string law_;
  FrictionLawSpec spec_;
  const JointProperties& joint_;
};

// A law built in: its name, what it reads, how to make it. The table is in
// df/src/core/friction_registry.cpp (one line per law).
struct FrictionLawEntry {
  std::string name;
  FrictionLawSpec (*spec)();
  std::unique_ptr<FrictionLaw> (*make)(const JointProperties&);
};
const std::vector<FrictionLawEntry>& friction_laws();
const FrictionLawEntry* find_friction_law(const std::string& name);  // nullptr if unknown

// The law named in the joint properties; InputError for an unknown name,
// FrictionParameterError for a bad parameter.
std::unique_ptr<FrictionLaw> make_friction_law(const JointProperties& joint);

// A law that never lets go (strength without limit): contacts stick while
// the model settles into equilibrium (Control::initial_equilibrium).
const FrictionLaw* stuck_friction();

}  // namespace dda::df
