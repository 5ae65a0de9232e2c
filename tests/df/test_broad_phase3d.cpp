// The 3D broad phase (df/3d/broad_phase3d.hpp) against brute force: random boxes
// of mixed sizes, a few far larger than the rest (a base, a long wall), with
// any number of threads; and the parallel parts of the 3D step that use it
// (contact detection over the candidate pairs, block terms) giving the same
// numbers on one thread and on two.
#include <gtest/gtest.h>
#include <omp.h>

#include <random>

#include "df_test_models3d.hpp"
#include "forced_threads.hpp"
#include "dda/df/core/block_system.hpp"
#include "dda/df/3d/broad_phase3d.hpp"
#include "dda/df/3d/simulation3d.hpp"

namespace dda::df3 {
namespace {

std::vector<std::pair<int, int>> brute_force(const std::vector<Box3>& boxes, double margin) {
  std::vector<std::pair<int, int>> pairs;
  const int n = static_cast<int>(boxes.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const Box3 a = boxes[i].grown(margin), b = boxes[j].grown(margin);
      if ((a.lo.array() <= b.hi.array()).all() && (b.lo.array() <= a.hi.array()).all()) pairs.emplace_back(i, j);
    }
  return pairs;
}

std::vector<Box3> random_boxes(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> pos(0, 30), size(0.1, 2), big(0.1, 8);
  std::vector<Box3> boxes;
  for (int i = 0; i < n; ++i) {
    Box3 b;
    b.lo = Vec3(pos(rng), pos(rng), pos(rng));
    // Every tenth box up to 8 m on a side: sizes differ by two orders.
    auto& s = i % 10 == 0 ? big : size;
    b.hi = b.lo + Vec3(s(rng), s(rng), s(rng));
    boxes.push_back(b);
  }
  return boxes;
}

TEST(BroadPhase3, SameAsBruteForceOnMixedSizes) {
  std::vector<Box3> boxes = random_boxes(1500, 11);
  boxes.insert(boxes.begin() + 700, Box3{Vec3(-5, -5, -3), Vec3(35, 35, 0.5)});  // a base under everything
  boxes.push_back(Box3{Vec3(10, -2, -2), Vec3(10.3, 32, 32)});                  // a thin wall across
  for (const double margin : {0.0, 0.05, 0.7}) {
    const auto brute = brute_force(boxes, margin);
    ASSERT_FALSE(brute.empty());
    EXPECT_EQ(broad_phase3(boxes, margin), brute) << "margin " << margin;
  }
}

TEST(BroadPhase3, TouchingFacesAreCandidates) {
  // Boxes that share a face or only a corner overlap with margin 0.
  const std::vector<Box3> boxes{{Vec3(0, 0, 0), Vec3(1, 1, 1)}, {Vec3(1, 0, 0), Vec3(2, 1, 1)},
                                {Vec3(2, 1, 1), Vec3(3, 2, 2)}, {Vec3(5, 5, 5), Vec3(6, 6, 6)}};
  const std::vector<std::pair<int, int>> expected{{0, 1}, {1, 2}};
  EXPECT_EQ(broad_phase3(boxes, 0), expected);
  EXPECT_TRUE(broad_phase3({boxes[0]}, 1).empty());
  EXPECT_TRUE(broad_phase3({}, 1).empty());
}

TEST(BroadPhase3, SameWithOneAndTwoThreads) {
  std::vector<Box3> boxes = random_boxes(5000, 3);
  boxes[42].hi = Vec3(40, 40, 40);  // one huge box
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const auto one = broad_phase3(boxes, 0.05);
  omp_set_num_threads(2);
  const auto two = broad_phase3(boxes, 0.05);
  omp_set_num_threads(saved);
  EXPECT_EQ(one, two);
  EXPECT_EQ(one, brute_force(boxes, 0.05));
}

std::vector<Polyhedron> run_stack(int threads, std::vector<Contact3>& contacts) {
  const df::testing::ForcedThreads forced(threads);  // the parallel loops even on 36 blocks
  Simulation3 sim(testing::sliding_stack());
  for (int s = 0; s < 10; ++s) sim.step(2e-3);
  contacts = sim.contacts();
  return sim.blocks();
}

TEST(BroadPhase3, StepIsTheSameOnOneAndTwoThreads) {
  std::vector<Contact3> c1, c2;
  const auto one = run_stack(1, c1), two = run_stack(2, c2);
  ASSERT_EQ(c1.size(), c2.size());
  int closed = 0;
  for (size_t k = 0; k < c1.size(); ++k) {
    EXPECT_EQ(c1[k].i, c2[k].i);
    EXPECT_EQ(c1[k].j, c2[k].j);
    EXPECT_EQ(c1[k].state, c2[k].state);
    EXPECT_EQ(c1[k].normal_force, c2[k].normal_force);  // bit for bit
    closed += c1[k].state != ContactState3::Open;
  }
  EXPECT_GT(closed, 20);
  double moved = 0;
  for (size_t b = 0; b < one.size(); ++b)
    for (size_t v = 0; v < one[b].vertices.size(); ++v) {
      EXPECT_EQ(one[b].vertices[v], two[b].vertices[v]) << "block " << b << " vertex " << v;
      moved = std::max(moved, (one[b].vertices[v] - testing::sliding_stack().blocks[b].vertices[v]).norm());
    }
  EXPECT_GT(moved, 1e-4);  // it did slide
}

}  // namespace
}  // namespace dda::df3
