// run_recorded() for the 3D Simulation3: the shared loop of run_loop.hpp,
// stepping exactly as Simulation3::run() does, so a run stopped and resumed
// takes the same steps as one that was not.
#include <algorithm>

#include "dda/df/io/results3d.hpp"

namespace dda::df3 {

bool run_finished(const Simulation3& sim) { return sim.finished(); }

void run_step(Simulation3& sim) {
  const Control3& c = sim.model().control;
  sim.advance(c.total_time > 0 ? c.total_time - sim.time() : 1e300);
}

int last_step(const Simulation3& sim) { return sim.log().empty() ? 0 : sim.log().back().step; }

void write_results(const std::string& path, const Results3& results, const Simulation3& sim, bool complete) {
  write_results3_h5(path, results, sim, complete);
}

double run_progress(const Simulation3& sim) {
  const Control3& c = sim.model().control;
  const double f = c.total_time > 0 ? sim.time() / c.total_time
                                    : static_cast<double>(sim.log().size()) / std::max(1, c.steps);
  return std::clamp(f, 0.0, 1.0);
}

df::RunEnd run_recorded(Simulation3& sim, Results3& results, const std::string& path, const RunControl3& control) {
  return df::run_recorded_loop(sim, results, path, control);
}

Frame3 make_frame(const Simulation3& sim) {
  Frame3 f;
  f.step = last_step(sim);
  f.time = sim.time();
  for (const Polyhedron& b : sim.blocks()) f.vertices.insert(f.vertices.end(), b.vertices.begin(), b.vertices.end());
  f.velocity = sim.velocities();
  f.stress = sim.stresses();
  return f;
}

}  // namespace dda::df3
