// Earthquake, route foundation (the displacement mode): the foundation's
// fixed points follow the ground displacement d_g(t). The blocks feel the
// motion only through their contacts, as on a shaking table.
#include "dda/common/error.hpp"
#include "dda/df/2d/ground_motion.hpp"

namespace dda::df {

void apply_foundation_motion(const GroundMotion<2>& motion, const std::vector<std::size_t>& foundation,
                             ModelInput& in) {
  if (foundation.empty())
    throw InputError("The displacement mode needs a foundation to move, and the model has no fixed point "
                     "(add fixed points, or fixed.boundary).");
  for (const std::size_t k : foundation)
    if (in.fixed_points[k].history)
      throw InputError("Fixed point '" + in.fixed_points[k].name +
                       "' already follows its own displacement table, so it cannot also follow the ground.");
  // Rows at the record's samples with the ground velocity as rates: the
  // foundation moves along the C1 cubic through them, which is d_g itself
  // (a cubic between samples, with these values and slopes), so its
  // velocity stays continuous whatever the steps (model.hpp, TimeHistory).
  // Past the last row it keeps its last velocity (zero acceleration, as in
  // the loading mode) rather than stopping dead, which would be an impulse
  // the loading mode does not have.
  TimeHistory d;
  for (const double t : motion.times()) {
    d.t.push_back(t);
    d.value.push_back(motion.displacement(t));
    d.rate.push_back(motion.velocity(t));
  }
  for (const std::size_t k : foundation) in.fixed_points[k].history = d;
}

}  // namespace dda::df
