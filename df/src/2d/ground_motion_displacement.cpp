// Earthquake, displacement mode: the foundation's fixed points follow the
// ground displacement d_g(t), the processed acceleration integrated twice
// (trapezoidal rule, from rest). The blocks feel the motion only through
// their contacts, as on a shaking table.
#include <algorithm>
#include <cmath>

#include "dda/common/error.hpp"
#include "dda/df/2d/ground_motion.hpp"

namespace dda::df {
void DisplacementMode::apply(const GroundMotion& motion, const std::vector<std::size_t>& foundation,
                             ModelInput& in) const {
  if (foundation.empty())
    throw InputError("The displacement mode needs a foundation to move, and the model has no fixed point "
                     "(add fixed points, or fixed.boundary).");
  for (const std::size_t k : foundation)
    if (in.fixed_points[k].history)
      throw InputError("Fixed point '" + in.fixed_points[k].name +
                       "' already follows its own displacement table, so it cannot also follow the ground.");
  // The baseline correction, if any, is already in the acceleration.
  const IntegratedRecord ir = integrate_record(refined_record(motion, in.control.dt), 0);
  // Rows with the ground velocity as rates: the foundation moves along the
  // C1 cubic through them, so its velocity stays continuous whatever the
  // steps (model.hpp, TimeHistory). Past the last row it keeps its last
  // velocity (zero acceleration, as in the loading mode) rather than
  // stopping dead, which would be an impulse the loading mode does not have.
  TimeHistory d;
  for (std::size_t i = 0; i < ir.t.size(); ++i) {
    d.t.push_back(ir.t[i]);
    d.value.emplace_back(ir.d[0][i], ir.d[1][i]);
    d.rate.emplace_back(ir.v[0][i], ir.v[1][i]);
  }
  for (const std::size_t k : foundation) in.fixed_points[k].history = d;
}

}  // namespace dda::df
