// 3D block cutting speed: `build/bench/bench_cut3d` (issue 5's figures).
//
// BM_Cut3dThreeSets/S: a 50 m cube cut by three persistent sets of spacing
// S m (dip/dip direction 80/030, 75/130, 10/250, the first plane of each set
// 0.37 S from the cube's centre), so roughly (50/S)^3 blocks: S = 5 gives
// about 1k, S = 2.3 about 10k.
// BM_Cut3dDiscs/N: the same cube and N discs, radius 5 m (N = 1000: P32 =
// 0.63 m^-1, a moderately fractured mass), centres uniform
// in the cube, normals uniform on the sphere, seed 42; finite fractures cut
// only where they reach through a block (glue mode: the parts they leave
// stay glued into bodies; counters bodies and parts).
// Counters: parts (convex blocks), bodies, parts_per_s (convex blocks made
// per second of cutting, excavation and body building).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "dda/common/fracture_model.hpp"
#include "dda/dc/cut3d.hpp"

namespace {

using dda::Vec3;

Vec3 normal_from_dip(double dip, double dipdir) {
  const double d = dip * dda::kPi / 180, a = dipdir * dda::kPi / 180;
  return {std::sin(d) * std::sin(a), std::sin(d) * std::cos(a), std::cos(d)};
}

dda::FractureModel cube() {
  dda::FractureModel m;
  m.domain = {Vec3(0, 0, 0), Vec3(50, 50, 50)};
  for (const char* s : {"a", "b", "c"}) m.sets.push_back({s, "bench"});
  return m;
}

dda::FractureModel three_sets(double spacing) {
  dda::FractureModel m = cube();
  const Vec3 normals[3] = {normal_from_dip(80, 30), normal_from_dip(75, 130), normal_from_dip(10, 250)};
  const Vec3 centre(25, 25, 25);
  for (int s = 0; s < 3; ++s) {
    const int n = static_cast<int>(std::ceil(45.0 / spacing));  // half-diagonal of the cube is 43.3 m
    for (int k = -n; k <= n; ++k) {
      dda::Fracture3 f;
      f.shape = dda::FractureShape::Plane;
      f.normal = normals[s];
      f.centre = centre + (k + 0.37) * spacing * normals[s];
      f.set = s;
      m.fractures.push_back(f);
    }
  }
  return m;
}

dda::FractureModel discs(int n) {
  dda::FractureModel m = cube();
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0, 50);
  std::normal_distribution<double> g;
  for (int i = 0; i < n; ++i) {
    dda::Fracture3 f;
    f.shape = dda::FractureShape::Disc;
    f.normal = Vec3(g(rng), g(rng), g(rng)).normalized();
    if (f.normal.z() < 0) f.normal = -f.normal;
    f.centre = Vec3(u(rng), u(rng), u(rng));
    f.radius = 5;
    f.set = i % 3;
    m.fractures.push_back(f);
  }
  return m;
}

void run(benchmark::State& state, const dda::FractureModel& m) {
  double blocks = 0, bodies = 0, seconds = 0, unfinished = 0;
  for (auto _ : state) {
    const auto r = dda::dc::cut_blocks_3d(m);
    blocks = static_cast<double>(r.model.blocks.size());
    bodies = static_cast<double>(r.model.bodies.size());
    seconds = r.report["seconds"].get<double>();
    unfinished = r.report["unfinished_fractures"].get<double>();
    benchmark::DoNotOptimize(r);
  }
  state.counters["parts"] = blocks;
  state.counters["bodies"] = bodies;
  state.counters["cut_s"] = seconds;
  state.counters["parts_per_s"] = blocks / seconds;
  state.counters["unfinished"] = unfinished;
}

void BM_Cut3dThreeSets(benchmark::State& state) { run(state, three_sets(static_cast<double>(state.range(0)) / 10)); }
BENCHMARK(BM_Cut3dThreeSets)->Arg(50)->Arg(23)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_Cut3dDiscs(benchmark::State& state) { run(state, discs(static_cast<int>(state.range(0)))); }
BENCHMARK(BM_Cut3dDiscs)->Arg(1000)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
