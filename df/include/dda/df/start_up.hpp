#pragma once
// What the start-up relaxation of initial_equilibrium did (the 2D
// Control::initial_equilibrium, the 3D Control3::initial_equilibrium): one
// report for both solvers, so that whoever prints it (the `dda df` session)
// says the same for a 2D and a 3D run.

namespace dda::df {

// The relaxation runs in two phases of static solves (df/src/start_up_relax.hpp):
// every closed contact stuck, then the joints' friction laws. Each count is
// the solves the phase spent, positive when it came to rest within the
// tolerance, negative when it stopped short of that (a block that falls,
// topples or keeps sliding; its accepted iterates are kept either way, the
// run starts from the last of them), 0 when the phase did not run (no
// relaxation asked for, or phase 1 did not come to rest).
struct StartUp {
  int stuck_iterations = 0, friction_iterations = 0;
  // Phase 2 came to rest: every contact within its friction, the run starts
  // at rest in frictional equilibrium.
  bool frictional_equilibrium = false;
};

}  // namespace dda::df
