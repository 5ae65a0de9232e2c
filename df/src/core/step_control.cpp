// The step-length rule of both solvers (step_control.hpp).
#include "core/step_control.hpp"

#include <algorithm>

namespace dda::df {

StepControl::Try StepControl::next_try(double current_dt, double max_dt) {
  return {std::min(current_dt, max_dt), max_dt < current_dt};
}

// A relative margin: dt_min times a factor and a dt cut to it may differ in
// the last bits.
bool StepControl::at_min_dt(double dt) const { return dt <= min_dt_ * (1 + 1e-9); }

std::optional<double> StepControl::redo_dt(bool settled, double moved, double dt) const {
  const bool far = too_far(moved);
  if ((settled && !far) || at_min_dt(dt)) return std::nullopt;
  // To what the displacement limit allows (with a margin, and at least by
  // half), or by 3 when the contact states did not settle.
  const double factor = far ? std::min(0.5, 0.9 * max_displacement_ / moved) : 1.0 / 3.0;
  return std::max(min_dt_, dt * factor);
}

double StepControl::after_step(double current_dt, bool shortened, int cuts) const {
  // Easy steps let dt grow back gradually toward the user's dt.
  if (!shortened && cuts == 0) return std::min(user_dt_, current_dt * 1.1);
  return current_dt;
}

}  // namespace dda::df
