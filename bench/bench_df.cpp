// Forward-solver speed: `build/bench/bench_df`.
//
// Model: a running-bond brick wall (bricks 1 m x 0.5 m, every other row
// shifted by half a brick) standing on a base block held by three fixed
// points, under gravity, started at rest with the bricks exactly touching.
// E = 5 GPa, density 2600, phi = 35 deg, dt = 1 ms, w0 = 1 m (so the search
// distance is 25 mm). BM_BrickWall/<blocks>/<solver>: solver 0 = auto,
// 1 = cholmod, 2 = pcg. Each benchmark iteration is one Simulation::step();
// three steps are taken before timing starts (the first analyses and
// factorisations are then out of the way, as in a long run).
//
// Counters: blocks, contacts, ms_per_step, steps_per_s, the share of the
// step spent in contact search (finding the contacts, carrying their states
// over) / contact geometry (each contact's linearised geometry, the start of
// forming its springs) / assembly / linear solve / the contacts' state updates
// after each solve (update_pct; updated_pct: the share of the contacts
// updated after a solve, see Model::contact_update_tolerance) / ending an accepted step: blocks moved,
// stresses, energies (accept_pct); the rest is the step's bookkeeping),
// near_searches
// (steps whose near pairs were searched afresh, see near_list.hpp),
// solves per step, PCG iterations per PCG solve, CHOLMOD analyses per step,
// threads.
//
// `bench_df --blocks FILE.h5 [--dt S]` times the steps of a blocks file
// instead (default dt 1 ms; fixed points of the file hold their blocks;
// loads are ignored), on top of any benchmark flag.
//
// `bench_df --blocks FILE.h5 --scenario S.yaml|MODEL.ana` times the very
// model `dda df` would run (materials, joints, loading, fixed points and
// control of the scenario or DDA-for-Windows analysis file), so another DDA
// program can be timed on the same model; after the timing it prints the
// model time reached and the final position of every measurement point.
// Add --benchmark_min_time=N (seconds) or run a fixed number of steps with
// --steps N; --skip N takes N steps before the timing starts (default 3),
// e.g. to time a model once its start-up transient has died out;
// --clusters 1 sets control.contact_clusters true (contact clusters
// between global solves), 0 false (every open-close iterate a solve of the
// whole system); without it the model's own setting holds.
// --resume RESULTS.h5 (with --scenario) starts from the state saved in a
// results file of that model (`dda df` keeps it at the end of a run, or
// at --stop-at-step): the steps of a model that has come to rest, say,
// timed without running up to them each time.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <fstream>
#include <memory>
#include <sstream>

#include "dda/common/block_shape.hpp"
#include "dda/common/memory_policy.hpp"
#include "dda/common/model_io.hpp"
#include "dda/common/yaml_reader.hpp"
#include "dda/df/io/import_ana.hpp"
#include "dda/df/core/linear_solver.hpp"
#include "dda/df/2d/model.hpp"
#include "dda/df/io/results.hpp"
#include "dda/df/io/scenario.hpp"
#include "dda/df/2d/simulation.hpp"

