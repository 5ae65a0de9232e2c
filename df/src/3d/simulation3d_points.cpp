// Fixed points, point loads and measurement points of the 3D step
// (points3d.hpp, simulation3d.hpp).
#include <string>

#include "dda/common/error.hpp"
#include "dda/df/3d/simulation3d.hpp"

namespace dda::df3 {

void Simulation3::index_points() {
  const int n = static_cast<int>(model_.blocks.size());
  fixed_of_block_.assign(static_cast<size_t>(n), {});
  loads_of_block_.assign(static_cast<size_t>(n), {});
  auto check = [&](int block, const Vec3& x, const std::string& what, bool needs_free) {
    if (block < 0 || block >= n) throw InputError(what + ": block " + std::to_string(block) + " does not exist.");
    if (!x.allFinite()) throw InputError(what + ": the position is not a finite number.");
    if (needs_free && model_.fixed[static_cast<size_t>(block)])
      throw InputError(what + ": block " + std::to_string(block) + " is fixed, so the point would do nothing.");
  };
  for (size_t p = 0; p < model_.fixed_points.size(); ++p) {
    const FixedPoint3& fp = model_.fixed_points[p];
    const std::string what = "Fixed point " + std::to_string(p + 1);
    check(fp.block, fp.position, what, true);
    if (fp.motion) fp.motion->check(what + " motion");
    if (fp.penalty < 0) throw InputError(what + ": the penalty must not be negative.");
    fixed_of_block_[static_cast<size_t>(fp.block)].push_back(static_cast<int>(p));
    fixed_at_.push_back(fp.position);
  }
  for (size_t p = 0; p < model_.loads.size(); ++p) {
    const PointLoad3& l = model_.loads[p];
    const std::string what = "Point load " + std::to_string(p + 1);
    check(l.block, l.position, what, true);
    l.force.check(what + " force");
    loads_of_block_[static_cast<size_t>(l.block)].push_back(static_cast<int>(p));
    load_at_.push_back(l.position);
  }
  for (const MeasurementPoint3& m : model_.measurements) {
    check(m.block, m.position, "Measurement point " + m.name, false);
    measure_at_.push_back(m.position);
  }
  histories_.assign(model_.measurements.size(), {});
  sample_measurements();
}

void Simulation3::add_point_terms(int b, double dt, const BlockGeometry3& g, Matrix12d& k, Vector12d& f) const {
  // Settling (initial_equilibrium), time stands at 0: the loads of t = 0,
  // and a moving fixed point must not move yet.
  const double span = settling_ ? 0.0 : dt;
  for (const int p : loads_of_block_[static_cast<size_t>(b)])
    add_point_load(g, load_at_[static_cast<size_t>(p)],
                   model_.loads[static_cast<size_t>(p)].force.average(time_, time_ + span), f);
  for (const int p : fixed_of_block_[static_cast<size_t>(b)]) {
    const FixedPoint3& fp = model_.fixed_points[static_cast<size_t>(p)];
    Vec3 target = fp.position;
    if (fp.motion) target += fp.motion->at(time_ + span);
    const double penalty = fp.penalty > 0 ? fp.penalty : 10 * model_.normal_penalty;
    add_point_spring(g, fixed_at_[static_cast<size_t>(p)], target - fixed_at_[static_cast<size_t>(p)], penalty, k, f);
  }
}

void Simulation3::sample_measurements() {
  for (size_t p = 0; p < model_.measurements.size(); ++p) {
    const MeasurementPoint3& m = model_.measurements[p];
    const auto b = static_cast<size_t>(m.block);
    MeasurementSample3 s;
    s.time = time_;
    s.position = measure_at_[p];
    s.displacement = measure_at_[p] - m.position;
    s.velocity = displacement_matrix(measure_at_[p], model_.blocks[b].centroid) * velocity_[b];
    s.stress = stress_[b];
    histories_[p].push_back(s);
  }
}

}  // namespace dda::df3
