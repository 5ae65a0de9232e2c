#pragma once
// The open-close iteration of a step, one driver for the 2D and the 3D
// solver. Internal to df/src.
//
// A step's contact states are not known before it is solved: a contact
// assumed closed may pull, one assumed locked may exceed its friction, an
// open one may penetrate. So the step is solved with assumed states, every
// contact is updated from the solution, and the system is solved again with
// the new states until none changes and every sliding contact's friction
// agrees with the normal force it produced (Shi's open-close iteration).
//
// The rules of the iteration, the same in both dimensions:
// - While states change, solves may be trial ones (a loose tolerance,
//   linear_solver.hpp): they only have to decide states. An iterate that
//   settles on a trial solve is solved again at full accuracy and checked
//   once more, so an accepted step's states are those of a full solve. The
//   last iterate allowed is always a full solve.
// - After a trial solve the kernel may update only the contacts that can
//   have changed (the 2D kernel's moved blocks); after the first solve and
//   after every full one it updates them all, so an accepted step is checked
//   whole.
// - Between two global solves the contact clusters (contact_clusters.hpp)
//   may settle the changes on the blocks around them; the global solve
//   after them is a full one, which verifies them.
// - The kernel may give up early (the 3D start-up relaxation's diverging
//   friction, start_up_relax.hpp); the caller then treats the step as not
//   settled, as when the iterations run out.
//
// What differs between the dimensions is behind OpenCloseKernel: the 2D
// kernel is in simulation.cpp (Simulation::open_close), the 3D one in
// simulation3d.cpp (Simulation3::iterate).
#include <concepts>

namespace dda::df {

// What a solver offers the open-close driver.
//   solve(iteration, trial)   assemble K and F in the states the last update
//                             left (iteration 1: those the step starts from)
//                             and solve; trial: a trial solve is allowed.
//                             Returns whether the solve was a trial one.
//   update_contacts(iteration, every)
//                             update the contacts from the solution (every
//                             one if `every`); true when none changed state
//                             and every sliding contact's friction agrees
//                             with its normal force
//   gives_up()                stop now, unsettled (after an update that did
//                             not settle)
//   settle_clusters()         settle the last update's changes locally; true
//                             when they settled (the next global solve then
//                             checks them), false to go on globally
template <class K>
concept OpenCloseKernel = requires(K& kernel, int iteration, bool flag) {
  { kernel.solve(iteration, flag) } -> std::convertible_to<bool>;
  { kernel.update_contacts(iteration, flag) } -> std::convertible_to<bool>;
  { kernel.gives_up() } -> std::convertible_to<bool>;
  { kernel.settle_clusters() } -> std::convertible_to<bool>;
};

struct OpenCloseRules {
  int max_iterations = 1;    // global solves allowed
  bool trial_first = true;   // the first solve may be a trial one (false after a quiet step)
  bool clusters = false;     // settle changes on contact clusters between global solves
};

// Iterates the step's contact states to agreement. True when they settled
// (the last solve a full one); `iterations` is the number of global solves.
template <OpenCloseKernel K>
bool iterate_open_close(K& kernel, const OpenCloseRules& rules, int& iterations) {
  const int limit = rules.max_iterations;
  bool trial = rules.trial_first;
  for (iterations = 1; iterations <= limit; ++iterations) {
    const bool was_trial = kernel.solve(iterations, trial && iterations < limit);
    const bool settled = kernel.update_contacts(iterations, iterations == 1 || !was_trial);
    if (settled) {
      if (!was_trial) return true;
      trial = false;  // verify at full accuracy
      continue;
    }
    if (kernel.gives_up()) return false;
    if (rules.clusters && iterations < limit && kernel.settle_clusters()) {
      trial = false;  // the next global solve checks the clusters' states, at full accuracy
      continue;
    }
    if (iterations == 1) trial = true;  // a full first solve that did not settle: trials from here
  }
  iterations = limit;
  return false;
}

}  // namespace dda::df
