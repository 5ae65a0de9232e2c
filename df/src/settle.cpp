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
// How, in two phases of static solves (the velocity is zeroed after each),
// each repeated until no vertex moves more than 1e-9 w0 (at most 50 in each
// phase; an iterate whose contact states do not settle within
// max(100, max_open_close) iterations ends the phase unaccepted; phase 2
// follows whenever phase 1 accepted a solve):
//  1. every closed contact stuck, pseudo step 10 dt (the inertia term then
//     only regularises): the blocks settle into their springs without any
//     slip, whatever the friction;
//  2. with the joints' friction laws, pseudo step 10 dt, or dt from the
//     first solve whose states do not settle on: a contact asked for
//     more shear than its friction gives up the excess and slides, and the
//     load moves to the contacts that can carry it. Without this phase a
//     5 m block of 1 GPa rock on a plane, with friction 0.1 degree above
//     the slope, started with its uphill corner carrying three times the
//     shear its normal force allows (the shear springs share the load
//     evenly; the moment of the load takes the normal force off that
//     corner). The corner slipped at t = 0, the jolt set the block rocking,
//     and the rocking walked it 0.44 m down the plane in 2 s
//     (tests/df/test_friction_limit.cpp). The shorter pseudo step steadies
//     the frictional iteration: at 10 dt a 400-brick wall's second solve
//     did not settle in 100 open-close iterations; at dt that block on the
//     plane crept towards its equilibrium too slowly to reach it. A block that must
//     slide (friction below the slope) moves 0.5 a dt^2 a solve without
//     end, and a wall whose end bricks creep gets down to a constant creep
//     too: once the motion of a solve shrinks by less than 5 % (after three
//     solves) the phase stops. Its iterates are kept either way: each is an
//     accepted static state, and together they moved the model by a few
//     times the first solve's motion (2e-6 m on the wall); start_up() says
//     whether the equilibrium was reached.
// Blocks with no closed contact, fixed point or intact bolt are held where they are (they
// have no equilibrium; they start to move at t = 0). A block that would
// move more than g2 w0 in one iteration is not in static equilibrium
// (toppling, say): settling stops there and the dynamics takes over. Time
// stays 0, the velocities are the initial ones, contacts keep their states
// and their springs loaded, the histories and the energy ledger start from
// the settled state.
#include <cmath>

#include "dda/df/simulation.hpp"

namespace dda::df {

// A model with blocks that are not in equilibrium (a loose block turning
// about one corner) never meets the tolerance; its settling is cut here and
// the dynamics takes over. Stacks and slopes in equilibrium settle in a few
// iterations.
constexpr int kMaxSettleIterations = 50;

Simulation::Relaxation Simulation::relax(bool contacts_stick) {
  const int nb = model_.block_count();
  double dts = 10 * model_.control.dt;
  const double tolerance = 1e-9 * *model_.control.w0;
  settling_stuck_ = contacts_stick;
  double last_moved = 0;
  Relaxation r;
  int since_switch = 0;  // accepted solves at this pseudo step
  for (int k = 0; k < kMaxSettleIterations; ++k) {
    detect_contacts();
    std::vector<Contact> work = contacts_;
    Eigen::VectorXd d;
    int iterations = 0;
    // An iterate whose contact states did not settle is not an equilibrium:
    // accepting it left contacts penetrated by millimetres (a 40-bed model,
    // a kinetic-energy burst of 1.7 MJ/m at t = 0). Stop before it instead.
    if (!open_close(dts, work, d, iterations)) {
      // The frictional iteration gets a shorter pseudo step, whose inertia
      // steadies it, before giving up.
      if (contacts_stick || dts <= model_.control.dt) break;
      dts = model_.control.dt;
      since_switch = 0;
      continue;
    }
    std::vector<bool> supported(nb, false);
    for (const Contact& c : work)
      if (c.state != ContactState::Open) supported[c.vblock] = supported[c.eblock] = true;
    for (const FixedPoint& f : model_.fixed_points) supported[f.block] = true;
    for (std::size_t b = 0; b < bolts_.size(); ++b)
      if (!bolts_[b].broken) supported[model_.bolts[b].anchor_block] = supported[model_.bolts[b].head_block] = true;
    for (int i = 0; i < nb; ++i)
      if (!supported[i]) d.segment<kDofs>(kDofs * i).setZero();
    const double moved = max_vertex_displacement(d);
    if (!std::isfinite(moved) || moved > max_step_displacement_) break;
    // Sliding that does not die away: no frictional equilibrium to find.
    if (!contacts_stick && since_switch >= 3 && moved > 0.95 * last_moved) break;
    ++since_switch;
    last_moved = moved;
    StepRecord rec;
    rec.max_displacement = moved;  // accept() hands it to the near list's bound
    accept(dts, d, work, rec);
    ++settle_iterations_;
    ++r.solves;
    time_ = 0;
    step_count_ = 0;  // bonds still form between faces in touch
    for (BlockState& b : blocks_) b.velocity.setZero();
    if (moved <= tolerance) {
      r.reached = true;
      break;
    }
  }
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
  settle_iterations_ = 0;
  start_up_ = {};
  // Phase 2 follows whenever phase 1 got anywhere: a block that topples
  // keeps phase 1 from its tolerance, but the rest of the model is relaxed
  // and its contacts still deserve their friction.
  const Relaxation stuck = relax(true);
  start_up_.stuck_iterations = stuck.solves;
  start_up_.stuck_equilibrium = stuck.reached;
  if (stuck.solves > 0) {
    const Relaxation friction = relax(false);
    start_up_.friction_iterations = friction.solves;
    start_up_.frictional_equilibrium = stuck.reached && friction.reached;
  }
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
