#pragma once
// Viscous damping of the blocks' deformation, stated as a damping ratio at
// a frequency (docs/solver2d.md, "Viscous damping"). 2D and 3D alike.
//
// The damping is stiffness-proportional, C = beta K_e on each block's
// elastic (strain) stiffness, so a mode of circular frequency w loses the
// fraction beta w / 2 of critical: `ratio` at `frequency`, proportionally
// more above it and less below. It acts on strain rates only: rigid motion
// (a free fall, a slide, a rotation) is never slowed, unlike `dynamic` < 1
// or mass-proportional damping. The contact springs are not damped; with the
// default penalties (50 E) they are far stiffer than the blocks, so a
// block bouncing or rocking on its contacts stores nearly all its elastic
// energy in its own strain and is damped at about the stated ratio.
#include <numbers>

namespace dda::df {

struct ViscousDamping {
  double ratio = 0;      // fraction of critical damping at `frequency` (0: none)
  double frequency = 0;  // Hz, where the ratio holds

  bool on() const { return ratio > 0; }
  // s: C = beta K_e, so that beta w / 2 = ratio at w = 2 pi frequency.
  double beta() const { return on() ? ratio / (std::numbers::pi * frequency) : 0.0; }
  // The fraction of critical damping a mode of `hz` gets.
  double ratio_at(double hz) const { return on() ? ratio * hz / frequency : 0.0; }
};

}  // namespace dda::df
