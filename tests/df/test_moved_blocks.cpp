// The open-close iteration updates, after a trial solve, only the contacts
// of blocks that moved (moved_blocks.hpp, Model::contact_update_tolerance).
// These tests check the bound it rests on, the bookkeeping of what moved, and
// that a transient run with the filter settles its steps on the same contact
// states as a run that updates every contact after every solve.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "df_test_models.hpp"
#include "dda/df/2d/block_kinematics.hpp"
#include "dda/df/2d/moved_blocks.hpp"
#include "dda/df/2d/simulation.hpp"

namespace dda::df {
namespace {

// The bound must hold for every point within the radius: T(p) (the 2D DDA
// displacement field, block_kinematics.hpp) applied to random changes at
// random points, corners of the radius included (where a rotation moves a
// point by sqrt(2) R |r| in |u| + |v|, more than R |r|).
TEST(MovedBlocks, PointBoundHoldsForEveryPointWithinTheRadius) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1), ang(0, 2 * M_PI), frac(0, 1);
  const Vec2 centroid(3, -2);
  double tightest = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    Vector6d change;
    for (int k = 0; k < kDofs; ++k) change[k] = u(rng) * (k < 2 ? 1e-3 : 1e-4);
    if (trial % 4 == 0) change.head<2>().setZero();  // rotations and strains alone
    const double r = 0.1 + 2 * frac(rng);
    const double bound = MovedBlocks::point_bound(change, r);
    for (int p = 0; p < 20; ++p) {
      const double a = p < 4 ? M_PI / 4 + p * M_PI / 2 : ang(rng);  // four diagonal corners first
      const double reach = p < 4 ? r : r * frac(rng);
      const Vec2 point = centroid + reach * Vec2(std::cos(a), std::sin(a));
      const Vec2 moved = t_matrix(centroid, point) * change;
      const double actual = std::abs(moved.x()) + std::abs(moved.y());
      ASSERT_LE(actual, bound * (1 + 1e-12)) << "trial " << trial << " point " << p;
      tightest = std::max(tightest, actual / bound);
    }
  }
  // Not loose either: some point comes within a third of it.
  EXPECT_GT(tightest, 0.66);
  // A translation is bounded exactly.
  Vector6d shift = Vector6d::Zero();
  shift << 2e-9, -1e-9, 0, 0, 0, 0;
  EXPECT_DOUBLE_EQ(MovedBlocks::point_bound(shift, 5.0), 3e-9);
}

// A block is marked when its change since it was last marked exceeds the
// tolerance: small changes add up against the kept reference.
TEST(MovedBlocks, SmallChangesAddUpAgainstTheReference) {
  const double tol = 1e-12;
  MovedBlocks m;
  m.start({1.0, 1.0});
  Eigen::VectorXd d = Eigen::VectorXd::Zero(2 * kDofs);
  m.mark(d, tol, false);  // first mark after start: every block
  EXPECT_TRUE(m.moved(0));
  EXPECT_TRUE(m.moved(1));
  // Block 0 drifts by 0.3 tol a solve; block 1 stays.
  const int expected[] = {0, 0, 0, 1, 0, 0, 0, 1};  // marked at 1.2 tol, then again 1.2 tol later
  for (int it = 0; it < 8; ++it) {
    d[0] += 0.3 * tol;
    m.mark(d, tol, false);
    EXPECT_EQ(m.moved(0), expected[it] == 1) << "solve " << it;
    EXPECT_FALSE(m.moved(1)) << "solve " << it;
  }
  // A rotation moves the points at the radius: 0.6 tol of rotation on a
  // block of radius 1 is 1.2 tol of bound.
  d[kDofs + 2] += 0.6 * tol;
  m.mark(d, tol, false);
  EXPECT_TRUE(m.moved(1));
  EXPECT_EQ(m.moved_count(), 1);
  // `all` marks every block; a NaN counts as moved.
  m.mark(d, tol, true);
  EXPECT_EQ(m.moved_count(), 2);
  m.mark(d, tol, false);
  EXPECT_EQ(m.moved_count(), 0);
  d[kDofs + 4] = std::numeric_limits<double>::quiet_NaN();
  m.mark(d, tol, false);
  EXPECT_TRUE(m.moved(1));
  EXPECT_FALSE(m.moved(0));
}

