// run_recorded(): a Simulation stepped to its end with frames, periodic
// atomic rewrites of the results file, and a clean stop on request.
#include <algorithm>
#include <chrono>
#include <cmath>

#include "dda/df/results.hpp"
#include "dda/df/runaway.hpp"

namespace dda::df {
namespace {

// Steps shorter than this are rounding left-overs (as Simulation::run_until).
double time_eps(const Simulation& sim) { return 1e-6 * sim.model().control.dt; }

bool finished(const Simulation& sim) {
  const Control& c = sim.model().control;
  if (c.total_time > 0) return c.total_time - sim.time() <= time_eps(sim);
  return static_cast<int>(sim.log().size()) >= c.steps;
}

// One step toward the end, exactly as Simulation::run() would take it: a full
// step while dt is shorter than what is left, else run_until() lands on the
// end time (shortening the last step, as an uninterrupted run does).
void step_toward_end(Simulation& sim) {
  const Control& c = sim.model().control;
  if (c.total_time > 0 && sim.current_dt() >= c.total_time - sim.time())
    sim.run_until(c.total_time);
  else
    sim.step();
}

bool frame_due(const Simulation& sim, const Results& r) {
  if (r.frames.empty()) return true;
  const int step = sim.log().empty() ? 0 : sim.log().back().step;
  if (r.output.every > 0) return step % r.output.every == 0;
  const double interval = r.output.interval;
  const double eps = 1e-9 * interval;
  return std::floor((sim.time() + eps) / interval) > std::floor((r.frames.back().time + eps) / interval);
}

}  // namespace

double run_progress(const Simulation& sim) {
  const Control& c = sim.model().control;
  const double f = c.total_time > 0 ? sim.time() / c.total_time
                                    : static_cast<double>(sim.log().size()) / std::max(1, c.steps);
  return std::clamp(f, 0.0, 1.0);
}

RunEnd run_recorded(Simulation& sim, Results& results, const std::string& path, const RunControl& control) {
  using Clock = std::chrono::steady_clock;
  auto record = [&] {
    results.frames.push_back(make_frame(sim));
    if (control.on_frame) control.on_frame(sim, results.frames.size() - 1);
  };
  if (results.frames.empty()) record();
  auto last_write = Clock::now();
  int steps_since_write = 0;
  RunEnd end = RunEnd::Finished;
  while (!finished(sim)) {
    if (control.interrupted && *control.interrupted) {
      end = RunEnd::Interrupted;
      break;
    }
    if (control.stop_at_step && static_cast<int>(sim.log().size()) >= *control.stop_at_step) {
      end = RunEnd::Stopped;
      break;
    }
    try {
      step_toward_end(sim);
    } catch (const RunawayError&) {
      // The failed step was not accepted: keep what the run did before it.
      write_results_h5(path, results, sim, false);
      throw;
    }
    ++steps_since_write;
    if (control.on_step) control.on_step(sim);
    if (frame_due(sim, results)) record();
    const double since = std::chrono::duration<double>(Clock::now() - last_write).count();
    if ((control.checkpoint_steps > 0 && steps_since_write >= control.checkpoint_steps) ||
        (control.checkpoint_seconds > 0 && since >= control.checkpoint_seconds)) {
      write_results_h5(path, results, sim, false);
      last_write = Clock::now();
      steps_since_write = 0;
    }
  }
  if (end == RunEnd::Finished) {
    const int step = sim.log().empty() ? 0 : sim.log().back().step;
    if (results.frames.back().step != step) record();  // the final state is always a frame
  }
  write_results_h5(path, results, sim, end == RunEnd::Finished);
  return end;
}

}  // namespace dda::df
