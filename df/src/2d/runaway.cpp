// Stops a run whose step solution is not a finite number or moves a block
// further than the whole model is large (see runaway.hpp).
#include "dda/df/core/runaway.hpp"

#include <cmath>
#include <sstream>

#include "dda/df/2d/simulation.hpp"

namespace dda::df {

void Simulation::check_runaway(const Eigen::VectorXd& d, double moved, double dt, bool at_min_dt) const {
  const int nb = model_.block_count();
  int bad = -1;
  for (int i = 0; i < nb && bad < 0; ++i)
    if (!d.segment<kDofs>(kDofs * i).allFinite()) bad = i;
  double size = 0;
  if (bad < 0) {
    // A finite step is only a runaway if even the smallest dt moves a block
    // further than the model is large (its bounding box diagonal).
    if (!at_min_dt) return;
    Box2 box = bounding_box(blocks_[0].vertices);
    for (const BlockState& b : blocks_) {
      const Box2 bb = bounding_box(b.vertices);
      box.lo = box.lo.cwiseMin(bb.lo);
      box.hi = box.hi.cwiseMax(bb.hi);
    }
    size = (box.hi - box.lo).norm();
    if (moved <= size) return;
    double worst = -1;
    for (int i = 0; i < nb; ++i) {
      const Vector6d di = d.segment<kDofs>(kDofs * i);
      for (const Vec2& v : blocks_[i].vertices) {
        const double m = (move_point(blocks_[i].geometry.centroid, di, v) - v).norm();
        if (m > worst) worst = m, bad = i;
      }
    }
  }
  std::ostringstream s;
  s << "Step " << step_count_ + 1 << " (t = " << time_ + dt << " s, dt = " << dt << " s) ";
  if (size == 0)
    s << "gave block " << bad << " a displacement that is not a finite number";
  else
    s << "moved block " << bad << " by " << moved << " m, more than the whole model (" << size << " m)";
  s << ", so the run was stopped: try a smaller time step or penalty, and check the loads, fixed points and "
       "material properties.";
  throw RunawayError(s.str(), step_count_ + 1, time_ + dt, bad);
}

}  // namespace dda::df
