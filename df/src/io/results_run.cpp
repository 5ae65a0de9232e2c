// run_recorded() for the 2D Simulation: the shared loop of run_loop.hpp with
// the 2D solver's notion of the run's end and of a step toward it.
#include <algorithm>

#include "dda/df/io/results.hpp"

namespace dda::df {

// Steps shorter than this are rounding left-overs (as Simulation::run_until).
static double time_eps(const Simulation& sim) { return 1e-6 * sim.model().control.dt; }

bool run_finished(const Simulation& sim) {
  const Control& c = sim.model().control;
  if (c.total_time > 0) return c.total_time - sim.time() <= time_eps(sim);
  return static_cast<int>(sim.log().size()) >= c.steps;
}

// One step toward the end, exactly as Simulation::run() would take it: a full
// step while dt is shorter than what is left, else run_until() lands on the
// end time (shortening the last step, as an uninterrupted run does).
void run_step(Simulation& sim) {
  const Control& c = sim.model().control;
  if (c.total_time > 0 && sim.current_dt() >= c.total_time - sim.time())
    sim.run_until(c.total_time);
  else
    sim.step();
}

int last_step(const Simulation& sim) { return sim.log().empty() ? 0 : sim.log().back().step; }

void write_results(const std::string& path, const Results& results, const Simulation& sim, bool complete) {
  write_results_h5(path, results, sim, complete);
}

double run_progress(const Simulation& sim) {
  const Control& c = sim.model().control;
  const double f = c.total_time > 0 ? sim.time() / c.total_time
                                    : static_cast<double>(sim.log().size()) / std::max(1, c.steps);
  return std::clamp(f, 0.0, 1.0);
}

RunEnd run_recorded(Simulation& sim, Results& results, const std::string& path, const RunControl& control) {
  return run_recorded_loop(sim, results, path, control);
}

}  // namespace dda::df
