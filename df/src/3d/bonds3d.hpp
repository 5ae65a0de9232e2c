#pragma once
// Bonds of the 3D joints (private to DF; docs/solver3d.md, "Bonds"; the
// rules both dimensions share are core/bond.hpp's). A joint set with
// cohesion c or tensile strength T (Pa) bonds the contacts of its faces that
// touch when the run starts. Each contact stands for a share of
// the patch where the two faces lie on each other (facing_patches3d.hpp):
// the patch's area split evenly among the pair's contacts on it, which is
// its tributary area when they are its corners (a face on a face has a
// contact at every corner of the overlap). While intact the contact holds
// c A in shear on top of friction (the laws add it, FrictionInput::bonded)
// and T A in tension; past either it breaks for good and is a frictional
// contact from then on, as in 2D (df/src/2d/contact.cpp).
#include <functional>
#include <vector>

#include "dda/df/3d/simulation3d.hpp"
#include "dda/df/core/bond.hpp"

namespace dda::df3 {

// The share of its face-to-face patch (m^2) each contact stands for;
// 0 for a contact on no patch (a corner on a face, crossing edges) or one
// `accept` leaves out.
std::vector<double> bond_areas3(const std::vector<Polyhedron>& blocks, const std::vector<Contact3>& contacts,
                                double reach, double merge, const std::function<bool(const Contact3&)>& accept);

// The pull (N) a contact's bond holds before it lets go: T A, 0 unbonded.
double bond_tension3(const Contact3& c, const Model3& m);

// The bond lets go in tension: the springs' energy at the break, the normal
// spring at T A and the shear spring at `shear` (N), is released.
void break_bond_in_tension3(Contact3& c, const Model3& m, const ContactSprings3& springs,
                            const Eigen::Vector2d& shear);

}  // namespace dda::df3
