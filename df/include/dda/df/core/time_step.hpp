#pragma once
// The time step a model gets when its scenario gives none (`control.dt`
// absent), 2D and 3D alike (docs/solver2d.md, "The default time step").
//
// dt is the time a P wave takes to cross the median block (its size the
// square root of its area in 2D, the cube root of its volume in 3D), and
// no longer than the shortest sample interval of the loading (an
// earthquake record, an incident wave, a load or displacement table), whose
// peaks a longer step would average away. The crossing time is where a
// block stops being a deformable body and becomes a rigid one for the
// step: its fundamental elastic mode (period about 1.8 crossing times for a
// square) is damped out by DDA's step, while the motions users look at
// (falls, slides, rotations, the shaking) take hundreds of such steps. The
// step is implicit, so this is an accuracy choice, not a stability limit;
// the step control (g2, the open-close limit) still shortens any step that
// needs it.
#include <string>
#include <vector>

namespace dda::df {

// m/s: sqrt(M / rho) with M the P-wave (constrained) modulus:
// E (1 - nu) / ((1 + nu) (1 - 2 nu)) in 3D and plane strain, E / (1 - nu^2)
// in plane stress.
double p_wave_speed(double young, double poisson, double density, bool plane_stress);

struct BlockCrossing {
  double size = 0;   // m
  double speed = 0;  // m/s, P wave in the block's material
};

struct TimeStepChoice {
  double dt = 0;      // s
  std::string basis;  // why, for the run's first lines ("a P wave crosses the median block, 1 m, in ...")
};

// `loading_interval`: the loading's shortest sample interval, s (0: none).
// InputError if no block has a size.
TimeStepChoice default_time_step(std::vector<BlockCrossing> blocks, double loading_interval);

// The shortest interval between successive times, 0 for fewer than two.
double shortest_interval(const std::vector<double>& times);

}  // namespace dda::df
