// Control3::initial_equilibrium: the 3D model relaxed statically before
// t = 0, by the rules the 2D solver follows (settle.cpp says why a run needs
// it, start_up_relax.hpp how the two phases go and when they stop).
//
// What it changes in 3D (tests/df/test_simulation3d.cpp, a 1 m cube on a
// 20-degree plane): with gravity applied suddenly the cube at friction 10
// degrees slides further than V1 by 1.1e-5 of s(1 s), and at friction 30
// degrees it moves 7e-6 m after t = 0 (its shear springs' stretch);
// settled, by 1e-10 of s and 2e-13 m. It does not make the cube at friction
// 20.1 degrees hold: that is how a 3D sliding contact turns its friction
// (docs/solver3d.md, "Friction at its limit").
//
// While settling time stands at 0: gravity acts, the earthquake adds only
// its acceleration at t = 0 (none, for a record that starts at rest) and the
// foundation does not move, loads are those of t = 0 and moving fixed
// points stay at their start. Blocks with no closed contact and no fixed
// point are held where they are (they have no equilibrium; they start to
// move at t = 0). Time stays 0, the velocities are the initial ones,
// contacts keep their states and their springs loaded, blocks their
// stresses, bolts their forces; the log and the histories start from the settled state.
#include <limits>
#include <optional>
#include <vector>

#include "dda/df/core/runaway.hpp"
#include "dda/df/3d/simulation3d.hpp"
#include "core/start_up_relax.hpp"

namespace dda::df3 {

df::Relaxation Simulation3::relax(bool contacts_stick) {
  const std::size_t nb = model_.blocks.size();
  settling_stuck_ = contacts_stick;
  std::vector<Vector12d> d;
  auto solve = [&](double dts) -> std::optional<double> {
    detect();
    start_contacts_ = contacts_;
    int iterations = 0;
    const bool settled = iterate(dts, d, iterations);
    // The iterate works on contacts_ in place: keep its contacts aside until
    // it is accepted, so that one refused leaves the last accepted state.
    contacts_.swap(start_contacts_);
    if (!settled) return std::nullopt;
    std::vector<bool> supported(nb, false);
    for (const Contact3& c : start_contacts_)
      if (c.state != ContactState3::Open)
        supported[static_cast<std::size_t>(c.i)] = supported[static_cast<std::size_t>(c.j)] = true;
    for (const FixedPoint3& f : model_.fixed_points) supported[static_cast<std::size_t>(f.block)] = true;
    for (std::size_t k = 0; k < bolts_.size(); ++k)  // an intact bolt holds both its blocks
      if (!bolts_[k].broken)
        supported[static_cast<std::size_t>(model_.bolts[k].anchor_block)] =
            supported[static_cast<std::size_t>(model_.bolts[k].head_block)] = true;
    for (std::size_t b = 0; b < nb; ++b)
      if (!supported[b]) d[b].setZero();
    try {
      return max_vertex_displacement(d);
    } catch (const df::RunawayError&) {  // a solution that is not finite: no equilibrium, the dynamics decides
      return std::numeric_limits<double>::quiet_NaN();
    }
  };
  auto accept = [&](double dts, double /*moved*/) {
    contacts_.swap(start_contacts_);
    finish_step(d, dts);
    time_ = 0;
    for (Vector12d& v : velocity_) v.setZero();
  };
  const df::Relaxation r = df::relax_phase(contacts_stick, model_.control.dt, 1e-9 * w0_,
                                     model_.control.max_displacement_ratio * w0_, solve, accept,
                                           start_up_observer_);
  settling_stuck_ = false;
  return r;
}

void Simulation3::settle() {
  started_ = true;
  // Only before the first step (a run restored from a checkpoint has started).
  if (!model_.control.initial_equilibrium || !log_.empty() || time_ > 0) return;
  const std::vector<Vector12d> initial = velocity_;
  for (Vector12d& v : velocity_) v.setZero();
  settling_ = true;
  start_up_ = df::relax_both_phases([this](bool contacts_stick) { return relax(contacts_stick); });
  settling_ = false;
  // A contact last updated with its contacts stuck holds the unbounded
  // strength of that phase; the first step recomputes it before using it,
  // but a checkpoint or an output written before then shows the joint's.
  // A glued contact has no joint and keeps none.
  for (Contact3& c : contacts_)
    if (c.state != ContactState3::Open && !c.glued)
      c.strength = law_of(c).strength(friction_input3(c, model_.control.dt), c.friction);
  // The relaxation's pseudo-steps leave no motion behind: the run starts
  // from the initial velocities.
  velocity_ = initial;
  log_.clear();
  for (auto& h : histories_) h.clear();
  sample_measurements();
  restart_bolt_histories();
  start_energy();  // the ledger counts from the state the run starts from
}

}  // namespace dda::df3
