#pragma once
// The step-length rule of both forward solvers (2D Simulation::advance, 3D
// Simulation3::advance), in one place.
//
// A step is tried at the current length, or shorter when the run's end or
// the caller asks for less (`max_dt`). The try is thrown away and redone
// shorter when its contacts did not settle (cut by 3) or when it moved a
// vertex further than the limit (g2 times the model's half-size: cut to
// 0.9 of what the limit allows, at least by half), but never below the
// shortest step (control.min_dt_ratio times control.dt); at the shortest
// step the try is kept, and the solver judges whether it ran away. After
// a step that needed no cut and was not shortened, the length grows back by
// 10 % toward the user's dt.
//
// Only the rule is here; each solver keeps its current length, its contact
// states to put back for a redo and its own runaway test.
#include <optional>

namespace dda::df {

class StepControl {
 public:
  // `user_dt`: control.dt, the longest step; `min_dt`: the shortest one, s;
  // `max_displacement`: the farthest a vertex may move in a step, m.
  StepControl(double user_dt, double min_dt, double max_displacement)
      : user_dt_(user_dt), min_dt_(min_dt), max_displacement_(max_displacement) {}

  // The next try: the current length, or `max_dt` if that is shorter (then
  // the step is `shortened` and does not let dt grow back).
  struct Try {
    double dt = 0;
    bool shortened = false;
  };
  static Try next_try(double current_dt, double max_dt);

  // `dt` is the shortest step, to round-off: nothing is left to cut.
  bool at_min_dt(double dt) const;
  // A vertex moved further in the try than a step may move one.
  bool too_far(double moved) const { return moved > max_displacement_; }

  // After a try of length `dt` that settled or not and moved a vertex by
  // `moved`: the shorter length to redo it with, or nothing to keep it.
  std::optional<double> redo_dt(bool settled, double moved, double dt) const;

  // The length after a kept step: `current_dt` grown by 10 % (at most to
  // the user's dt) if the step took no cut and was not shortened, else
  // unchanged.
  double after_step(double current_dt, bool shortened, int cuts) const;

 private:
  double user_dt_, min_dt_, max_displacement_;
};

}  // namespace dda::df
