// Rock bolts in the 3D solver (df/3d/bolts3d.hpp, the law in df/core/bolt_law.hpp).
//
// The model: a fixed 1 m cube (the roof, z in [2, 3]) and a free 1 m cube
// below it (z in [0, 1]), 1 m apart so that they never touch; a vertical
// bolt joins the roof's centre (0.5, 0.5, 2.5) to the hanging cube's centre
// (0.5, 0.5, 0.5): L0 = 2 m. rho = 2600 kg/m^3, so m = 2600 kg and the
// weight W = m g = 25,506 N; k = 1e6 N/m. The bolt ends at the centroid,
// where the displacement matrix has no strain or rotation columns: the
// hanging cube is a mass on a spring, whose closed forms are
//   static extension     W / k = 0.025506 m (pretension P: (W - P) / k),
//   free oscillation     about it, angular frequency sqrt(k / m), period
//                        T = 2 pi sqrt(m / k) = 0.32038 s,
//   after a break        free fall from the state at the break.
// The step is DDA's implicit one (constant acceleration, from the forces at
// the end of the step): a spring loses k/2 dL^2 in a step in which it
// stretches by dL (docs/formulation.md), which the ledger test checks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>
#include <filesystem>
#include <memory>

#include "dda/common/error.hpp"
#include "dda/df/3d/ground_motion3d.hpp"
#include "dda/df/io/results3d.hpp"
#include "dda/df/3d/simulation3d.hpp"
#include "df_test_models3d.hpp"