namespace {

using dda::Vec2;
using namespace dda::df;
using dda::make_block;

dda::Polygon2 rectangle(double x0, double y0, double w, double h) {
  return {{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}};
}

ModelInput brick_wall(int blocks) {
  // Twice as wide as high in bricks: cols = 2 rows.
  const int rows = std::max(1, static_cast<int>(std::lround(std::sqrt(blocks / 2.0))));
  const int cols = std::max(1, blocks / rows);
  const double bw = 1.0, bh = 0.5;
  ModelInput in;
  in.geometry.blocks.push_back(make_block(rectangle(-1, -1, cols * bw + 3, 1)));
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      in.geometry.blocks.push_back(make_block(rectangle(c * bw + (r % 2) * 0.5 * bw, r * bh, bw, bh)));
  Material m;
  m.density = 2600;
  m.young = 5e9;
  m.poisson = 0.25;
  in.materials = {m};
  JointProperties j;
  j.friction_deg = 35;
  in.joint_sets = {j};
  in.control.dt = 1e-3;
  in.control.w0 = 1.0;
  for (const double x : {-0.5, 0.5 * cols * bw, cols * bw + 1.5})
    in.fixed_points.push_back({"base", Vec2(x, -0.5), 0, {}});
  return in;
}

const char* solver_name(int code) { return code == 1 ? "cholmod" : code == 2 ? "pcg" : "auto"; }

// A step that throws (a model that blows up) ends the benchmark with its
// message instead of aborting the program.
int g_skip_steps = 3;  // steps taken before timing starts (--skip)
int g_clusters = -1;  // control.contact_clusters of --scenario models (--clusters 0|1; -1: the model's own)

void time_steps(benchmark::State& state, Simulation& sim) {
  try {
    sim.start();  // the start-up relaxation (initial_equilibrium) is not a step: not counted
    for (int s = 0; s < g_skip_steps; ++s) sim.step();
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  const StepTimings t0 = sim.timings();
  const SolverStats s0 = sim.solver().stats();
  const double time0 = sim.time();
  long steps = 0;
  for (auto _ : state) {
    try {
      sim.step();
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      break;
    }
    ++steps;
  }
  const StepTimings& t1 = sim.timings();
  const SolverStats s1 = sim.solver().stats();
  const double total = t1.total - t0.total;
  const double n = static_cast<double>(std::max(1L, steps));
  state.counters["blocks"] = sim.model().block_count();
  state.counters["contacts"] = static_cast<double>(sim.contacts().size());
  state.counters["ms_per_step"] = 1e3 * total / n;
  state.counters["steps_per_s"] = n / total;
  // The model time a step advances: the cost per step depends on it (the
  // step control cuts dt when the open-close iteration does not settle, and
  // a shorter step settles in fewer iterations), so compare runs by wall
  // time per model time too.
  state.counters["dt_us"] = 1e6 * (sim.time() - time0) / n;
  state.counters["wall_s_per_model_s"] = total / std::max(1e-300, sim.time() - time0);
  const double geometry = t1.contact_geometry - t0.contact_geometry;
  state.counters["search_pct"] = 100 * (t1.contact_search - t0.contact_search - geometry) / total;
  state.counters["geometry_pct"] = 100 * geometry / total;
  state.counters["assembly_pct"] = 100 * (t1.assembly - t0.assembly) / total;
  state.counters["solve_pct"] = 100 * (t1.solve - t0.solve) / total;
  state.counters["update_pct"] = 100 * (t1.contact_update - t0.contact_update) / total;
  state.counters["accept_pct"] = 100 * (t1.accept - t0.accept) / total;
  state.counters["near_searches"] = static_cast<double>(t1.near_searches - t0.near_searches);
  state.counters["solves_per_step"] = static_cast<double>(t1.solves - t0.solves) / n;
  // Solves on contact clusters (contact_clusters.hpp) and their CG iterations.
  state.counters["local_solves_per_step"] = static_cast<double>(t1.local_solves - t0.local_solves) / n;
  state.counters["local_it"] = t1.local_solves > t0.local_solves
                                   ? static_cast<double>(t1.local_iterations - t0.local_iterations) /
                                         static_cast<double>(t1.local_solves - t0.local_solves)
                                   : 0;
  // The share of contacts updated after a solve: all after the first and
  // full solves, those of moved blocks after the others.
  const long solves = t1.solves - t0.solves;
  state.counters["updated_pct"] =
      solves > 0 ? 100.0 * static_cast<double>(t1.contact_updates - t0.contact_updates) /
                       (static_cast<double>(solves) * std::max<double>(1.0, static_cast<double>(sim.contacts().size())))
                 : 0;
  const long pcg = s1.pcg_solves - s0.pcg_solves;
  state.counters["pcg_it"] = pcg > 0 ? static_cast<double>(s1.pcg_iterations - s0.pcg_iterations) / pcg : 0;
  state.counters["fallbacks"] = static_cast<double>(s1.fallbacks - s0.fallbacks);
  // PCG trial solves that took the last solve's residual over, as a share
  // of the PCG solves, and the share of the block rows they formed afresh.
  const long kept = s1.pcg_residuals_kept - s0.pcg_residuals_kept;
  state.counters["kept_pct"] = pcg > 0 ? 100.0 * static_cast<double>(kept) / static_cast<double>(pcg) : 0;
  state.counters["refreshed_pct"] =
      kept > 0 ? 100.0 * static_cast<double>(s1.pcg_rows_refreshed - s0.pcg_rows_refreshed) /
                     (static_cast<double>(kept) * std::max(1, sim.model().block_count()))
               : 0;
  state.counters["analyses_per_step"] = static_cast<double>(s1.analyses - s0.analyses) / n;
  state.counters["threads"] = omp_get_max_threads();
}

void BM_BrickWall(benchmark::State& state) {
  ModelInput in = brick_wall(static_cast<int>(state.range(0)));
  in.control.solver = solver_name(static_cast<int>(state.range(1)));
  Simulation sim(build_model(std::move(in)));
  state.SetLabel(sim.solver().name());
  time_steps(state, sim);
}

// The first step from rest: PCG starts from zero (no warm start) and
// CHOLMOD does its symbolic analysis; the worst case for both.
void BM_BrickWallFirstStep(benchmark::State& state) {
  ModelInput in = brick_wall(static_cast<int>(state.range(0)));
  in.control.solver = solver_name(static_cast<int>(state.range(1)));
  const Model model = build_model(std::move(in));
  double pcg_it = 0;
  for (auto _ : state) {
    state.PauseTiming();
    Simulation sim(model);
    state.ResumeTiming();
    sim.step();
    const SolverStats st = sim.solver().stats();
    pcg_it = st.pcg_solves > 0 ? static_cast<double>(st.pcg_iterations) / st.pcg_solves : 0;
  }
  state.counters["pcg_it"] = pcg_it;
  state.counters["blocks"] = model.block_count();
}

// Sizes of about 1k, 10k and 50k blocks with the automatic choice; both
// solvers at the sizes around the crossover.
BENCHMARK(BM_BrickWall)
    ->Args({1000, 0})->Args({10000, 0})->Args({50000, 0})
    ->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
BENCHMARK(BM_BrickWall)
    ->ArgsProduct({{30, 100, 250, 1000, 5000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);
BENCHMARK(BM_BrickWallFirstStep)
    ->ArgsProduct({{30, 100, 250, 1000, 5000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);

// The forward-run input of a scenario (.yaml) or DDA-for-Windows analysis
// (.ana) on the blocks of `blocks_file`, as `dda df` reads it.
ModelInput scenario_input(const std::string& scenario, const std::string& blocks_file) {
  const dda::BlockModel blocks = dda::read_blocks_h5(blocks_file);
  if (scenario.size() > 4 && scenario.substr(scenario.size() - 4) == ".ana") {
    std::ifstream in(scenario);
    if (!in) throw dda::InputError(scenario + ": cannot be read.");
    std::stringstream text;
    text << in.rdbuf();
    return import_ana(text.str(), scenario, blocks, blocks_file).scenario.input;
  }
  return read_df_scenario(dda::YamlNode::load_file(scenario), blocks, blocks_file).input;
}

// Times `steps` steps (or as many as Google Benchmark's time allows) of the
// model and prints where its measurement points end up.
// Starts from `start` if given (a checkpoint of the same model).
void register_model(const std::string& label, const Model& model, int steps,
                    std::shared_ptr<const SimulationState> start = nullptr) {
  auto* b = benchmark::RegisterBenchmark(("BM_Model/" + label).c_str(), [model, start](benchmark::State& state) {
    Simulation sim(model);
    if (start) sim.restore(*start);
    state.SetLabel(sim.solver().name());
    time_steps(state, sim);
    std::fprintf(stderr, "model: %zu steps to t = %.6g s\n", sim.log().size(), sim.time());
    for (int k = 0; k < static_cast<int>(model.measurements.size()); ++k) {
      const Vec2 p = sim.measurement_position(k);
      const Vec2 u = p - model.measurements[static_cast<std::size_t>(k)].position;
      std::fprintf(stderr, "  %-12s x %.9g  y %.9g  (ux %.6g, uy %.6g)\n", model.measurements[static_cast<std::size_t>(k)].name.c_str(),
                  p.x(), p.y(), u.x(), u.y());
    }
  });
  b->Unit(benchmark::kMillisecond)->UseRealTime();
  if (steps > 0) b->Iterations(steps);
}

}  // namespace

int main(int argc, char** argv) {
  dda::keep_freed_memory();  // memory_policy.hpp: large buffers are re-allocated every iterate
  // Our own flags first; the rest goes to Google Benchmark.
  std::string blocks_file, scenario, resume;
  double dt = 1e-3;
  int steps = 0;
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    const bool has_value = i + 1 < argc;
    if (std::strcmp(argv[i], "--blocks") == 0 && has_value) {
      blocks_file = argv[++i];
    } else if (std::strcmp(argv[i], "--dt") == 0 && has_value) {
      dt = std::atof(argv[++i]);
    } else if (std::strcmp(argv[i], "--scenario") == 0 && has_value) {
      scenario = argv[++i];
    } else if (std::strcmp(argv[i], "--steps") == 0 && has_value) {
      steps = std::atoi(argv[++i]);
    } else if (std::strcmp(argv[i], "--resume") == 0 && has_value) {
      resume = argv[++i];
    } else if (std::strcmp(argv[i], "--clusters") == 0 && has_value) {
      g_clusters = std::atoi(argv[++i]) != 0 ? 1 : 0;
    } else if (std::strcmp(argv[i], "--skip") == 0 && has_value) {
      g_skip_steps = std::max(0, std::atoi(argv[++i]));
    } else {
      rest.push_back(argv[i]);
    }
  }
  if (!resume.empty() && scenario.empty()) {
    std::fprintf(stderr, "bench_df: --resume needs --scenario and --blocks (the model the results file is of).\n");
    return 1;
  }
  if (!scenario.empty() && blocks_file.empty()) {
    std::fprintf(stderr, "bench_df: --scenario needs --blocks (the blocks file `dda dc` wrote for it).\n");
    return 1;
  }
  if (!blocks_file.empty()) {
    try {
      if (!scenario.empty()) {
        std::shared_ptr<const SimulationState> start;
        if (!resume.empty()) {
          Results saved = read_results_h5(resume);
          if (!saved.checkpoint)
            throw dda::InputError(resume + ": holds no saved state to start from (not a results file of `dda df`?).");
          start = std::make_shared<const SimulationState>(std::move(*saved.checkpoint));
        }
        ModelInput in = scenario_input(scenario, blocks_file);
        if (g_clusters >= 0) in.control.contact_clusters = g_clusters == 1;
        register_model(scenario, build_model(std::move(in)), steps, start);
      } else {
        ModelInput in;
        in.geometry = dda::read_blocks_h5(blocks_file);
        in.control.dt = dt;
        // Loads need forces from a scenario: skip them here.
        dda::BlockModel no_loads = in.geometry;
        std::erase_if(no_loads.points,
                      [](const dda::LocatedPoint& p) { return p.point.kind == dda::PointKind::Load; });
        add_points_from_block_model(no_loads, {}, in);
        register_model(blocks_file, build_model(std::move(in)), steps);
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "bench_df: %s\n", e.what());
      return 1;
    }
  }
  int rest_argc = static_cast<int>(rest.size());
  benchmark::Initialize(&rest_argc, rest.data());
  if (benchmark::ReportUnrecognizedArguments(rest_argc, rest.data())) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
