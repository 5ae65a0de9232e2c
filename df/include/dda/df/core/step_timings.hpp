#pragma once
// Where the time of the steps goes (wall clock, summed over all steps since
// the Simulation was made; see Simulation::timings()).
#include <chrono>

namespace dda::df {

struct StepTimings {
  double contact_search = 0;  // s: broad + narrow phase, states carried over, and contact_geometry
  double contact_geometry = 0;  // s: of it, each contact's linearised geometry from the new positions
  double assembly = 0;        // s: K and F, every open-close iteration
  double solve = 0;           // s: the linear solves
  double contact_update = 0;  // s: the contacts' state updates from each solve (open-close)
  double accept = 0;          // s: ending an accepted step (blocks moved, stresses, energies, friction states)
  double total = 0;           // s: whole steps, attempts thrown away included
  long solves = 0;            // linear solves of the whole system done
  long local_solves = 0;      // solves on contact clusters (contact_clusters.hpp)
  long local_iterations = 0;  // their conjugate-gradient iterations, summed
  long contact_updates = 0;   // contacts updated after the solves (open-close; see Model::contact_update_tolerance)
  long near_searches = 0;     // fresh searches for near pairs (the rest reused them)
};

// Adds the wall time of its own lifetime to a StepTimings field.
class ScopedTimer {
 public:
  explicit ScopedTimer(double& sink) : sink_(sink), start_(std::chrono::steady_clock::now()) {}
  ~ScopedTimer() { sink_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

 private:
  double& sink_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace dda::df