// A running-bond wall dropped onto its base from gaps of 0.2 to 1 mm (no
// faces in touch: faces in exact touch make a run's states depend on the
// rounding of its sums, so two runs could not be compared step by step),
// beside a row of blocks resting on the base, held in place by fixed points
// (5 cm apart: side faces in touch at no normal force would slide back and
// forth with the rounding too). The steps of the falling wall need many
// open-close iterates; the held blocks' contacts hardly move through them,
// like the resting parts of a large model.
ModelInput falling_wall() {
  const int rows = 8, cols = 10, held = 30;
  ModelInput in;
  in.geometry.blocks.push_back(test::make_block(test::rectangle(-1, -1, cols + 2 * held + 5, 1)));
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> gap(2e-4, 1e-3);
  double y = gap(rng);
  for (int r = 0; r < rows; ++r, y += 0.5 + gap(rng)) {
    double x = 0.5 * (r % 2);
    for (int c = 0; c < cols; ++c, x += 1 + gap(rng))
      in.geometry.blocks.push_back(test::make_block(test::rectangle(x, y, 1, 0.5)));
  }
  for (int k = 0; k < held; ++k) {
    const double x = cols + 3 + 1.05 * k;
    in.geometry.blocks.push_back(test::make_block(test::rectangle(x, 0, 1, 0.5)));
    const int block = static_cast<int>(in.geometry.blocks.size()) - 1;
    for (const double dx : {0.25, 0.75}) in.fixed_points.push_back({"held", Vec2(x + dx, 0.25), block, {}});
  }
  in.materials = {test::rock(2600, 5e9)};
  JointProperties j;
  j.friction_deg = 30;
  in.joint_sets = {j};
  in.control.dt = 2e-3;
  in.control.w0 = 1.0;
  in.control.max_open_close = 20;
  in.control.solver = "pcg";  // the trial solves are PCG's
  // The global iteration, whose trial solves the filter serves: with
  // contact clusters the two runs' cluster solves (CG to 1e-6) take paths
  // that differ by 3e-11 m, which says nothing about the filter.
  in.control.contact_clusters = false;
  for (const double x : {-0.5, 0.5 * cols, cols + 2 * held + 3.5})
    in.fixed_points.push_back({"base", Vec2(x, -0.5), 0, {}});
  return in;
}

struct RunResult {
  std::vector<StepRecord> steps;
  std::vector<Polygon2> vertices;
  long solves = 0, updates = 0;
};

RunResult run(const Model& model, int steps) {
  Simulation sim(model);
  RunResult out;
  for (int s = 0; s < steps; ++s) out.steps.push_back(sim.step());
  for (const BlockState& b : sim.blocks()) out.vertices.push_back(b.vertices);
  out.solves = sim.timings().solves;
  out.updates = sim.timings().contact_updates;
  return out;
}

// Where the filter could go wrong, a skipped contact that should have
// changed state, the full solve that ends each step would find it and the
// iteration would take other turns: other iterate counts, other states, and
// positions that differ by more than the solves' tolerance. The steps are
// compared over the first 25, 0.05 s: the wall's impacts make the run
// sensitive to rounding after that (gravity changed by two units in the last
// place changes the iterate count of step 29; over these 25 steps it moves
// the blocks by 4e-11 m, ten times the bound below).
TEST(MovedBlocks, FilteredUpdatesSettleOnTheSameStatesAsUpdatingEveryContact) {
  Model filtered = build_model(falling_wall());
  ASSERT_GT(filtered.contact_update_tolerance, 0);
  Model every = filtered;
  every.contact_update_tolerance = 0;
  const int steps = 25;
  const RunResult a = run(filtered, steps), b = run(every, steps);
  int iterates = 0;
  for (int s = 0; s < steps; ++s) {
    EXPECT_EQ(a.steps[s].open_close_iterations, b.steps[s].open_close_iterations) << "step " << s;
    EXPECT_EQ(a.steps[s].open, b.steps[s].open) << "step " << s;
    EXPECT_EQ(a.steps[s].sliding, b.steps[s].sliding) << "step " << s;
    EXPECT_EQ(a.steps[s].locked, b.steps[s].locked) << "step " << s;
    EXPECT_EQ(a.steps[s].dt, b.steps[s].dt) << "step " << s;
    iterates += a.steps[s].open_close_iterations;
  }
  // The wall did fall into its contacts, through steps of many iterates.
  EXPECT_GT(iterates, 3 * steps);
  double fell = 0, differ = 0;
  for (std::size_t i = 1; i < a.vertices.size(); ++i)
    for (std::size_t v = 0; v < a.vertices[i].size(); ++v) {
      fell = std::max(fell, (filtered.blocks[i].vertices[v] - a.vertices[i][v]).norm());
      differ = std::max(differ, (a.vertices[i][v] - b.vertices[i][v]).norm());
    }
  EXPECT_GT(fell, 1e-4);
  // The two runs solve the same systems but for the forces of skipped
  // contacts, which lag by at most pn times the update tolerance (1e-15 m),
  // and the trial solves they start from: they agree to less than a
  // billionth of the fall (4.6e-12 m; measured: 0, the same to the bit).
  EXPECT_LT(differ, 1e-9 * fell);
  // And the filter did skip. (Few here: on a model of 120 blocks every PCG
  // iteration reaches every block. On the 10k-block layered model a trial
  // iterate updates a third of the contacts; see bench_df's updated_pct.)
  EXPECT_EQ(a.solves, b.solves);
  EXPECT_LT(a.updates, b.updates);
}

}  // namespace
}  // namespace dda::df
