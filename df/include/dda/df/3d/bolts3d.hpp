#pragma once
// Rock bolts of the 3D solver: the 2D bolts' law (bolt_law.hpp: force
// T = pretension + k (L - L0), breakage for good above the breaking force,
// stored energy T^2 / 2k) between material points of two 3D blocks, or of a
// block and a fixed block. Simulation3 puts them in its step system
// (simulation3d_bolts.cpp) exactly as 2D does: with u the unit vector
// anchor -> head at the start of the step, dL = e_a . d_a + e_h . d_h,
// e_a = -T_a^T u, e_h = T_h^T u (T the 3x12 displacement matrix of the end's
// block at the end), the energy T dL + k/2 dL^2.
#include <optional>
#include <string>

#include "dda/df/3d/block3d.hpp"
#include "dda/df/core/bolt_law.hpp"

namespace dda::df3 {

struct Bolt3 {
  std::string name;
  Vec3 anchor{0, 0, 0};             // end in anchor_block, at the start of the run
  Vec3 head{0, 0, 0};               // end in head_block
  int anchor_block = -1, head_block = -1;
  double stiffness = 0;             // N/m, > 0
  double pretension = 0;            // N, >= 0: the force at the initial length
  std::optional<double> breaking_force;  // N; none: never breaks
};

using BoltState3 = df::BoltStateOf<3>;

// The gradient of the bolt's linearised change of length with respect to
// the unknowns of its anchor and head blocks (ca, ch their centroids now).
struct BoltRows3 {
  Vector12d anchor, head;
};
BoltRows3 bolt_rows3(const BoltState3& s, const Vec3& ca, const Vec3& ch);

}  // namespace dda::df3
