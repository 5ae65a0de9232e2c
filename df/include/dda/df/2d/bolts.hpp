#pragma once
// Rock bolts (see Bolt in model.hpp): their evolving state, their terms in
// the step system and their update after an accepted step.
//
// With u the unit vector anchor -> head at the start of the step and
// dL = u . (T_h(H) d_h - T_a(A) d_a) the linearised change of length, the
// bolt adds the energy T dL + k/2 dL^2 (T its force at the start of the
// step): stiffness k e e^T on the two diagonal blocks and their coupling
// (e = [-T_a^T u; T_h^T u]), and its current force as two equal and
// opposite point loads, T along u on the anchor and -T along u on the head.
// After the step both ends ride with their blocks, T is recomputed from the
// new length, and a bolt whose T exceeds its breaking force breaks for good
// (it still carried its force during the step in which it broke).
#include <vector>

#include "dda/df/core/bolt_law.hpp"
#include "dda/df/2d/model.hpp"
#include "dda/df/core/types.hpp"

namespace dda::df {

class BlockSystem;

// The law itself (force, breakage, energy, state) is bolt_law.hpp, the
// same in 3D; what is 2D here is how the ends ride with their blocks.
using BoltState = BoltStateOf<2>;

BoltState initial_bolt_state(const Bolt& bolt);

// Stiffness and force of an intact bolt; ca, ch are the current centroids
// of its anchor and head blocks.
void add_bolt_terms(const Bolt& bolt, const BoltState& s, const Vec2& ca, const Vec2& ch, BlockSystem& sys);

// Moves the ends with the step increments of their blocks (exact rotation),
// recomputes the force and breaks the bolt if it is over its strength.
// Returns the energy a break in this step released (T^2 / 2k, J per unit
// thickness), else 0.
double advance_bolt(const Bolt& bolt, BoltState& s, const Vec2& ca, const Vector6d& da, const Vec2& ch,
                    const Vector6d& dh);

}  // namespace dda::df
