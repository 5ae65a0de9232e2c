#pragma once
// Rigid sliding block under a record, in SLAMMER's form (Jibson, Rathje,
// Jibson and Lee 2013, USGS Techniques and Methods 12-B1): one horizontal
// acceleration history a(t) (m/s^2), a yield acceleration a_y = k_y g, and
// sliding in one direction only: the block slides relative to its base while
// a(t) > a_y, with relative acceleration a(t) - a_y, until its relative
// velocity returns to zero (docs/analytical.md, "Newmark analyses of records").
//
// The record is linear between samples, and so is a(t) - a_y: the velocity
// is then quadratic and the displacement cubic within a step, and both are
// integrated exactly, with the starts (a crosses a_y) and the stops (the
// velocity reaches zero) found within the step. The result does not depend
// on a time step of its own: it is the exact Newmark displacement of the
// piecewise-linear record.
#include <vector>

namespace dda::analysis {

struct RigidSliding {
  double displacement = 0.0;  // m, final, >= 0
  double max_velocity = 0.0;  // m/s, relative to the base
  int slip_episodes = 0;
  std::vector<double> velocity;  // at the samples, with keep_history
};

// a: two samples or more at the step dt > 0; yield_acceleration >= 0 (m/s^2).
RigidSliding rigid_sliding(const std::vector<double>& a, double dt, double yield_acceleration,
                           bool keep_history = false);

}  // namespace dda::analysis
