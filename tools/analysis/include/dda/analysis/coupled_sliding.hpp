#pragma once
// Coupled sliding of a deformable mass (Rathje and Bray 2000; SLAMMER's
// coupled option): the first-mode shear beam of shear_beam.hpp on a base
// that slides one way over the ground when the base shear needs more than
// k_y times the weight (docs/analytical.md, "Newmark analyses of records").
//
// With a_g the ground acceleration, D >= 0 the sliding of the base relative
// to the ground (against the direction of positive a_g, as the rigid block
// of rigid_sliding.hpp), a_y = k_y g, alpha = L / M = 2 / pi and
// Gamma = 4 / pi, the base acceleration is a_b = a_g - D'' and
//   q'' + 2 xi omega q' + omega^2 q = -Gamma (a_g - D'')       (the mode)
//   sticking (D' = 0):  D'' = 0, while a_g + alpha q'' <= a_y  (base shear)
//   sliding  (D' > 0):  D'' = a_g + alpha q'' - a_y
// so that while sliding (1 - alpha Gamma) q'' + 2 xi omega q' + omega^2 q =
// -Gamma a_y. Per unit mass, the energy balance is
//   d/dt [D'^2 / 2 - alpha D' q' + q'^2 / 4 + omega^2 q^2 / 4]
//     + xi omega q'^2 + a_y D' = a_g (D' - alpha q').
//
// Integration: the average-acceleration (trapezoidal) Newmark scheme at the
// record's step, implicit in q'' (unconditionally stable, so a stiff mass
// needs no smaller step); a start of sliding (the base shear demand crossing
// a_y) and a stop (D' reaching zero) are located within the step by linear
// interpolation, and the step is split there. Ts = 0 is the rigid block.
#include <vector>

#include "dda/analysis/shear_beam.hpp"

namespace dda::analysis {

struct CoupledSliding {
  double displacement = 0.0;  // m, final D
  double max_velocity = 0.0;  // m/s, max D'
  // With keep_history, at the samples: the modal coordinate q (m) and its
  // rate, the sliding D and its rate.
  std::vector<double> q, q_rate, sliding, sliding_rate;
};

CoupledSliding coupled_sliding(const std::vector<double>& a, double dt, double yield_acceleration,
                               const ShearBeam& beam, bool keep_history = false);

}  // namespace dda::analysis
