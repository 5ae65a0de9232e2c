#pragma once
// The start-up relaxation of initial_equilibrium, one set of rules for the
// 2D solver (settle.cpp, which says why a run needs it) and the 3D solver
// (settle3d.cpp): the solvers differ in how they solve and move their
// blocks, not in when the relaxation stops.
//
// How, in two phases of static solves (the velocity is zeroed after each),
// each repeated until no vertex moves more than 1e-9 w0 (at most 50 in each
// phase; an iterate whose contact states do not settle within
// max(kSettleOpenClose, the step's limit) iterations ends the phase
// unaccepted; phase 2 follows whenever phase 1 accepted a solve: a block
// that topples keeps phase 1 from its tolerance, but the rest of the model
// is relaxed and its contacts still deserve their friction):
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
// A block that would move more than g2 w0 in one iteration is not in static
// equilibrium (toppling, say): settling stops there and the dynamics takes
// over.
#include <cmath>
#include <limits>
#include <optional>

#include "dda/df/core/start_up.hpp"

namespace dda::df {

// A model with blocks that are not in equilibrium (a loose block turning
// about one corner) never meets the tolerance; its settling is cut here and
// the dynamics takes over. Stacks and slopes in equilibrium settle in a few
// iterations.
constexpr int kMaxSettleIterations = 50;

// One phase. solve(dts) makes one static solve with pseudo step dts and
// keeps it: std::nullopt when its contact states did not settle, else the
// largest vertex motion of the solution (not finite: no equilibrium), with
// the blocks that nothing holds already held where they are. accept(dts,
// moved) then makes that solve the model's state, at rest. `limit` is the
// step's displacement limit g2 w0, `tolerance` 1e-9 w0; `observer` (may be
// empty) hears of every accepted solve.
template <class Solve, class Accept>
Relaxation relax_phase(bool contacts_stick, double dt, double tolerance, double limit, Solve&& solve, Accept&& accept,
                       const StartUpObserver& observer) {
  double dts = 10 * dt;
  double last_moved = 0;
  Relaxation r;
  int since_switch = 0;  // accepted solves at this pseudo step
  for (int k = 0; k < kMaxSettleIterations; ++k) {
    // An iterate whose contact states did not settle is not an equilibrium:
    // accepting it left contacts penetrated by millimetres (a 40-bed model,
    // a kinetic-energy burst of 1.7 MJ/m at t = 0). Stop before it instead.
    const std::optional<double> moved = solve(dts);
    if (!moved) {
      // The frictional iteration gets a shorter pseudo step, whose inertia
      // steadies it, before giving up.
      if (contacts_stick || dts <= dt) break;
      dts = dt;
      since_switch = 0;
      continue;
    }
    if (!std::isfinite(*moved) || *moved > limit) break;
    // Sliding that does not die away: no frictional equilibrium to find.
    if (!contacts_stick && since_switch >= 3 && *moved > 0.95 * last_moved) break;
    ++since_switch;
    last_moved = *moved;
    accept(dts, *moved);
    ++r.solves;
    if (observer) observer(contacts_stick, r.solves, *moved);
    if (*moved <= tolerance) {
      r.reached = true;
      break;
    }
  }
  return r;
}

// The friction of a relaxation solve running away. The open-close iteration
// takes each sliding contact's friction from the normal force of the last
// iterate; under a pseudo step of 10 dt (little inertia) that fixed point
// can diverge where blocks are wedged between steep joints: the friction
// pushes a block into its neighbours, whose normal forces grow, and so the
// friction. On the jointed cube of bench/df3d.sh (joints dipping 80 deg,
// friction 30 deg) such contacts' friction grew by a factor of 1.65 an
// iterate to MN under blocks of 26 kN, with no state change; each
// relaxation solve then ran its 100 iterations before giving up, and 15
// of them made the 1k cube's start take minutes. Told after each update,
// diverging() is true once the largest change of a sliding contact's
// friction has grown four updates running with no change of state: the
// solve cannot settle, and is given up at once (the relaxation then goes
// on as for any solve that does not settle).
class FrictionRunaway {
 public:
  bool diverging(bool states_changed, double largest_friction_change) {
    growing_ = !states_changed && largest_friction_change > last_ ? growing_ + 1 : 0;
    last_ = largest_friction_change;
    return growing_ >= 4;
  }

 private:
  double last_ = std::numeric_limits<double>::infinity();  // the first update only sets the reference
  int growing_ = 0;
};

// Both phases: relax(contacts_stick) runs one (relax_phase).
template <class Relax>
StartUp relax_both_phases(Relax&& relax) {
  StartUp s;
  const Relaxation stuck = relax(true);
  s.stuck_iterations = stuck.solves;
  s.stuck_equilibrium = stuck.reached;
  if (stuck.solves > 0) {
    const Relaxation friction = relax(false);
    s.friction_iterations = friction.solves;
    s.frictional_equilibrium = stuck.reached && friction.reached;
  }
  return s;
}

}  // namespace dda::df