namespace dda::df3 {
namespace {

namespace fs = std::filesystem;

constexpr double kMass = 2600, kG = 9.81, kWeight = kMass * kG, kStiffness = 1e6, kRest = 2.0;
const double kPi = std::acos(-1.0);

Model3 hanging_cube(double dt) {
  Model3 m;
  m.blocks = {testing::box({0, 0, 2}, {1, 1, 3}), testing::box({0, 0, 0}, {1, 1, 1})};
  m.fixed = {true, false};
  m.materials = {{2600, 1e10, 0.25}};
  m.gravity = {0, 0, -kG};
  m.contact_reach = 0.01;
  m.control.dt = dt;
  m.control.initial_equilibrium = false;  // released from rest at L0: the oscillation's start
  m.measurements = {{"centre", 1, Vec3(0.5, 0.5, 0.5)}};
  Bolt3 b;
  b.name = "b1";
  b.anchor = {0.5, 0.5, 2.5};
  b.head = {0.5, 0.5, 0.5};
  b.anchor_block = 0;
  b.head_block = 1;
  b.stiffness = kStiffness;
  m.bolts = {b};
  return m;
}

void run_for(Simulation3& sim, double dt, int steps) {
  for (int s = 0; s < steps; ++s) sim.step(dt);
}

// The greatest (sign +1) or least (-1) lengths of a bolt's history, each
// from the parabola through the extreme sample and its neighbours: (time,
// length) of its vertex.
std::vector<std::pair<double, double>> extremes(const std::vector<df::BoltSample>& h, double dt, int sign) {
  std::vector<std::pair<double, double>> out;
  for (std::size_t s = 1; s + 1 < h.size(); ++s) {
    const double a = sign * h[s - 1].length, b = sign * h[s].length, c = sign * h[s + 1].length;
    if (!(b > a && b >= c)) continue;
    const double shift = 0.5 * (a - c) / (a - 2 * b + c);  // in steps
    out.emplace_back(h[s].time + shift * dt, sign * (b - 0.25 * (a - c) * shift));
  }
  return out;
}

// DDA's step damps a spring-mass oscillation by xi = w dt / 4 of critical
// (constant acceleration taken from the end-of-step force: Newmark with
// gamma = 1, beta = 1/2, whose amplification matrix gives w dt / 4 to 2e-6
// at the w dt of these tests): after half a cycle the swing is e^(-pi xi)
// of what it was.
double half_cycle_decay(double w, double dt) { return std::exp(-kPi * w * dt / 4); }

// Settled (initial_equilibrium) before the run: the bolt carries the
// weight at length L0 + (W - P) / k, and the block then stays there.
// The relaxation's static solves keep an inertia term 2m / (10 dt)^2 as a
// regulariser (start_up_relax.hpp), which leaves each solve
// k / (k + 2m / (10 dt)^2) of the way to equilibrium: with a bolt ten
// times stiffer (k = 1e7 N/m, W/k = 2.55 mm) and dt = 0.01 s that is 95 %,
// and the tolerance 1e-9 w0 is met in a few solves. (The k = 1e6 bolt with
// dt = 1 ms gets 2 % a solve and stops 9 mm short after the 50 allowed.)
TEST(Bolts3d, HangingCubeSettlesAtWeightOverStiffness) {
  const double k = 1e7;
  for (const double pretension : {0.0, 0.4 * kWeight, 2 * kWeight}) {
    Model3 m = hanging_cube(0.01);
    m.control.initial_equilibrium = true;
    m.bolts[0].stiffness = k;
    m.bolts[0].pretension = pretension;
    Simulation3 sim(m);
    sim.start();
    EXPECT_TRUE(sim.start_up().stuck_equilibrium) << "P = " << pretension;
    const df::BoltSample start = sim.bolt_histories()[0].front();
    std::printf("P = %.1f N: settled in %d solves at T = %.6f N, L = %.9f m\n", pretension,
                sim.settle_iterations(), start.force, start.length);
    const double extension = (kWeight - pretension) / k;  // negative: the bolt shortens
    EXPECT_NEAR(start.force, kWeight, 1e-6 * kWeight) << "P = " << pretension;
    EXPECT_NEAR(start.length, kRest + extension, 1e-9) << "P = " << pretension;
    run_for(sim, 0.01, 100);
    // At rest in equilibrium: the next 0.1 s move it by round-off only.
    EXPECT_NEAR(sim.bolts()[0].force, kWeight, 1e-6 * kWeight) << "P = " << pretension;
    EXPECT_LT(sim.histories()[0].back().velocity.norm(), 1e-7) << "P = " << pretension;
    EXPECT_EQ(sim.bolt_histories()[0].size(), 101u);
  }
}

// Released from rest at L0: L(t) = L0 + W/k (1 - cos(w t)), w = sqrt(k/m),
// as the step damps it (half_cycle_decay). The period is the time between
// the first two greatest lengths; the centre the mean of the first greatest
// length and of the least lengths before and after it (which cancels the
// damping to O(xi^2)); the first swing reaches W/k (1 + e^(-pi xi)).
TEST(Bolts3d, HangingCubeOscillatesAtSqrtKOverMAboutWeightOverK) {
  const double dt = 2e-4, w = std::sqrt(kStiffness / kMass), period = 2 * kPi / w, stretch = kWeight / kStiffness;
  Simulation3 sim(hanging_cube(dt));
  run_for(sim, dt, static_cast<int>(2.2 * period / dt));
  const auto& h = sim.bolt_histories()[0];
  const auto peaks = extremes(h, dt, +1), troughs = extremes(h, dt, -1);
  ASSERT_GE(peaks.size(), 2u);
  ASSERT_GE(troughs.size(), 1u);
  std::printf("period %.7f s (2 pi sqrt(m/k) = %.7f s), first swing %.7e m\n", peaks[1].first - peaks[0].first,
              period, peaks[0].second - kRest);
  EXPECT_NEAR(peaks[1].first - peaks[0].first, period, 1e-4 * period);
  const double centre = 0.5 * (peaks[0].second + 0.5 * (h[0].length + troughs[0].second));
  EXPECT_NEAR(centre, kRest + stretch, 1e-4 * stretch);
  EXPECT_NEAR(peaks[0].second - kRest, stretch * (1 + half_cycle_decay(w, dt)), 1e-4 * stretch);
  EXPECT_FALSE(sim.bolts()[0].broken);
}

// Breaking force W / 2: reached when W/k (1 - cos w t) = W / 2k, at
// t = T / 6; the bolt breaks at the end of the first step past it, stays
// broken with no force, and from then on the cube falls freely: its centre
// follows z_b + v_b (t - t_b) - g (t - t_b)^2 / 2 from the state at the
// break (exact for the constant-acceleration step).
TEST(Bolts3d, BoltWeakerThanTheWeightBreaksAndTheCubeFallsFreely) {
  const double dt = 1e-3, period = 2 * kPi * std::sqrt(kMass / kStiffness);
  Model3 m = hanging_cube(dt);
  m.bolts[0].breaking_force = 0.5 * kWeight;
  Simulation3 sim(m);
  run_for(sim, dt, 300);
  const auto& h = sim.bolt_histories()[0];
  std::size_t at = 0;
  while (at < h.size() && !h[at].broken) ++at;
  ASSERT_LT(at, h.size());
  const double t_break = h[at].time;
  std::printf("broke at t = %.4f s (T/6 = %.5f s)\n", t_break, period / 6);
  EXPECT_GE(t_break, period / 6 - dt * 1e-6);
  EXPECT_LT(t_break, period / 6 + dt);
  for (std::size_t s = at; s < h.size(); ++s) {
    EXPECT_TRUE(h[s].broken) << s;
    EXPECT_EQ(h[s].force, 0.0) << s;
  }
  // The energy the bar held when it broke, T^2 / 2k with T = k (L - L0) at
  // the break, is booked as breakage.
  const double t_at_break = kStiffness * (h[at].length - kRest);
  EXPECT_GT(t_at_break, 0.5 * kWeight);
  EXPECT_NEAR(sim.energy_log().back().breakage, t_at_break * t_at_break / (2 * kStiffness), 1e-9);
  // The falling cube touches nothing: the ledger's residual stays what the
  // bolt's steps left (free fall is exact), and the bolt holds no energy.
  for (std::size_t s = at; s < sim.energy_log().size(); ++s) {
    EXPECT_NEAR(sim.energy_log()[s].residual, sim.energy_log()[at].residual, 1e-9 * kWeight) << s;
    EXPECT_EQ(sim.energy_log()[s].bolts, 0.0) << s;
  }
  const MeasurementSample3& b = sim.histories()[0][at];
  const MeasurementSample3& last = sim.histories()[0].back();
  const double t = last.time - b.time;
  EXPECT_NEAR(last.position.z(), b.position.z() + b.velocity.z() * t - 0.5 * kG * t * t, 1e-9);
  EXPECT_NEAR(last.velocity.z(), b.velocity.z() - kG * t, 1e-9);
}

// Two free cubes 2 m apart in zero gravity joined by a bolt with
// pretension P between their centres: they oscillate against each other
// with the reduced mass m/2, T = 2 pi sqrt(m / 2k), the length swinging
// from L0 down to L0 - 2P/k at T/2 (less the step's damping,
// half_cycle_decay); their momentum stays zero. Through
// K's coupling of the two blocks, with CHOLMOD and with PCG (whose product
// takes the bolt's coupling separately).
TEST(Bolts3d, PretensionedBoltBetweenTwoFreeCubesSwingsWithTheReducedMass) {
  const double dt = 2e-4, pretension = 1e4, w = std::sqrt(2 * kStiffness / kMass), period = 2 * kPi / w;
  for (const char* solver : {"cholmod", "pcg"}) {
    Model3 m = hanging_cube(dt);
    m.fixed = {false, false};
    m.gravity = {0, 0, 0};
    m.control.solver = solver;
    m.bolts[0].pretension = pretension;
    Simulation3 sim(m);
    run_for(sim, dt, static_cast<int>(0.75 * period / dt));
    const auto least = extremes(sim.bolt_histories()[0], dt, -1);
    ASSERT_EQ(least.size(), 1u) << solver;
    const double swing = pretension / kStiffness * (1 + half_cycle_decay(w, dt));
    EXPECT_NEAR(least[0].second, kRest - swing, 1e-4 * swing) << solver;
    EXPECT_NEAR(least[0].first, period / 2, dt) << solver;
    const Vector12d v0 = sim.velocities()[0], v1 = sim.velocities()[1];
    EXPECT_LT((v0.head<3>() + v1.head<3>()).norm(), 1e-9) << solver;  // equal masses: momentum m (v0 + v1)
  }
}

// The ledger: stored energy (kinetic + bolt T^2/2k) changes by the work of
// gravity less what the implicit step dissipates, k/2 dL^2 in each step
// (dL from the bolt's length history): the residual is that sum and no
// more; it never goes negative (no energy made).
TEST(Bolts3d, LedgerBooksTheBoltsEnergy) {
  const double dt = 1e-3;
  Simulation3 sim(hanging_cube(dt));
  run_for(sim, dt, 400);
  const auto& h = sim.bolt_histories()[0];
  const auto& e = sim.energy_log();
  double dissipated = 0;
  for (std::size_t s = 1; s < h.size(); ++s) {
    const double dl = h[s].length - h[s - 1].length;
    dissipated += 0.5 * kStiffness * dl * dl;
    EXPECT_NEAR(e[s].residual, dissipated, 1e-9 * kWeight) << "step " << s;
  }
  std::printf("residual %.6f J = the steps' k dL^2/2 %.6f J, of %.3f J of gravity's work\n", e.back().residual,
              dissipated, e.back().gravity_work);
  const df::BoltSample& last = h.back();
  EXPECT_NEAR(e.back().bolts, last.force * last.force / (2 * kStiffness), 1e-9);
  EXPECT_GT(dissipated, 0.0);
}

// The roof moved by the ground (an earthquake in displacement mode, a
// constant 2 m/s^2 upward from t = 0, no gravity) drags the cube by the
// bolt: relative to the roof the cube feels -m a, so the bolt stretches to
// m a / k (1 - cos w t), its first greatest length m a / k (1 + e^(-pi xi))
// at T/2 (half_cycle_decay). The ground's work on the bolt is booked with
// the loads (T at the end of the step times the stretch its increment
// makes), so the residual is again the steps' k/2 dL^2 and nothing else.
TEST(Bolts3d, GroundMovingTheFixedEndDragsTheCubeAndItsWorkIsBooked) {
  const double dt = 2e-4, a = 2, w = std::sqrt(kStiffness / kMass), period = 2 * kPi / w;
  Model3 m = hanging_cube(dt);
  m.gravity = {0, 0, 0};
  m.earthquake = {std::make_shared<GroundMotion3>(std::vector<double>{0, 1}, std::vector<Vec3>{{0, 0, a}, {0, 0, a}}),
                  &df::ground_motion_mode("displacement")};
  Simulation3 sim(m);
  run_for(sim, dt, static_cast<int>(0.75 * period / dt));
  const auto& h = sim.bolt_histories()[0];
  const auto peaks = extremes(h, dt, +1);
  ASSERT_EQ(peaks.size(), 1u);
  const double swing = kMass * a / kStiffness * (1 + half_cycle_decay(w, dt));
  EXPECT_NEAR(peaks[0].second - kRest, swing, 1e-4 * swing);
  EXPECT_NEAR(peaks[0].first, period / 2, dt);
  const auto& e = sim.energy_log();
  double dissipated = 0;
  for (std::size_t s = 1; s < h.size(); ++s) {
    const double dl = h[s].length - h[s - 1].length;
    dissipated += 0.5 * kStiffness * dl * dl;
  }
  std::printf("ground's work %.6f J, residual %.9f J = the steps' k dL^2/2 %.9f J\n", e.back().load_work,
              e.back().residual, dissipated);
  EXPECT_GT(e.back().load_work, 0.0);
  EXPECT_NEAR(e.back().residual, dissipated, 1e-9 * e.back().load_work);
}

// Resumed from a checkpoint (state / restore, and through the results
// file) before the bolt breaks, the run breaks it in the same step and ends
// bit for bit where the uninterrupted run ends.
TEST(Bolts3d, ResumedRunIsBitIdentical) {
  const double dt = 1e-3;
  Model3 m = hanging_cube(dt);
  m.bolts[0].breaking_force = 0.5 * kWeight;
  m.control.steps = 120;
  Simulation3 whole(m);
  whole.run();

  Simulation3 first(m);
  for (int s = 0; s < 30; ++s) first.advance();
  ASSERT_FALSE(first.bolts()[0].broken);
  Simulation3 second(m);
  second.restore(first.state());
  second.run();
  EXPECT_EQ(second.blocks()[1].vertices, whole.blocks()[1].vertices);
  EXPECT_EQ(second.velocities()[1], whole.velocities()[1]);
  ASSERT_EQ(second.bolt_histories()[0].size(), whole.bolt_histories()[0].size());
  for (std::size_t s = 0; s < whole.bolt_histories()[0].size(); ++s) {
    EXPECT_EQ(second.bolt_histories()[0][s].length, whole.bolt_histories()[0][s].length) << s;
    EXPECT_EQ(second.bolt_histories()[0][s].broken, whole.bolt_histories()[0][s].broken) << s;
  }
  EXPECT_EQ(second.energy_log().back().residual, whole.energy_log().back().residual);
  EXPECT_EQ(second.energy_log().back().breakage, whole.energy_log().back().breakage);

  // Through the results file, as `dda df --stop-at-step` and `--resume`.
  PolyhedronModel blocks;
  blocks.blocks = m.blocks;
  Results3 r;
  r.blocks = blocks;
  r.source.blocks_path = "blocks3d.h5";
  r.output.every = 10;
  const std::string path = (fs::temp_directory_path() / "dda_bolts3d_resume.h5").string();
  {
    Simulation3 a(m);
    RunControl3 rc;
    rc.stop_at_step = 30;
    ASSERT_EQ(run_recorded(a, r, path, rc), df::RunEnd::Stopped);
  }
  Results3 saved = read_results3_h5(path);
  ASSERT_EQ(saved.bolt_names, std::vector<std::string>{"b1"});
  ASSERT_EQ(saved.bolt_histories[0].size(), 31u);
  Simulation3 b(m);
  b.restore(*saved.checkpoint);
  Results3 rb = r;
  rb.frames = saved.frames;
  ASSERT_EQ(run_recorded(b, rb, path, RunControl3{}), df::RunEnd::Finished);
  EXPECT_EQ(b.blocks()[1].vertices, whole.blocks()[1].vertices);
  const Results3 done = read_results3_h5(path);
  ASSERT_EQ(done.bolt_histories[0].size(), whole.bolt_histories()[0].size());
  for (std::size_t s = 0; s < done.bolt_histories[0].size(); ++s) {
    EXPECT_EQ(done.bolt_histories[0][s].force, whole.bolt_histories()[0][s].force) << s;
    EXPECT_EQ(done.bolt_histories[0][s].broken, whole.bolt_histories()[0][s].broken) << s;
  }
  fs::remove(path);
}

TEST(Bolts3d, BadBoltsAreInputErrors) {
  auto refused = [](void (*spoil)(Model3&)) {
    Model3 m = hanging_cube(1e-3);
    spoil(m);
    try {
      Simulation3 sim(m);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(refused([](Model3& m) { m.bolts[0].stiffness = 0; }).find("Bolt 'b1' has a stiffness"), std::string::npos);
  EXPECT_NE(refused([](Model3& m) { m.bolts[0].head_block = 0; }).find("both ends in block 0"), std::string::npos);
  EXPECT_NE(refused([](Model3& m) { m.bolts[0].head_block = 7; }).find("block 7 does not exist"), std::string::npos);
  EXPECT_NE(refused([](Model3& m) { m.fixed = {true, true}; }).find("joins two fixed blocks"), std::string::npos);
  EXPECT_NE(refused([](Model3& m) { m.bolts[0].pretension = -1; }).find("negative pretension"), std::string::npos);
}

}  // namespace
}  // namespace dda::df3
