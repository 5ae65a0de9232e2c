// Simulation::state() and Simulation::restore(): the evolving state of a run,
// copied out for a checkpoint and put back to resume (see SimulationState).
#include <limits>
#include <string>

#include "dda/common/error.hpp"
#include "dda/df/2d/simulation.hpp"

namespace dda::df {

SimulationState Simulation::state() const {
  SimulationState s;
  s.time = time_;
  s.dt = dt_;
  s.step_count = step_count_;
  s.blocks = blocks_;
  s.contacts = contacts_;
  s.fixed_anchor = fixed_anchor_;
  s.fixed_pos = fixed_pos_;
  s.load_pos = load_pos_;
  s.measurement_pos = measurement_pos_;
  s.log = log_;
  s.histories = histories_;
  s.solver_warm_start = solver_->warm_start();
  s.bolts = bolts_;
  s.bolt_histories = bolt_histories_;
  s.energy_log = energy_log_;
  s.started = started_;
  return s;
}

void Simulation::restore(const SimulationState& s) {
  auto check = [](std::size_t got, std::size_t want, const char* what) {
    if (got != want)
      throw InputError("The saved state has " + std::to_string(got) + " " + what + " but the model has " +
                       std::to_string(want) + "; it was saved from a different model.");
  };
  check(s.blocks.size(), blocks_.size(), "blocks");
  for (std::size_t i = 0; i < s.blocks.size(); ++i)
    if (s.blocks[i].vertices.size() != blocks_[i].vertices.size())
      throw InputError("Block " + std::to_string(i) + " of the saved state has " +
                       std::to_string(s.blocks[i].vertices.size()) + " vertices but the model's has " +
                       std::to_string(blocks_[i].vertices.size()) + "; it was saved from a different model.");
  check(s.fixed_anchor.size(), fixed_anchor_.size(), "fixed points");
  check(s.fixed_pos.size(), fixed_pos_.size(), "fixed points");
  check(s.load_pos.size(), load_pos_.size(), "load points");
  check(s.measurement_pos.size(), measurement_pos_.size(), "measurement points");
  check(s.histories.size(), histories_.size(), "measurement histories");
  check(s.bolts.size(), bolts_.size(), "bolts");
  check(s.bolt_histories.size(), bolt_histories_.size(), "bolt histories");
  if (s.energy_log.empty()) throw InputError("The saved state has no energy record of the start of the run.");
  const int nb = static_cast<int>(blocks_.size());
  const int nj = static_cast<int>(model_.joints.size());
  for (const Contact& c : s.contacts) {
    const bool ok = c.vblock >= 0 && c.vblock < nb && c.eblock >= 0 && c.eblock < nb && c.joint >= 0 &&
                    c.joint < nj && c.vertex >= 0 &&
                    c.vertex < static_cast<int>(blocks_[c.vblock].vertices.size()) && c.edge >= 0 &&
                    c.edge < static_cast<int>(blocks_[c.eblock].vertices.size());
    if (!ok) throw InputError("A saved contact refers to a block, vertex, edge or joint the model does not have.");
  }
  time_ = s.time;
  dt_ = s.dt;
  step_count_ = s.step_count;
  blocks_ = s.blocks;
  moved_since_detection_ = std::numeric_limits<double>::infinity();  // the near list checks the vertices
  contacts_ = s.contacts;
  // The checkpoint keeps a contact's bond, not its glue: a glued contact is
  // one across an artificial cut that was bonded when the run started, and
  // a glued contact's bond never breaks, so bonded on an artificial cut
  // means glued, exactly. (Without this a resumed run let its cuts open.)
  for (Contact& c : contacts_)
    c.glued = c.glued || (c.bonded && on_artificial_cut(model_.blocks[c.vblock], c.vertex, model_.blocks[c.eblock], c.edge));
  contact_index_current_ = false;
  fixed_anchor_ = s.fixed_anchor;
  fixed_pos_ = s.fixed_pos;
  load_pos_ = s.load_pos;
  measurement_pos_ = s.measurement_pos;
  log_ = s.log;
  histories_ = s.histories;
  solver_->set_warm_start(s.solver_warm_start);
  bolts_ = s.bolts;
  bolt_histories_ = s.bolt_histories;
  energy_log_ = s.energy_log;  // record 0 is the starting state (start_energy())
  started_ = s.started;
}

}  // namespace dda::df
