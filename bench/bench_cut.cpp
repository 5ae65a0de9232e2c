// Block cutting speed: `build/bench/bench_cut`.
//
// Input: N random joint traces, lengths uniform in [1, 5] m, orientations
// uniform in [0, 180) deg, centres uniform in a square domain of side
// sqrt(N / 2) m (constant density: 2 trace centres per m^2, ~3 crossings per
// trace), two joint sets alternating, seed 42. The square is the domain, so
// traces are clipped at its sides. Counters: lines, blocks, faces (bounded
// faces of the arrangement after pruning) and the cutter's own seconds.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "dda/common/line_model.hpp"
#include "dda/dc/cut.hpp"

namespace {

dda::LineModel random_model(int n, unsigned seed) {
  const double side = std::sqrt(n / 2.0);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, side), ua(0, dda::kPi), ul(1, 5);
  dda::LineModel m;
  m.domain = {dda::Vec2(0, 0), dda::Vec2(side, 0), dda::Vec2(side, side), dda::Vec2(0, side)};
  m.lines.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const dda::Vec2 c(u(rng), u(rng));
    const double a = ua(rng), l = ul(rng);
    const dda::Vec2 d(0.5 * l * std::cos(a), 0.5 * l * std::sin(a));
    dda::JointLine j;
    j.a = c - d;
    j.b = c + d;
    j.set = i % 2;
    m.lines.push_back(j);
  }
  return m;
}

void BM_CutRandomLines(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const dda::LineModel m = random_model(n, 42);
  double blocks = 0, faces = 0, seconds = 0;
  for (auto _ : state) {
    dda::dc::CutResult r = dda::dc::cut_blocks(m, {});
    blocks = static_cast<double>(r.model.blocks.size());
    faces = r.report["faces"].get<double>();
    seconds = r.report["seconds"].get<double>();
    benchmark::DoNotOptimize(r);
  }
  state.counters["lines"] = n;
  state.counters["blocks"] = blocks;
  state.counters["faces"] = faces;
  state.counters["cut_s"] = seconds;
}

BENCHMARK(BM_CutRandomLines)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
