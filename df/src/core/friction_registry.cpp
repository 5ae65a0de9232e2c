// The table of friction laws, the reader of their parameters, and the
// "stuck" law used while the model settles.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "dda/df/core/friction.hpp"
#include "dda/df/core/friction_laws.hpp"

namespace dda::df {
namespace {

template <class Law>
std::unique_ptr<FrictionLaw> make(const JointProperties& j) {
  return std::make_unique<Law>(j);
}

FrictionLawSpec no_parameters() { return {}; }

std::unique_ptr<FrictionLaw> make_coulomb(const JointProperties& j) {
  return std::make_unique<CoulombFriction>(j.friction_deg, j.cohesion);
}

std::string num(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

class StuckFriction final : public FrictionLaw {
 public:
  std::string name() const override { return "stuck"; }
  double strength(const FrictionInput& /*in*/, const FrictionState& /*state*/) const override {
    return std::numeric_limits<double>::max();
  }
};

}  // namespace

const std::vector<FrictionLawEntry>& friction_laws() {
  // One line per law.
  static const std::vector<FrictionLawEntry> laws{
      {"coulomb", &no_parameters, &make_coulomb},
      {"log_linear", &LogLinearFriction::spec, &make<LogLinearFriction>},
      {"rate_state", &RateStateFriction::spec, &make<RateStateFriction>},
      {"stribeck", &StribeckFriction::spec, &make<StribeckFriction>},
      {"slip_weakening", &SlipWeakeningFriction::spec, &make<SlipWeakeningFriction>},
      {"degradation", &DegradationFriction::spec, &make<DegradationFriction>},
  };
  return laws;
}

const FrictionLawEntry* find_friction_law(const std::string& name) {
  for (const FrictionLawEntry& e : friction_laws())
    if (e.name == name) return &e;
  return nullptr;
}

std::unique_ptr<FrictionLaw> make_friction_law(const JointProperties& joint) {
  if (const FrictionLawEntry* e = find_friction_law(joint.friction_law)) return e->make(joint);
  std::string known;
  for (const FrictionLawEntry& e : friction_laws()) known += (known.empty() ? "" : ", ") + e.name;
  throw InputError("Unknown friction law '" + joint.friction_law + "' (known: " + known + ").");
}

const FrictionLaw* stuck_friction() {
  static const StuckFriction law;
  return &law;
}

FrictionParameters::FrictionParameters(const std::string& law, const FrictionLawSpec& spec,
                                       const JointProperties& joint)
    : law_(law), spec_(spec), joint_(joint) {
  // Everything given must be something the law reads, in the right form.
  for (const auto& [key, value] : joint.friction_parameters) {
    bool known = false;
    for (const FrictionParameter& p : spec_.numbers) known = known || p.key == key;
    if (!known) fail(key, "is not a number the law reads");
    if (!std::isfinite(value)) fail(key, "must be a finite number");
  }
  for (const auto& [key, value] : joint.friction_options) {
    const FrictionOption* o = nullptr;
    for (const FrictionOption& w : spec_.words)
      if (w.key == key) o = &w;
    if (!o) fail(key, "is not a word the law reads");
    std::string choices;
    bool ok = false;
    for (const std::string& c : o->choices) {
      choices += (choices.empty() ? "" : ", ") + c;
      ok = ok || c == value;
    }
    if (!ok) fail(key, "must be one of " + choices + ", got '" + value + "'");
  }
}

const FrictionParameter& FrictionParameters::spec_of(const std::string& key) const {
  for (const FrictionParameter& p : spec_.numbers)
    if (p.key == key) return p;
  throw InternalError("friction law " + law_ + " reads '" + key + "' without declaring it");
}

bool FrictionParameters::given(const std::string& key) const {
  return joint_.friction_parameters.count(key) > 0;
}

double FrictionParameters::number(const std::string& key) const { return number(key, spec_of(key).fallback); }

double FrictionParameters::number(const std::string& key, double fallback) const {
  const FrictionParameter& p = spec_of(key);
  const auto it = joint_.friction_parameters.find(key);
  if (it == joint_.friction_parameters.end()) {
    if (std::isnan(fallback)) fail(key, "is required (" + p.unit + ")");
    return fallback;
  }
  if (!p.range.contains(it->second)) fail(key, "must be " + p.range.describe() + ", got " + num(it->second));
  return it->second;
}

std::string FrictionParameters::word(const std::string& key) const {
  for (const FrictionOption& o : spec_.words)
    if (o.key == key) {
      const auto it = joint_.friction_options.find(key);
      return it == joint_.friction_options.end() ? o.choices.front() : it->second;
    }
  throw InternalError("friction law " + law_ + " reads '" + key + "' without declaring it");
}

void FrictionParameters::fail(const std::string& key, const std::string& phrase) const {
  throw FrictionParameterError(law_, key, phrase);
}

double friction_strength(double mu, const FrictionInput& in, double cohesion) {
  // As Coulomb: nothing frictional in tension, cohesion only while bonded.
  const double frictional = in.normal_force > 0 ? in.normal_force * std::max(mu, 0.0) : 0.0;
  return frictional + (in.bonded ? cohesion * in.contact_length : 0.0);
}

}  // namespace dda::df
