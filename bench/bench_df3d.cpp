// 3D forward-solver speed: `build/bench/bench_df3d` (bench/df3d.sh prints
// the table).
//
// Model: a cube of jointed rock cut by DC's 3D cutter (cut3d.hpp) with three
// persistent sets of spacing 1 m, dip/dip direction 10/250, 80/030 and
// 80/130, so the blocks are skewed parallelepipeds (and slivers along the
// cube's faces), not stacked bricks. The blocks touching the cube's base are
// fixed; the rest start at rest under gravity with Model3's defaults
// (E = 1 GPa, rho = 2600, phi = 30, penalties 1e9 N/m) and contact_reach
// 0.02 m (2 % of the block size; the largest displacement in a step is far
// smaller). Blocks under 0.01 m^3 (slivers where planes pass near an edge
// or corner of the cube, down to 1e-10 m^3) are left out: against 1e9 N/m
// penalties their tiny mass makes K too ill-conditioned for a Cholesky
// factor. BM_JointedCube/<E>: a cube of edge E dm; 37, 90 and 205 give
// about 100, 1,000 and 10,000 blocks.
//
// Each benchmark iteration is one Simulation3::step(dt) (default dt = 2 ms,
// --dt S), the first from rest included; --steps N steps (default 6);
// --solver auto|cholmod|pcg (default auto: Control3::solver); --clusters 0|1
// (default 1: Control3::contact_clusters); --equilibrium 0|1 (default 1:
// Control3::initial_equilibrium); --iterations N (open-close iterations
// allowed a step; default Model3's).
// Counters: blocks, fixed, contacts and closed contacts after the last
// step, ms_start and start_solves (the start-up relaxation before t = 0:
// its time and its global solves), ms_first (the first step),
// ms_later (the mean of the others), solves per step (open-close
// iterates; cluster solves per step), and the shares of the step spent in contact detection,
// assembly and the linear solve (the rest: open-close updates and the
// end-of-step block update), and PCG's mean iterations per solve and
// its fallbacks to CHOLMOD. Assembly and solve come from
// Simulation3::timings(); detection is timed by running detect_contacts3 on
// the same state just before each step, outside the timed step (the step
// then repeats that very work).
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "dda/common/memory_policy.hpp"
#include "dda/common/fracture_model.hpp"
#include "dda/dc/cut3d.hpp"
#include "dda/df/3d/simulation3d.hpp"
#include "dda/dl/dfn3d.hpp"

