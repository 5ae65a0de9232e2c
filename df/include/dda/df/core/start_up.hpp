#pragma once
// What the start-up relaxation of initial_equilibrium did (the 2D
// Control::initial_equilibrium, the 3D Control3::initial_equilibrium): one
// report for both solvers, so that whoever prints it (the `dda df` session)
// says the same for a 2D and a 3D run.

#include <functional>

namespace dda::df {

// The relaxation runs in two phases of static solves (df/src/core/start_up_relax.hpp):
// every closed contact stuck, then the joints' friction laws. Each count is
// the solves the phase accepted (0 when it did not run: no relaxation
// asked for, or phase 1 accepted none); the flags say whether the phase
// came to rest within the tolerance. A phase that stops short of that (a
// block that falls, topples or keeps sliding) keeps its accepted iterates:
// the run starts from the last of them.
struct StartUp {
  int stuck_iterations = 0, friction_iterations = 0;
  bool stuck_equilibrium = false;
  // Both phases came to rest: every contact within its friction, the run
  // starts at rest in frictional equilibrium.
  bool frictional_equilibrium = false;
};

// One phase of it.
struct Relaxation {
  int solves = 0;        // accepted
  bool reached = false;  // the last moved no vertex more than the tolerance
};

// Told after every accepted relaxation solve: the phase (true: contacts
// stuck), the solves the phase has accepted so far and the largest vertex
// motion of the last. Lets a caller show that a long relaxation (minutes on
// 10k blocks) is getting somewhere.
using StartUpObserver = std::function<void(bool contacts_stick, int solves, double moved)>;

// Open-close iterations a relaxation solve may take at least. The
// relaxation has no shorter step to fall back on, and a tunnel of 2,221
// blocks needed 50 in its first stuck solve (with the default 6 of a step
// its relaxation ended there).
constexpr int kSettleOpenClose = 100;

}  // namespace dda::df
