// Checkpoint state of the 3D run (SimulationState3 in simulation3d.hpp).
#include "dda/common/error.hpp"
#include "dda/df/3d/simulation3d.hpp"

namespace dda::df3 {

SimulationState3 Simulation3::state() const {
  SimulationState3 s;
  s.time = time_;
  s.dt = dt_;
  for (const Polyhedron& p : model_.blocks) s.vertices.push_back(p.vertices);
  s.velocity = velocity_;
  s.stress = stress_;
  s.contacts = contacts_;
  s.log = log_;
  s.fixed_at = fixed_at_;
  s.load_at = load_at_;
  s.measure_at = measure_at_;
  s.histories = histories_;
  s.energy_log = energy_log_;
  s.solver_warm_start = solver_->warm_start();
  s.started = started_;
  s.bolts = bolts_;
  s.bolt_histories = bolt_histories_;
  s.bonds_placed = bonds_placed_;
  return s;
}

void Simulation3::restore(const SimulationState3& s) {
  const size_t n = model_.blocks.size();
  bool fits = s.vertices.size() == n && s.velocity.size() == n && s.stress.size() == n &&
              s.fixed_at.size() == fixed_at_.size() && s.load_at.size() == load_at_.size() &&
              s.measure_at.size() == measure_at_.size() && s.histories.size() == histories_.size() &&
              s.bolts.size() == bolts_.size() && s.bolt_histories.size() == bolts_.size();
  for (size_t b = 0; fits && b < n; ++b) fits = s.vertices[b].size() == model_.blocks[b].vertices.size();
  // A contact is glued exactly when its joint is the glue's (detect keeps them so).
  for (const Contact3& c : s.contacts)
    fits = fits && c.i >= 0 && c.j >= 0 && static_cast<size_t>(c.i) < n && static_cast<size_t>(c.j) < n &&
           c.joint >= 0 && static_cast<size_t>(c.joint) < springs_.size() && c.glued == (c.joint == model_.glue_joint());
  if (!fits) throw InputError("The checkpoint does not fit the model (block, vertex, contact, point or bolt counts differ).");
  time_ = s.time;
  dt_ = s.dt;
  for (size_t b = 0; b < n; ++b) {
    model_.blocks[b].vertices = s.vertices[b];
    refresh_geometry(model_.blocks[b]);
  }
  velocity_ = s.velocity;
  stress_ = s.stress;
  contacts_ = s.contacts;
  log_ = s.log;
  fixed_at_ = s.fixed_at;
  load_at_ = s.load_at;
  measure_at_ = s.measure_at;
  histories_ = s.histories;
  solver_->set_warm_start(s.solver_warm_start);
  started_ = s.started;
  bolts_ = s.bolts;
  bolt_histories_ = s.bolt_histories;
  bonds_placed_ = s.bonds_placed;
  // A checkpoint written before the 3D ledger has none: it counts from here.
  if (s.energy_log.empty()) {
    start_energy();
  } else {
    energy_log_ = s.energy_log;
  }
}

}  // namespace dda::df3
