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

#include "dda/df/model.hpp"
#include "dda/df/types.hpp"

namespace dda::df {

class BlockSystem;

struct BoltState {
  Vec2 anchor{0, 0}, head{0, 0};   // current end positions
  double rest_length = 0;          // L0, m (initial length)
  double force = 0;                // N, tension positive; 0 once broken
  bool broken = false;
};

// One sample of a bolt's history (sample 0 is the initial state).
struct BoltSample {
  double time = 0;
  double force = 0;                // N, tension positive
  double length = 0;               // m
  bool broken = false;
};

BoltState initial_bolt_state(const Bolt& bolt);

// Stiffness and force of an intact bolt; ca, ch are the current centroids
// of its anchor and head blocks.
void add_bolt_terms(const Bolt& bolt, const BoltState& s, const Vec2& ca, const Vec2& ch, BlockSystem& sys);

// Moves the ends with the step increments of their blocks (exact rotation),
// recomputes the force and breaks the bolt if it is over its strength.
// Returns true if it broke in this step.
bool advance_bolt(const Bolt& bolt, BoltState& s, const Vec2& ca, const Vector6d& da, const Vec2& ch,
                  const Vector6d& dh);

// Elastic energy in the bar, T^2 / (2 k) (0 once broken), J per unit thickness.
double bolt_energy(const Bolt& bolt, const BoltState& s);

}  // namespace dda::df