namespace {

using dda::Vec3;
using namespace dda::df3;

constexpr double kSpacing = 1.0;      // m, all three sets
constexpr double kSmallest = 0.01;    // m^3: smaller blocks are left out

int g_steps = 6;
double g_dt = 2e-3;
std::string g_solver = "auto";
bool g_clusters = true;
int g_iterations = 0;  // open-close iterations allowed a step; 0: Model3's default
bool g_equilibrium = true;

dda::FractureModel jointed_cube(double edge) {
  dda::FractureModel m;
  m.domain = {Vec3(0, 0, 0), Vec3(edge, edge, edge)};
  const Vec3 normals[3] = {dda::dl::normal_from_dip(10, 250), dda::dl::normal_from_dip(80, 30),
                           dda::dl::normal_from_dip(80, 130)};
  const Vec3 centre = Vec3::Constant(edge / 2);
  const int reach = static_cast<int>(std::ceil(0.87 * edge / kSpacing));  // half the cube's diagonal
  for (int s = 0; s < 3; ++s) {
    m.sets.push_back({std::string(1, static_cast<char>('a' + s)), "bench"});
    for (int k = -reach; k <= reach; ++k) {
      dda::Fracture3 f;
      f.shape = dda::FractureShape::Plane;
      f.normal = normals[s];
      f.centre = centre + (k + 0.37) * kSpacing * normals[s];  // no plane through the cube's corners
      f.set = s;
      m.fractures.push_back(f);
    }
  }
  return m;
}

Model3 cube_model(double edge) {
  Model3 m;
  for (dda::Polyhedron& p : dda::dc::cut_blocks_3d(jointed_cube(edge)).model.blocks)
    if (p.volume >= kSmallest * std::pow(kSpacing, 3)) m.blocks.push_back(std::move(p));
  for (const dda::Polyhedron& p : m.blocks) {
    double bottom = p.vertices.front().z();
    for (const Vec3& v : p.vertices) bottom = std::min(bottom, v.z());
    m.fixed.push_back(bottom < 1e-6 * edge);  // the bottom layer rests on the (absent) ground
  }
  m.contact_reach = 0.02 * kSpacing;
  m.control.solver = g_solver;
  m.control.contact_clusters = g_clusters;
  m.control.initial_equilibrium = g_equilibrium;
  if (g_iterations > 0) m.max_iterations = g_iterations;
  return m;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void BM_JointedCube(benchmark::State& state) {
  const Model3 model = cube_model(0.1 * static_cast<double>(state.range(0)));
  Simulation3 sim(model);
  // The start-up relaxation (Control3::initial_equilibrium), timed and
  // counted on its own.
  const auto relax = std::chrono::steady_clock::now();
  sim.start();
  const double start_seconds = seconds_since(relax);
  const long start_solves = sim.timings().solves, start_local = sim.timings().local_solves;
  double first = 0, later = 0, detection = 0, total = 0;
  long steps = 0, solves = 0;
  for (auto _ : state) {
    state.PauseTiming();
    const auto probe = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(detect_contacts3(sim.blocks(), sim.contacts(), model.contact_reach, model.contact_merge));
    detection += seconds_since(probe);
    state.ResumeTiming();
    const auto start = std::chrono::steady_clock::now();
    try {
      solves += sim.step(g_dt).iterations;
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      break;
    }
    const double t = seconds_since(start);
    (steps == 0 ? first : later) += t;
    total += t;
    ++steps;
  }
  long fixed = 0, closed = 0;
  for (const bool f : model.fixed) fixed += f;
  for (const Contact3& c : sim.contacts()) closed += c.state != ContactState3::Open;
  const double n = static_cast<double>(std::max(1L, steps));
  const dda::df::StepTimings& t = sim.timings();
  state.counters["blocks"] = static_cast<double>(model.blocks.size());
  state.counters["fixed"] = static_cast<double>(fixed);
  state.counters["contacts"] = static_cast<double>(sim.contacts().size());
  state.counters["closed"] = static_cast<double>(closed);
  state.counters["ms_first"] = 1e3 * first;
  state.counters["ms_later"] = steps > 1 ? 1e3 * later / static_cast<double>(steps - 1) : 0;
  state.counters["solves_per_step"] = static_cast<double>(solves) / n;
  state.counters["cluster_solves_per_step"] = static_cast<double>(t.local_solves - start_local) / n;
  state.counters["ms_start"] = 1e3 * start_seconds;
  state.counters["start_solves"] = static_cast<double>(start_solves);
  state.counters["detect_pct"] = 100 * detection / total;
  state.counters["assembly_pct"] = 100 * t.assembly / total;
  state.counters["solve_pct"] = 100 * t.solve / total;
  const dda::df::SolverStats st = sim.solver().stats();
  state.counters["pcg_iterations"] =
      st.pcg_solves > 0 ? static_cast<double>(st.pcg_iterations) / static_cast<double>(st.pcg_solves) : 0;
  state.counters["fallbacks"] = static_cast<double>(st.fallbacks);
  state.counters["threads"] = omp_get_max_threads();
}

}  // namespace

int main(int argc, char** argv) {
  dda::keep_freed_memory();  // memory_policy.hpp: large buffers are re-allocated every iterate
  // Our own flags first; the rest goes to Google Benchmark.
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    const bool has_value = i + 1 < argc;
    if (std::strcmp(argv[i], "--steps") == 0 && has_value) {
      g_steps = std::max(1, std::atoi(argv[++i]));
    } else if (std::strcmp(argv[i], "--iterations") == 0 && has_value) {
      g_iterations = std::max(1, std::atoi(argv[++i]));
    } else if (std::strcmp(argv[i], "--equilibrium") == 0 && has_value) {
      g_equilibrium = std::atoi(argv[++i]) != 0;
    } else if (std::strcmp(argv[i], "--clusters") == 0 && has_value) {
      g_clusters = std::atoi(argv[++i]) != 0;
    } else if (std::strcmp(argv[i], "--solver") == 0 && has_value) {
      g_solver = argv[++i];
    } else if (std::strcmp(argv[i], "--dt") == 0 && has_value) {
      g_dt = std::atof(argv[++i]);
    } else {
      rest.push_back(argv[i]);
    }
  }
  benchmark::RegisterBenchmark("BM_JointedCube", BM_JointedCube)
      ->Arg(37)
      ->Arg(90)
      ->Arg(205)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->Iterations(g_steps);
  int rest_argc = static_cast<int>(rest.size());
  benchmark::Initialize(&rest_argc, rest.data());
  if (benchmark::ReportUnrecognizedArguments(rest_argc, rest.data())) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
