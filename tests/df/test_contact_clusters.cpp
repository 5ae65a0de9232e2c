// Contact clusters (df/src/core/contact_clusters.hpp): the state changes of an
// open-close iterate settled on the blocks around them, with a global solve
// to check. The solves per step are deterministic counts, so they are
// tested as counts; the physics of every accepted step is tested contact by
// contact; and the result is the one the global iteration gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "df_test_models.hpp"
#include "dda/df/2d/simulation.hpp"

namespace dda::df {
namespace {

// A running-bond wall of rows x cols bricks on its base, relaxed under
// gravity before t = 0 (as the old program's gravity turn-on phase does for
// the DDA-for-Windows walls of bench/brick_wall.sh), then run at a fixed
// dt of 1 ms with 100 iterations allowed (the benchmark's settings).
ModelInput wall(int rows, int cols, bool clusters) {
  ModelInput in = test::brick_wall(rows, cols);
  in.control.initial_equilibrium = true;
  in.control.max_open_close = 100;
  in.control.min_dt_ratio = 1;  // dt fixed: the counts are per step of 1 ms
  in.control.contact_clusters = clusters;
  in.control.w0.reset();  // the model's own (half its height), as for the walls of the .geo/.ana files
  return in;
}

struct WallRun {
  double solves_per_step = 0;
  double cluster_solves_per_step = 0;
  Vec2 top{0, 0};  // displacement of the middle brick of the top row, m
};

WallRun run_wall(int rows, int cols, bool clusters, int steps) {
  ModelInput in = wall(rows, cols, clusters);
  const int top = 1 + (rows - 1) * cols + cols / 2;
  in.measurements.push_back({"top", in.geometry.blocks[top].vertices[0] + Vec2(0.5, 0.25), top});
  Simulation sim(build_model(std::move(in)));
  sim.start();
  const StepTimings t0 = sim.timings();  // the relaxation before t = 0 is not counted
  for (int s = 0; s < steps; ++s) sim.step();
  const StepTimings& t1 = sim.timings();
  WallRun r;
  r.solves_per_step = static_cast<double>(t1.solves - t0.solves) / steps;
  r.cluster_solves_per_step = static_cast<double>(t1.local_solves - t0.local_solves) / steps;
  r.top = sim.histories()[0].back().displacement;
  return r;
}

// The count: a 400-brick wall averages at most 3 solves of the
// whole system a step. Since the start-up relaxation hands the wall over in
// frictional equilibrium (settle.cpp, phase 2) the global iteration alone
// meets it too (2.78; 5.29 when the wall started with every contact stuck),
// and the clusters take a third off that: the test checks both, and that
// the clusters save at least a fifth, so that it fails if they stop doing
// their work. (200 steps: 1.73 global + 0.78 cluster solves with, 2.78
// without, when written; the walls of bench/brick_wall.sh give the same
// counts.)
TEST(ContactClusters, FourHundredBrickWallAveragesAtMostThreeSolvesAStep) {
  const WallRun with = run_wall(20, 20, true, 200);
  const WallRun without = run_wall(20, 20, false, 200);
  std::printf("400-brick wall, 200 steps: %.2f global + %.2f cluster solves a step with clusters, %.2f without\n",
              with.solves_per_step, with.cluster_solves_per_step, without.solves_per_step);
  EXPECT_LE(with.solves_per_step, 3.0);
  EXPECT_LE(without.solves_per_step, 3.0);
  EXPECT_LT(with.solves_per_step, 0.8 * without.solves_per_step);
  // The same wall either way: both end every step with every contact
  // checked against a full global solve. The top brick settles 0.2 mm under
  // the wall's weight; the two runs take other iterates, so they agree to
  // the trial solves' accuracy, not to the bit.
  EXPECT_NEAR(with.top.y(), without.top.y(), 1e-3 * std::abs(without.top.y()));
  EXPECT_NEAR(with.top.x(), without.top.x(), 1e-3 * std::abs(without.top.y()));
}

// Every accepted step satisfies the contact conditions the open-close rules
// state (ContactLaw::tolerance eps): a closed contact pulls with at most
// pn eps (but for the iteration's guard, below), a locked one carries at
// most its strength plus ps eps, a sliding one carries its strength
// exactly, against its slip. Checked after every
// step of a wall whose contacts change state in most steps (switched on
// under gravity, so it bounces on its springs).
void check_conditions(bool clusters, double& worst_pull) {
  ModelInput in = wall(8, 8, clusters);
  in.control.initial_equilibrium = false;
  Simulation sim(build_model(std::move(in)));
  const Model& m = sim.model();
  long solved_locally = 0, sliding = 0, locked = 0;
  worst_pull = 0;  // N, the largest tension of a closed contact
  for (int s = 0; s < 150; ++s) {
    const long before = sim.timings().local_solves;
    sim.step();
    solved_locally += sim.timings().local_solves - before;
    for (const Contact& c : sim.contacts()) {
      if (c.state == ContactState::Open) continue;
      const double eps = m.contact_tolerance, ps = m.joint_ps[c.joint];
      const double strength = std::tan(m.joints[c.joint].friction_deg * std::acos(-1.0) / 180) * std::max(0.0, c.normal_force);
      worst_pull = std::max(worst_pull, -c.normal_force);
      if (c.state == ContactState::Locked) {
        ++locked;
        ASSERT_LE(std::abs(c.shear_force), strength + ps * eps) << "step " << s + 1;
      } else {
        ++sliding;
        ASSERT_NEAR(c.shear_force, -c.slip_sign * strength, 1e-12 * strength + 1e-300) << "step " << s + 1;
      }
    }
  }
  std::printf("64-brick wall, 150 steps: %ld cluster solves, %ld locked and %ld sliding contact-steps checked, "
              "largest pull %.3g N\n", solved_locally, locked, sliding, worst_pull);
  if (clusters) {
    EXPECT_GT(solved_locally, 0);  // the clusters were at work
  }
  EXPECT_GT(sliding, 0);
}

TEST(ContactClusters, EveryAcceptedStepMeetsTheContactConditions) {
  double with = 0, without = 0;
  check_conditions(true, with);
  check_conditions(false, without);
  // A closed contact pulls with at most pn eps (0.25 N here) unless the
  // iteration's guard against chatter holds it closed (update_contact's
  // `hold`): it then keeps the pull of the cycle it was caught in. That
  // pull is not small: 4.3 kN at worst in this run of the global iteration
  // (a third of a brick's weight, 12.8 kN), a defect of the guard that the
  // clusters neither cause nor mend (3.3 kN with them). What is tested
  // here: the clusters leave the pulls no larger than the global iteration.
  EXPECT_LE(with, 1.25 * without);
  EXPECT_GT(without, 0.0);
}

}  // namespace
}  // namespace dda::df
