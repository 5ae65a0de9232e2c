// The normal laws of a contact and their table (normal_law.hpp).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "dda/common/error.hpp"
#include "dda/df/core/normal_law.hpp"

namespace dda::df {
namespace {

std::unique_ptr<NormalLaw> make_penalty(const std::map<std::string, double>& /*numbers*/, double pn) {
  return std::make_unique<PenaltyNormal>(pn);
}

std::unique_ptr<NormalLaw> make_oden_martins(const std::map<std::string, double>& numbers, double /*pn*/) {
  return std::make_unique<OdenMartinsNormal>(numbers.at("c_n"), numbers.at("m_n"));
}

std::string num(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

}  // namespace

OdenMartinsNormal::OdenMartinsNormal(double c_n, double m_n) : c_n_(c_n), m_n_(m_n) {}

double OdenMartinsNormal::force(double g) const { return g > 0 ? c_n_ * std::pow(g, m_n_) : 0.0; }

double OdenMartinsNormal::stiffness(double g) const {
  // m_n = 1 is c_n at g = 0 too (pow(0, 0) = 1); m_n > 1 starts at 0.
  return m_n_ * c_n_ * std::pow(std::max(g, 0.0), m_n_ - 1);
}

double OdenMartinsNormal::penetration_at_force(double n) const {
  return n > 0 ? std::pow(n / c_n_, 1 / m_n_) : 0.0;
}

double OdenMartinsNormal::energy_at_force(double n) const {
  // integral of c_n g^m dg = c_n g^(m+1) / (m+1) = n g / (m+1)
  return n * penetration_at_force(n) / (m_n_ + 1);
}

NormalSpring normal_spring_over_step(const NormalLaw* law, double pn, double dn0) {
  if (!law || law->linear()) return {pn, dn0};
  const double g0 = std::max(-dn0, 0.0);
  const double k = law->stiffness(g0);
  return {k, k > 0 ? dn0 + g0 - law->force(g0) / k : dn0};
}

const std::vector<NormalLawEntry>& normal_laws() {
  // One line per law.
  static const std::vector<NormalLawEntry> laws{
      {"penalty", {}, &make_penalty},
      {"oden_martins",
       {{"c_n", Range::positive(), "N/m^(1+m_n)"}, {"m_n", Range{1, 10, false, false}, "1"}},
       &make_oden_martins},
  };
  return laws;
}

const NormalLawEntry* find_normal_law(const std::string& name) {
  for (const NormalLawEntry& e : normal_laws())
    if (e.name == name) return &e;
  return nullptr;
}

std::unique_ptr<NormalLaw> make_normal_law(const JointProperties& joint, double pn) {
  const NormalLawEntry* law = find_normal_law(joint.normal_law);
  if (!law) {
    std::string known;
    for (const NormalLawEntry& e : normal_laws()) known += (known.empty() ? "" : ", ") + e.name;
    throw InputError("Unknown normal law '" + joint.normal_law + "' (known: " + known + ").");
  }
  const std::string head = "Normal law " + law->name + ": parameter ";
  for (const auto& [key, value] : joint.normal_parameters) {
    bool known = false;
    for (const NormalLawParameter& p : law->numbers) known = known || p.key == key;
    if (!known) throw InputError(head + key + " is not a number the law reads.");
  }
  for (const NormalLawParameter& p : law->numbers) {
    const auto it = joint.normal_parameters.find(p.key);
    if (it == joint.normal_parameters.end()) throw InputError(head + p.key + " is required (" + p.unit + ").");
    if (!std::isfinite(it->second) || !p.range.contains(it->second))
      throw InputError(head + p.key + " must be " + p.range.describe() + ", got " + num(it->second) + ".");
  }
  return law->make(joint.normal_parameters, pn);
}

}  // namespace dda::df
