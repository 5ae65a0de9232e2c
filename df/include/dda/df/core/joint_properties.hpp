#pragma once
// A joint set's properties as the scenario gives them: its friction law and
// the law's numbers, its normal law, its own penalties, its bond (cohesion
// and tensile strength) and its share of the joint water. The friction and
// normal laws (core) are made from it, and both kernels read it: the 2D
// model holds one per set (model.hpp), the 3D model too (Model3::joint_sets).
#include <map>
#include <optional>
#include <string>

namespace dda::df {

// Properties of one joint set (the edges, or 3D faces, that came from it).
struct JointProperties {
  double friction_deg = 30;          // Coulomb friction angle
  double cohesion = 0;               // Pa (force per unit contact length per unit thickness)
  double tensile_strength = 0;       // Pa, same units
  std::optional<double> normal_penalty;  // N/m per unit thickness; default Control::penalty_factor * max E
  std::optional<double> shear_penalty;   // N/m; default Control::shear_ratio * normal penalty
  std::string friction_law = "coulomb";  // name of the FrictionLaw (see friction.hpp)
  // The law's own numbers and words by key (e.g. "a" -> 0.01, "evolution" ->
  // "aging"); each law checks them (friction_laws.hpp, docs/scenario.md).
  std::map<std::string, double> friction_parameters;
  std::map<std::string, std::string> friction_options;
  // The contact's normal law (normal_law.hpp): "penalty" (the linear spring
  // normal_penalty) or another law with its numbers by key.
  std::string normal_law = "penalty";
  std::map<std::string, double> normal_parameters;
  // Fraction of the joint water's pore pressure on this set's faces, [0, 1]
  // (read only with a water table; water.hpp).
  double saturation = 1;
};

}  // namespace dda::df
