// Earthquake, displacement mode: the foundation's fixed points follow the
// ground displacement d_g(t), the processed acceleration integrated twice
// (trapezoidal rule, from rest). The blocks feel the motion only through
// their contacts, as on a shaking table.
#include <algorithm>
#include <cmath>

#include "dda/common/error.hpp"
#include "dda/df/ground_motion.hpp"

namespace dda::df {
namespace {

// The record with every interval split into equal parts no longer than `h`
// (linear interpolation, original samples kept): the trapezoidal rule then
// integrates a coarse record (an AT2 file at 0.01-0.02 s) as finely as the
// solver steps through it.
AccelRecord refine(const GroundMotion& g, double h) {
  AccelRecord r;
  r.source = g.source;
  auto push = [&r](double t, const Vec2& a) {
    r.t.push_back(t);
    r.a[0].push_back(a.x());
    r.a[1].push_back(a.y());
    r.a[2].push_back(0.0);
  };
  push(g.t.front(), g.acceleration.front());
  for (std::size_t i = 1; i < g.t.size(); ++i) {
    const double span = g.t[i] - g.t[i - 1];
    const int parts = std::max(1, static_cast<int>(std::ceil(span / h * (1 - 1e-9))));
    for (int k = 1; k < parts; ++k) {
      const double w = static_cast<double>(k) / parts;
      push(g.t[i - 1] + w * span, (1 - w) * g.acceleration[i - 1] + w * g.acceleration[i]);
    }
    push(g.t[i], g.acceleration[i]);
  }
  return r;
}

}  // namespace

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
  const IntegratedRecord ir = integrate_record(refine(motion, in.control.dt), 0);
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
