#pragma once
// Newmark rigid-block analysis on an inclined plane (2D: the vertical section
// through the dip direction).
//
// Per unit mass, with the body acceleration b(t) (see excitation.hpp) split
// into its horizontal part along the dip direction, b_h = b . h, h the
// horizontal unit vector towards the dip direction, and its vertical part
// b_v = b_z (the cross-slope part is ignored, as in Newmark's method):
//   driving (downslope)  D(t) = b_h cos(alpha) + (g - b_v) sin(alpha)
//   normal (pressing)    N(t) = (g - b_v) cos(alpha) - b_h sin(alpha)
// The relative acceleration along the plane (downslope positive) is
//   v > 0: D - mu N;  v < 0: D + mu N;
//   v = 0: D - mu N if D > mu N, D + mu N if D < -mu N (two-way only), else 0.
// Yield accelerations for a horizontal body acceleration along the dip
// direction (b_v = 0):  downslope  b_h = g tan(phi - alpha),
//                       upslope    b_h = -g tan(phi + alpha).
// A ground acceleration is the opposite of the body acceleration: the block
// slides downslope when the ground accelerates horizontally into the slope
// (away from the dip direction) at more than g tan(phi - alpha).
//
// Integration (the seed report's trapezoidal scheme): over each step the
// friction state is that of the start of the step, the acceleration is the
// average of its values at both ends, v += S dt, s += v dt + S dt^2 / 2;
// when the velocity would change sign the block stops at the zero crossing
// (linear in the step) and sticks until D exceeds the resistance again.
// N <= 0 (the block leaves the plane) ends the run with lift_off set.
//
// Pore pressure on the plane (ru > 0): Bishop's pore-pressure ratio, the
// water pressure on the plane as a fraction of the vertical overburden,
// u = ru gamma h. For the column of an infinite slope the water force is
// then U = ru W / cos(alpha), normal to the plane and constant (hydrostatic,
// no excess pore pressure from the shaking), so per unit mass
//   N(t) = (g - b_v) cos(alpha) - b_h sin(alpha) - g ru / cos(alpha)
// and the yield accelerations become, with mu = tan(phi) and
// c = cos(alpha), s = sin(alpha):
//   downslope  b_h = g (mu c - s - mu ru / c) / (c + mu s),
//   upslope    b_h = -g (s + mu c - mu ru / c) / (c - mu s).
#include <vector>

#include "dda/analysis/excitation.hpp"

namespace dda::analysis {

struct NewmarkInput {
  double dip_deg = 20.0;
  double dip_direction_deg = 90.0;
  double phi_deg = 30.0;
  bool two_way = false;  // false: downslope sliding only (classical Newmark)
  double gravity = 9.81;
  double ru = 0.0;       // pore-pressure ratio on the plane, [0, 1) (see above)
  double dt = 1e-4;
  double duration = 0.0;
};

struct NewmarkResult {
  std::vector<double> t, s, v, a;  // along the plane, downslope positive
  double yield_down = 0.0;         // m/s^2, horizontal body acceleration along the dip direction
  double yield_up = 0.0;           // m/s^2 (negative: towards the slope)
  bool lift_off = false;
  double lift_off_time = 0.0;
  int slip_episodes = 0;
};

NewmarkResult run_newmark(const NewmarkInput& input, const Excitation& excitation);

}  // namespace dda::analysis
