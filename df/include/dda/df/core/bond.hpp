#pragma once
// Bonds of joints, the same rules in 2D and 3D (docs/formulation.md,
// "Bonds and glue"). A joint set with cohesion c or tensile strength T bonds
// the contacts of its faces that touch when the run starts; DC's artificial
// cuts (inside one piece of rock) are glued by the same test. While intact a
// bond holds c times its measure in shear on top of friction (the friction
// laws add it, FrictionInput::bonded) and T times its measure in tension;
// past either it breaks for good and the contact is a frictional one from
// then on. A glued contact never breaks. The measure is the kernel's: in 2D
// the length of joint the contact stands for (per unit thickness), in 3D its
// share of the face-to-face patch.
#include <cmath>

#include "dda/df/core/joint_properties.hpp"

namespace dda::df {

// The joint bonds the faces of its set that touch at the start.
inline bool forms_bonds(const JointProperties& j) { return j.cohesion > 0 || j.tensile_strength > 0; }

// In touch when the run starts: a gap (or penetration) `gap` within a
// thousandth of the contact search distance.
inline bool in_touch_at_start(double gap, double search_distance) { return std::abs(gap) <= 1e-3 * search_distance; }

// The pull (N) an intact bond holds before it lets go; 0 once broken.
inline double bond_tension_capacity(double tensile_strength, double measure, bool bonded) {
  return bonded ? tensile_strength * measure : 0.0;
}

}  // namespace dda::df
