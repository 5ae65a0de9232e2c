// Contact clusters in 3D (df/src/3d/simulation3d_clusters.cpp, the driver
// shared with 2D in contact_clusters.hpp): the tests of the 2D clusters
// (test_contact_clusters.cpp) on a wall of 3D bricks. Solve counts are
// deterministic, so they are tested as counts; the physics of every
// accepted step is tested contact by contact; and the result is the one
// the global iteration gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "df_test_models3d.hpp"
#include "dda/df/3d/simulation3d.hpp"

namespace dda::df3 {
namespace {

using testing::box;

// A running-bond wall of rows x cols bricks 1 m long, 0.5 m high and 0.5 m
// thick on a fixed base slab, the bottom course resting on it. Gravity,
// Model3's rock and penalties (E 1 GPa, 1e9 N/m), friction 35 deg, dt
// fixed at 1 ms, 100 open-close iterations allowed (the settings of the 2D
// walls).
Model3 wall(int rows, int cols, bool clusters, bool equilibrium) {
  Model3 m;
  m.blocks.push_back(box(Vec3(-1, -0.5, -0.5), Vec3(cols + 1, 1.0, 0)));
  m.fixed.push_back(true);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      // Odd courses shifted by half a brick.
      const double x = c + 0.5 * (r % 2);
      m.blocks.push_back(box(Vec3(x, 0, 0.5 * r), Vec3(x + 1, 0.5, 0.5 * (r + 1))));
      m.fixed.push_back(false);
    }
  m.default_joint.friction_deg = 35;
  m.control.dt = 1e-3;
  m.control.min_dt_ratio = 1;
  m.control.contact_clusters = clusters;
  m.control.initial_equilibrium = equilibrium;
  m.max_iterations = 100;
  return m;
}

int top_brick(int rows, int cols) { return 1 + (rows - 1) * cols + cols / 2; }

struct WallRun {
  double solves_per_step = 0;
  double cluster_solves_per_step = 0;
  Vec3 top{0, 0, 0};  // displacement of the top course's middle brick, m
};

WallRun run_wall(int rows, int cols, bool clusters, bool equilibrium, int steps) {
  Simulation3 sim(wall(rows, cols, clusters, equilibrium));
  sim.start();
  // The start-up relaxation's solves are not counted.
  const long solves0 = sim.timings().solves, local0 = sim.timings().local_solves;
  const Vec3 start = sim.blocks()[top_brick(rows, cols)].centroid;
  for (int s = 0; s < steps; ++s) sim.step(1e-3);
  WallRun r;
  r.solves_per_step = static_cast<double>(sim.timings().solves - solves0) / steps;
  r.cluster_solves_per_step = static_cast<double>(sim.timings().local_solves - local0) / steps;
  r.top = sim.blocks()[top_brick(rows, cols)].centroid - start;
  return r;
}

// The count, on a 144-brick wall handed over at rest by the start-up
// relaxation (the default). When written: 2.60 global + 0.63 cluster
// solves a step with the clusters, 3.53 without (256 bricks over 100
// steps: 2.95 + 1.69 against 4.37). The saving of a tenth fails if the
// clusters stop doing their work.
TEST(ContactClusters3, BrickWallTakesFewerGlobalSolves) {
  const WallRun with = run_wall(12, 12, true, true, 60);
  const WallRun without = run_wall(12, 12, false, true, 60);
  std::printf("3D 144-brick wall, 60 steps: %.2f global + %.2f cluster solves a step with clusters, %.2f without; "
              "top brick moved %.3g m and %.3g m\n",
              with.solves_per_step, with.cluster_solves_per_step, without.solves_per_step, with.top.norm(),
              without.top.norm());
  EXPECT_LT(with.solves_per_step, 0.9 * without.solves_per_step);
  EXPECT_GT(with.cluster_solves_per_step, 0);
  // Handed over at rest, the wall stays there either way: the top brick
  // moves less than a micrometre (its weight on the 1e9 N/m springs of the
  // courses below would compress them by tens of micrometres, had the
  // relaxation not done so before t = 0).
  EXPECT_LT(with.top.norm(), 1e-6);
  EXPECT_LT(without.top.norm(), 1e-6);
}

// Every accepted step satisfies the contact conditions of the open-close
// rules (Model3::tolerance eps): a locked contact carries at most its
// strength plus ps eps, a sliding one its strength exactly, and the
// strength is tan(phi) times the contact's normal force. Checked after
// every step of a wall switched on under gravity (it bounces on its
// springs, so its contacts change state in most steps), with and without
// the clusters, whose settlements must agree.
TEST(ContactClusters3, EveryAcceptedStepMeetsTheContactConditions) {
  Vec3 top[2];
  for (const bool clusters : {true, false}) {
    Simulation3 sim(wall(6, 6, clusters, false));
    const Model3& m = sim.model();
    const double mu = std::tan(35 * std::acos(-1.0) / 180), eps = m.tolerance, ps = m.shear_penalty;
    const Vec3 start = sim.blocks()[top_brick(6, 6)].centroid;
    long locked = 0, sliding = 0;
    for (int s = 0; s < 80; ++s) {
      sim.step(1e-3);
      for (const Contact3& c : sim.contacts()) {
        if (c.state == ContactState3::Open) continue;
        const double strength = mu * std::max(0.0, c.normal_force);
        if (c.state == ContactState3::Locked) {
          ++locked;
          ASSERT_LE(c.shear_force.norm(), strength + ps * eps) << "step " << s + 1;
        } else {
          ++sliding;
          ASSERT_NEAR(c.strength, strength, 1e-12 * strength + 1e-300) << "step " << s + 1;
          ASSERT_NEAR(c.shear_force.norm(), strength, 1e-12 * strength + 1e-300) << "step " << s + 1;
        }
      }
    }
    top[clusters ? 0 : 1] = sim.blocks()[top_brick(6, 6)].centroid - start;
    std::printf("3D 36-brick wall switched on under gravity, 80 steps (clusters %s): %ld locked and %ld sliding "
                "contact-steps checked, %ld cluster solves; top brick settled %.6g m\n",
                clusters ? "on" : "off", locked, sliding, sim.timings().local_solves, top[clusters ? 0 : 1].z());
    EXPECT_GT(locked, 0);
    if (clusters) {
      EXPECT_GT(sim.timings().local_solves, 0);
    }
  }
  // The settlement (0.13 mm, the bounce on the springs) is the same
  // to the accuracy of the trial solves. (The sideways sway, a few
  // micrometres, depends on which corners stick and slip first, and is not
  // compared.)
  EXPECT_NEAR(top[0].z(), top[1].z(), 1e-3 * std::abs(top[1].z()));
}

}  // namespace
}  // namespace dda::df3
