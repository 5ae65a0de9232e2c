// The same run with 1 and 2 OpenMP threads gives bit-identical results:
// assembly sums in a fixed order (BlockSystem rounds), contact detection
// joins its per-thread lists in order, PCG adds its partial sums in fixed
// chunks.
#include <gtest/gtest.h>
#include <omp.h>

#include <random>

#include "df_test_models.hpp"
#include "forced_threads.hpp"
#include "dda/df/core/broad_phase.hpp"
#include "dda/df/2d/simulation.hpp"

namespace dda::df {
namespace {

// A running-bond brick wall of 73 blocks (~400 contacts, three PCG
// chunks); with the parallel grain lowered to one block every parallel loop
// runs on both threads. Kept small: on a loaded machine every OpenMP
// barrier can cost a scheduler time slice.
ModelInput wall(const std::string& solver) {
  ModelInput in = test::brick_wall(9, 8, solver);
  in.control.dt = 2e-3;
  return in;
}

// Vertices, then per block the end velocity and the stress (these show the
// last bits of the step solution, which the positions may round away).
std::vector<Polygon2> run(const Model& model, int threads, int steps) {
  std::vector<Polygon2> out;
  const testing::ForcedThreads forced(threads);
  Simulation sim(model);
  for (int s = 0; s < steps; ++s) sim.step();
  for (const BlockState& b : sim.blocks()) out.push_back(b.vertices);
  for (const BlockState& b : sim.blocks())
    out.push_back({b.velocity_end.segment<2>(0), b.velocity_end.segment<2>(2), b.velocity_end.segment<2>(4),
                   b.stress.head<2>(), Vec2(b.stress(2), 0)});
  return out;
}

void expect_identical(const std::vector<Polygon2>& a, const std::vector<Polygon2>& b) {
  ASSERT_EQ(a.size(), b.size());
  int differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t v = 0; v < a[i].size(); ++v)
      if (a[i][v].x() != b[i][v].x() || a[i][v].y() != b[i][v].y()) ++differ;
  EXPECT_EQ(differ, 0) << "numbers that differ between 1 and 2 threads";
}

class ParallelDeterminism : public ::testing::TestWithParam<std::string> {};

TEST_P(ParallelDeterminism, OneAndTwoThreadsGiveBitIdenticalBlocks) {
  const Model model = build_model(wall(GetParam()));
  const int steps = 2;
  const auto one = run(model, 1, steps);
  const auto two = run(model, 2, steps);
  expect_identical(one, two);
  // The wall moved (it settles into its contacts under gravity).
  double moved = 0;
  for (std::size_t i = 1; i < model.blocks.size(); ++i)
    moved = std::max(moved, (one[i][0] - model.blocks[i].vertices[0]).norm());
  EXPECT_GT(moved, 0);
}

INSTANTIATE_TEST_SUITE_P(Solvers, ParallelDeterminism, ::testing::Values("cholmod", "pcg"));

TEST(ParallelDeterminism, BroadPhaseIsSortedAndThreadIndependent) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 100), s(0.2, 2);
  std::vector<Box2> boxes(3000);
  for (Box2& b : boxes) {
    b.lo = Vec2(u(rng), u(rng));
    b.hi = b.lo + Vec2(s(rng), s(rng));
  }
  boxes[17].hi = Vec2(120, 120);  // one huge box
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const auto one = broad_phase(boxes, 0.05);
  omp_set_num_threads(2);
  const auto two = broad_phase(boxes, 0.05);
  omp_set_num_threads(saved);
  EXPECT_EQ(one, two);
  EXPECT_TRUE(std::is_sorted(one.begin(), one.end()));
  // Brute force on a sample of blocks.
  for (int i = 0; i < 3000; i += 97) {
    int expected = 0, got = 0;
    for (int j = 0; j < 3000; ++j) {
      if (j == i) continue;
      const Box2 &a = boxes[i], &b = boxes[j];
      if (a.lo.x() - 0.05 <= b.hi.x() + 0.05 && b.lo.x() - 0.05 <= a.hi.x() + 0.05 &&
          a.lo.y() - 0.05 <= b.hi.y() + 0.05 && b.lo.y() - 0.05 <= a.hi.y() + 0.05)
        ++expected;
    }
    for (const auto& [p, q] : one) got += (p == i || q == i);
    EXPECT_EQ(got, expected) << "block " << i;
  }
}

}  // namespace
}  // namespace dda::df
