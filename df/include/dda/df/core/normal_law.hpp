#pragma once
// Normal laws of a closed contact: its normal force against its
// penetration g (m, >= 0), per contact point, as the penalty spring of
// classic DDA is (in 2D per unit thickness too; in 3D the force itself). A law is one small type behind
// NormalLaw and one line in normal_laws() (df/src/core/normal_laws.cpp).
//
// The solver linearises the law once per step about the penetration at the
// start of the step, g0 (ContactGeometry::dn0, ContactGeometry3::dn0):
// N = N(g0) + N'(g0) (g - g0) (normal_spring_over_step below). The force at the end of a step is then
// off the curve by at most N''/2 times the square of the step's change of
// penetration, and the next step starts again from the curve at its own
// g0, so the error does not build up. Physics: docs/friction.md.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "dda/common/yaml_reader.hpp"  // Range
#include "dda/df/core/joint_properties.hpp"

namespace dda::df {

class NormalLaw {
 public:
  virtual ~NormalLaw() = default;
  virtual std::string name() const = 0;
  virtual double force(double g) const = 0;      // N, at penetration g >= 0
  virtual double stiffness(double g) const = 0;  // dN/dg, N/m
  // Elastic energy stored at normal force n >= 0 (J per unit thickness):
  // the integral of N dg from 0 up to the penetration that carries n.
  virtual double energy_at_force(double n) const = 0;
  // The linear penalty: the contact keeps its plain spring pn (the solver's
  // numbers stay those of classic DDA to the last bit).
  virtual bool linear() const { return false; }
};

// Classic DDA: N = pn g (pn = joint's normal_penalty, or its default).
class PenaltyNormal final : public NormalLaw {
 public:
  explicit PenaltyNormal(double pn) : pn_(pn) {}
  std::string name() const override { return "penalty"; }
  double force(double g) const override { return pn_ * g; }
  double stiffness(double /*g*/) const override { return pn_; }
  double energy_at_force(double n) const override { return n * n / (2 * pn_); }
  bool linear() const override { return true; }

 private:
  double pn_;
};

// Oden & Martins' normal compliance: N = c_n g^m_n (m_n >= 1), the load a
// rough interface carries as its asperities are pressed flat. m_n = 1 is
// the penalty spring c_n; m_n > 1 is soft at first touch and stiffens as
// the contact closes (Oden & Martins found 2 to 3.3 for rough metal
// surfaces).
class OdenMartinsNormal final : public NormalLaw {
 public:
  OdenMartinsNormal(double c_n, double m_n);
  std::string name() const override { return "oden_martins"; }
  double force(double g) const override;
  double stiffness(double g) const override;
  double energy_at_force(double n) const override;
  double penetration_at_force(double n) const;  // (n / c_n)^(1/m_n)

 private:
  double c_n_, m_n_;
};

// The spring a closed contact's normal law gives over one step, the same in
// 2D and 3D: N = -k (s0 + the step's change of the gap). The linear
// penalty (or no law) is k = pn, s0 = dn0, the numbers of classic DDA to
// the last bit. Another law is linearised about the penetration at the
// start of the step, g0 = max(-dn0, 0): N = N(g0) + N'(g0) (g - g0) with
// g = -(dn0 + change), i.e. k = N'(g0) and s0 = dn0 + g0 - N(g0) / k. It
// depends only on the step's start, so the spring an open-close iterate
// takes out of K is the one it put in. k = 0 (a law soft at first touch,
// at g0 = 0) carries N(g0) = 0 this step.
struct NormalSpring {
  double k, s0;
};
NormalSpring normal_spring_over_step(const NormalLaw* law, double pn, double dn0);

// A number a normal law reads: key, unit and what it must be.
struct NormalLawParameter {
  std::string key;
  Range range;
  std::string unit;
};

// A law built in: its name, its (required) numbers, how to make it from a
// joint's normal_parameters and its resolved penalty pn.
struct NormalLawEntry {
  std::string name;
  std::vector<NormalLawParameter> numbers;
  std::unique_ptr<NormalLaw> (*make)(const std::map<std::string, double>& numbers, double pn);
};
const std::vector<NormalLawEntry>& normal_laws();
const NormalLawEntry* find_normal_law(const std::string& name);  // nullptr if unknown

// The law a joint names; InputError (one sentence naming the law and the
// key) for an unknown name or a missing, unknown or out-of-range number.
std::unique_ptr<NormalLaw> make_normal_law(const JointProperties& joint, double pn);

}  // namespace dda::df
