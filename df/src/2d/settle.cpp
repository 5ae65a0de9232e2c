// Control::initial_equilibrium: relax the model statically before t = 0.
//
// Why (V1 at E = 1 GPa, the block on a 30-degree plane): a block placed on
// the plane with no contact force is not in equilibrium. In its first
// milliseconds it falls into its penalty springs and its own elastic
// compression while the normal force builds up from zero; friction, bounded
// by that normal force, is short, so the block slides nearly freely and
// gains a speed excess of the order of g sin(a) times a quarter period of
// its bounce on the plane. The excess is not given back (the contacts stick
// during the overshoot that follows), so it stays: 2.6 mm/s for a 1 m block
// of 1 GPa rock, 2.7 % of s(1 s) at phi = 29 degrees, and shorter steps are
// worse, not better: they damp the block's elastic bounce less, and a
// bouncing block creeps (at phi = 35 it walked 8.5 mm in 1 s instead of
// staying). The contact terms themselves check out (lever arms, l fixed in
// the step, the shear reference, the friction direction, every step
// dissipative), and with rigid-like blocks (E = 1000 GPa, the same
// penalty) the error is 0.08 %. The closed-form solution assumes the block
// rests in equilibrium at t = 0, as a block held and then released does;
// this option makes the model start that way.
//
// How: two phases of static solves, first with every closed contact stuck,
// then with the joints' friction laws, each until the model comes to rest
// (start_up_relax.hpp, whose rules the 3D solver shares).
// Blocks with no closed contact, fixed point or intact bolt are held where they are (they
// have no equilibrium; they start to move at t = 0). A block that would
// move more than g2 w0 in one iteration is not in static equilibrium
// (toppling, say): settling stops there and the dynamics takes over. Time
// stays 0, the velocities are the initial ones, contacts keep their states
// and their springs loaded, the histories and the energy ledger start from
// the settled state.
#include <optional>

#include "dda/df/2d/simulation.hpp"
#include "core/start_up_relax.hpp"

namespace dda::df {

df::Relaxation Simulation::relax(bool contacts_stick) {
  const int nb = model_.block_count();
  settling_stuck_ = contacts_stick;
  std::vector<Contact> work;
  Eigen::VectorXd d;
  auto solve = [&](double dts) -> std::optional<double> {
    detect_contacts();
    work = contacts_;
    int iterations = 0;
    if (!open_close(dts, work, d, iterations)) return std::nullopt;
    std::vector<bool> supported(nb, false);
    for (const Contact& c : work)
      if (c.state != ContactState::Open) supported[c.vblock] = supported[c.eblock] = true;
    for (const FixedPoint& f : model_.fixed_points) supported[f.block] = true;
    for (std::size_t b = 0; b < bolts_.size(); ++b)
      if (!bolts_[b].broken) supported[model_.bolts[b].anchor_block] = supported[model_.bolts[b].head_block] = true;
    for (int i = 0; i < nb; ++i)
      if (!supported[i]) d.segment<kDofs>(kDofs * i).setZero();
    return max_vertex_displacement(d);
  };
  auto accept_solve = [&](double dts, double moved) {
    StepRecord rec;
    rec.max_displacement = moved;  // accept() hands it to the near list's bound
    accept(dts, d, work, rec);
    time_ = 0;
    step_count_ = 0;  // bonds still form between faces in touch
    for (BlockState& b : blocks_) b.velocity.setZero();
  };
  const Relaxation r = relax_phase(contacts_stick, model_.control.dt, 1e-9 * *model_.control.w0,
                                 max_step_displacement_, solve, accept_solve, start_up_observer_);
  settling_stuck_ = false;
  return r;
}

void Simulation::settle() {
  started_ = true;
  // Only before the first step (a run restored from a checkpoint has started).
  if (!model_.control.initial_equilibrium || step_count_ > 0 || time_ > 0) return;
  const int nb = model_.block_count();
  std::vector<Vector6d> initial(nb);
  for (int i = 0; i < nb; ++i) {
    initial[i] = blocks_[i].velocity;
    blocks_[i].velocity.setZero();
  }
  settling_ = true;
  start_up_ = relax_both_phases([this](bool contacts_stick) { return relax(contacts_stick); });
  settling_ = false;
  // The relaxation's pseudo-steps leave no motion behind: the run starts
  // from the initial velocities, without acceleration (the receivers record
  // it at t = 0).
  for (int i = 0; i < nb; ++i) {
    blocks_[i].velocity = blocks_[i].velocity_end = initial[i];
    blocks_[i].acceleration.setZero();
  }
  log_.clear();
  for (auto& h : histories_) h.clear();
  record_measurements();
  init_physics();
}

}  // namespace dda::df
