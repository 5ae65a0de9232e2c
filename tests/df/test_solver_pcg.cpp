// The PCG step solver against CHOLMOD, the automatic choice, the fallback,
// CHOLMOD's analysis reuse over a run, and the declared-pattern block system.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "df_test_models.hpp"
#include "forced_threads.hpp"
#include "random_block_system.hpp"
#include "dda/common/error.hpp"
#include "dda/df/core/block_system.hpp"
#include "dda/df/core/linear_solver.hpp"
#include "dda/df/2d/simulation.hpp"

namespace dda::df {
namespace {

using test::brick_wall;

// Solves every step system with CHOLMOD (its answer drives the run) and
// with PCG, and records how far apart they are.
class ComparingSolver final : public LinearSolver {
 public:
  std::string name() const override { return "compare"; }
  int analyses() const override { return direct_->analyses(); }
  Eigen::VectorXd solve(const Eigen::SparseMatrix<double>& lower, const Eigen::VectorXd& b) override {
    return direct_->solve(lower, b);
  }
  Eigen::VectorXd solve_step(const BlockSystem& sys, double dt) override {
    const Eigen::VectorXd x = direct_->solve_step(sys, dt);
    const Eigen::VectorXd y = pcg_->solve_step(sys, dt);
    if (x.norm() > 0) worst = std::max(worst, (x - y).norm() / x.norm());
    ++compared;
    return x;
  }
  double worst = 0;
  int compared = 0;
  std::unique_ptr<LinearSolver> direct_ = make_cholmod_solver(), pcg_ = make_pcg_solver();
};

TEST(SolverPcg, AgreesWithCholmodOnAssembledContactSystems) {
  auto compare = std::make_unique<ComparingSolver>();
  ComparingSolver* c = compare.get();
  Simulation sim(build_model(brick_wall(6, 8)), std::move(compare));
  for (int s = 0; s < 20; ++s) sim.step();
  EXPECT_GT(sim.contacts().size(), 150u);
  EXPECT_GE(c->compared, 20);
  EXPECT_LE(c->worst, 1e-8);
  const SolverStats st = c->pcg_->stats();
  EXPECT_EQ(st.fallbacks, 0);
  std::printf("PCG vs CHOLMOD: %d systems, worst relative difference %.2e, %.1f PCG iterations per solve\n",
              c->compared, c->worst, static_cast<double>(st.pcg_iterations) / st.pcg_solves);
}

TEST(SolverPcg, GenericPathMatchesCholmod) {
  // A chain of random SPD 6x6 blocks through the CSC interface.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  const int n = 30;
  BlockSystem sys(n);
  for (int i = 0; i < n; ++i) {
    Matrix6d a = Matrix6d::NullaryExpr([&] { return u(rng); });
    sys.diagonal(i) += a * a.transpose() + 30 * Matrix6d::Identity();
    for (int r = 0; r < 6; ++r) sys.rhs(i)[r] = u(rng);
    if (i > 0) sys.add_coupling(i, i - 1, Matrix6d::NullaryExpr([&] { return u(rng); }));
  }
  const Eigen::VectorXd x = make_cholmod_solver()->solve(sys.lower(), sys.rhs());
  const auto pcg = make_pcg_solver();
  const Eigen::VectorXd y = pcg->solve(sys.lower(), sys.rhs());
  EXPECT_LE((x - y).norm(), 1e-9 * x.norm());
  EXPECT_EQ(pcg->stats().pcg_solves, 1);
}

TEST(SolverPcg, FallsBackToCholmodWhenItDoesNotConverge) {
  ModelInput in = brick_wall(3, 4);
  PcgOptions o;  // never converges (short of an exact zero residual), trial solves neither
  o.tolerance = 0;
  o.trial_tolerance = 0;
  o.max_iterations = 1;
  Simulation sim(build_model(in), make_pcg_solver(o));
  Simulation ref(build_model(in), make_cholmod_solver());
  for (int s = 0; s < 3; ++s) {
    sim.step();
    ref.step();
  }
  const SolverStats st = sim.solver().stats();
  EXPECT_GT(st.fallbacks, 0);
  EXPECT_EQ(st.fallbacks, st.factorizations);
  for (int i = 0; i < sim.model().block_count(); ++i)
    EXPECT_EQ(sim.blocks()[i].geometry.centroid, ref.blocks()[i].geometry.centroid);
}

TEST(SolverPcg, AutoChoosesBySizeAndTheUserCanForceEither) {
  EXPECT_EQ(Simulation(build_model(brick_wall(2, 2))).solver().name(), "auto");
  EXPECT_EQ(Simulation(build_model(brick_wall(2, 2, "pcg"))).solver().name(), "pcg");
  EXPECT_EQ(Simulation(build_model(brick_wall(2, 2, "cholmod"))).solver().name(), "cholmod");
  EXPECT_THROW(make_solver("lu"), InputError);

  // 13 blocks: CHOLMOD below a threshold of 14, PCG from 13.
  for (const int threshold : {14, 13}) {
    Simulation sim(build_model(brick_wall(3, 4)), make_solver("auto", threshold));
    sim.step();
    const SolverStats st = sim.solver().stats();
    EXPECT_EQ(st.pcg_solves > 0, threshold == 13);
    EXPECT_EQ(st.factorizations > 0, threshold == 14);
  }
}

TEST(SolverPcg, WarmStartCutsIterations) {
  // The second and later steps start from a warm start (the motion the last
  // step predicts; FirstSolveStartsFromThePredictedMotion below).
  // Switched on under gravity, so that the first step is a cold start (the
  // start-up relaxation would have solved the wall before it).
  ModelInput in = brick_wall(4, 6, "pcg");
  in.control.initial_equilibrium = false;
  Simulation sim(build_model(std::move(in)));
  sim.step();
  const SolverStats first = sim.solver().stats();
  for (int s = 0; s < 5; ++s) sim.step();
  const SolverStats later = sim.solver().stats();
  const double per_solve_first = static_cast<double>(first.pcg_iterations) / first.pcg_solves;
  const double per_solve_later = static_cast<double>(later.pcg_iterations - first.pcg_iterations) /
                                 (later.pcg_solves - first.pcg_solves);
  std::printf("PCG iterations per solve: first step %.1f, later %.1f\n", per_solve_first, per_solve_later);
  EXPECT_LT(per_solve_later, per_solve_first);
  EXPECT_EQ(later.fallbacks, 0);
}

TEST(SolverPcg, FirstSolveStartsFromThePredictedMotion) {
  // Two blocks falling apart, one thrown sideways: a DDA step is exact for
  // constant acceleration (V8), d = v dt + g dt^2 / 2, and that is where
  // every step's first solve starts (Simulation::predicted_step), so from the
  // second step on PCG has nothing left to do. Starting from the last
  // solution scaled to dt, as before, left g dt^2 to find in every step.
  ModelInput in;
  in.geometry.blocks.push_back(test::make_block(test::rectangle(0, 0, 1, 1)));
  in.geometry.blocks.push_back(test::make_block(test::rectangle(5, 0, 6, 1)));
  in.materials = {test::rock()};
  in.control.dt = 0.01;
  in.control.solver = "pcg";
  Vector6d thrown = Vector6d::Zero();
  thrown << 2, 1, 0, 0, 0, 0;
  in.initial_velocity = {Vector6d::Zero(), thrown};
  Simulation sim(build_model(in));
  sim.step();
  const SolverStats first = sim.solver().stats();
  EXPECT_GT(first.pcg_iterations, 0);  // from rest, the first step has to find g dt^2 / 2
  for (int s = 0; s < 10; ++s) sim.step();
  const SolverStats later = sim.solver().stats();
  EXPECT_GE(later.pcg_solves - first.pcg_solves, 10);  // at least one a step
  EXPECT_EQ(later.pcg_iterations, first.pcg_iterations);
}

TEST(SolverPcg, QuietStepsSettleOnOneFullSolve) {
  // A wall settling on its base: once a step's first solve changes no
  // contact state, the next step makes its first solve a full one
  // (Simulation::quiet_step) and settles on it, one solve a step instead
  // of a trial and its repeat. The steps stay full solves: the wall's top
  // follows CHOLMOD's run step by step as closely as PCG's tolerance lets it.
  ModelInput pcg_wall = brick_wall(4, 6, "pcg"), direct_wall = brick_wall(4, 6, "cholmod");
  for (ModelInput* in : {&pcg_wall, &direct_wall}) {
    in->control.dynamic = 0.9;
    in->control.max_open_close = 30;  // no step is cut: both runs take the same 200 steps
    in->measurements.push_back({"top", Vec2(3.25, 1.75), -1});
  }
  Simulation pcg(build_model(pcg_wall)), direct(build_model(direct_wall));
  pcg.run_until(0.2);
  direct.run_until(0.2);
  ASSERT_EQ(pcg.log().size(), 200u);
  ASSERT_EQ(direct.log().size(), 200u);
  int one_solve = 0;
  for (const StepRecord& r : pcg.log()) one_solve += r.open_close_iterations == 1;
  // The wall comes to rest within the first 70 steps (the states of its
  // contacts settle); every later step is quiet.
  EXPECT_GE(one_solve, 130);
  const std::vector<MeasurementSample>&a = pcg.histories()[0], &b = direct.histories()[0];
  ASSERT_EQ(a.size(), b.size());
  double worst = 0, largest = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    worst = std::max(worst, (a[k].displacement - b[k].displacement).norm());
    largest = std::max(largest, b[k].displacement.norm());
  }
  std::printf("%d of 200 steps on one solve; top: largest displacement %.3e m, PCG - CHOLMOD %.1e m\n", one_solve,
              largest, worst);
  // PCG stops at 1e-10 of the step's forces (gravity, inertia), which at
  // rest move the wall by little: its run is 4.7e-11 m (3e-6 of the top's
  // settlement) off CHOLMOD's, the same with or without the quiet steps.
  EXPECT_GT(largest, 1e-6);
  EXPECT_LE(worst, 1e-5 * largest);
}

TEST(SolverCholmod, AnalysisIsReusedOverARun) {
  Simulation sim(build_model(brick_wall(5, 6, "cholmod")));
  for (int s = 0; s < 30; ++s) sim.step();
  const SolverStats st = sim.solver().stats();
  std::printf("CHOLMOD over 30 steps: %ld analyses, %ld factorisations, ordering %s\n", st.analyses,
              st.factorizations, st.ordering.c_str());
  EXPECT_GE(st.factorizations, 30);
  EXPECT_LE(st.analyses * 5, st.factorizations);
  EXPECT_FALSE(st.ordering.empty());
}

TEST(BlockSystemPattern, CouplingsOutsideThePatternAndProductsAgree) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  auto random6 = [&] { return Matrix6d(Matrix6d::NullaryExpr([&] { return u(rng); })); };
  BlockSystem sys;
  sys.reset(5, {{0, 1}, {3, 1}, {1, 0}});
  for (int i = 0; i < 5; ++i) {
    const Matrix6d a = random6();
    sys.diagonal(i) += a * a.transpose() + 10 * Matrix6d::Identity();
  }
  const Matrix6d k01 = random6(), k31 = random6(), k42 = random6();
  sys.scatter([&](int k) {
    if (k == 0) sys.add_coupling(0, 1, k01);
    if (k == 1) sys.add_coupling(3, 1, k31);
  });
  sys.add_coupling(2, 4, k42.transpose());  // not declared
  const Eigen::MatrixXd full = Eigen::MatrixXd(sys.full());
  EXPECT_TRUE((full.block<6, 6>(0, 6).isApprox(k01)));
  EXPECT_TRUE((full.block<6, 6>(18, 6).isApprox(k31)));
  EXPECT_TRUE((full.block<6, 6>(24, 12).isApprox(k42)));
  EXPECT_TRUE((full.block<6, 6>(12, 24).isApprox(k42.transpose())));
  const Eigen::VectorXd x = Eigen::VectorXd::NullaryExpr(30, [&] { return u(rng); });
  Eigen::VectorXd y;
  sys.multiply(x, y);
  EXPECT_LE((y - full * x).norm(), 1e-12 * y.norm());
  // The undeclared pair stays in the pattern of the next reset.
  const std::uint64_t id = sys.pattern_id();
  sys.reset(5, {{0, 1}, {3, 1}, {1, 0}});
  EXPECT_EQ(sys.pattern_id(), id);
  EXPECT_EQ(sys.csc().nonZeros(), 5 * 21 + 3 * 36);
}

// The product by block-column sweeps (each stored coupling block read once
// for both of its rows): equal to the full matrix's product, and the same
// to the bit however the rows are shared out among sweeps (one range, two,
// seven of uneven length, or 57), which is what makes the PCG iterates
// independent of the thread count. Each chunk of rows is reported once,
// in order, when it is final: its rows equal the finished product then.
TEST(BlockSystemSweep, ProductIsTheSameToTheBitForAnySharingOfTheRows) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  const int nb = 300;
  // Beds of 23 blocks, and 40 pairs far apart.
  const BlockSystem sys = test::random_layered_system(nb, rng, {.bed = 23, .far_pairs = 40, .diagonal_shift = 10});
  const Eigen::VectorXd x = Eigen::VectorXd::NullaryExpr(6 * nb, [&] { return u(rng); });
  const Eigen::MatrixXd full = Eigen::MatrixXd(sys.full());
  const Eigen::VectorXd expected = full * x;
  Eigen::VectorXd whole;
  sys.multiply(x, whole);
  EXPECT_LE((whole - expected).norm(), 1e-13 * expected.norm());
  for (const std::vector<int>& cuts : std::vector<std::vector<int>>{
           {0, nb}, {0, 150, nb}, {0, 1, 40, 41, 100, 299, nb}, {}}) {
    std::vector<int> bounds = cuts;
    if (bounds.empty())
      for (int b = 0; b <= nb; b += 5) bounds.push_back(std::min(b, nb));  // 60 ranges of 5 rows
    Eigen::VectorXd y = Eigen::VectorXd::Constant(6 * nb, std::numeric_limits<double>::quiet_NaN());
    // Later ranges first: a range's sweep must not depend on another's having run.
    for (int r = static_cast<int>(bounds.size()) - 2; r >= 0; --r) {
      const int first = bounds[r], last = bounds[r + 1];
      int next = first;
      sys.multiply_sweep(x, y, nullptr, first, last, 7, [&](int lo, int hi) {
        EXPECT_EQ(lo, next);
        EXPECT_TRUE(hi - lo == 7 || hi == last);
        for (int i = lo; i < hi; ++i)
          EXPECT_EQ(y.segment<6>(6 * i), whole.segment<6>(6 * i)) << "row " << i << " reported before it was final";
        next = hi;
      });
      EXPECT_EQ(next, last);
    }
    int differ = 0;
    for (int k = 0; k < 6 * nb; ++k) differ += !(y[k] == whole[k]);
    EXPECT_EQ(differ, 0) << bounds.size() - 1 << " ranges";
  }
}

// scatter(f, only) calls f for the flagged items alone, and each block sees
// them in the order the full scatter gives it (which makes the assembly
// independent of the thread count): checked on the parallel paths (two
// threads, grain 1) and the serial ones, on items that straddle the ranges
// of blocks as well as items within one.
TEST(BlockSystemScatter, FlaggedItemsInTheOrderOfTheFullScatter) {
  std::mt19937 rng(11);
  const int nb = 400;
  std::uniform_int_distribution<int> block(0, nb - 1), near(-3, 3);
  std::vector<std::pair<int, int>> items;
  for (int k = 0; k < 3000; ++k) {
    const int a = block(rng);
    const int b = k % 5 == 0 ? block(rng) : std::clamp(a + near(rng), 0, nb - 1);  // some far apart
    items.emplace_back(a, b);
  }
  std::vector<std::uint8_t> only(items.size());
  for (auto& f : only) f = rng() % 3 == 0;
  for (const int threads : {2, 1}) {
    const testing::ForcedThreads forced(threads);
    BlockSystem sys;
    sys.reset(nb, items);
    auto visits = [&](const std::vector<std::uint8_t>* flags) {
      std::vector<std::vector<int>> seen(nb);  // per block, the items in the order f met them
      sys.scatter(
          [&](int k) {
            seen[items[k].first].push_back(k);
            if (items[k].second != items[k].first) seen[items[k].second].push_back(k);
          },
          flags);
      return seen;
    };
    const auto all = visits(nullptr), flagged = visits(&only);
    std::size_t calls = 0, expected_calls = 0;
    for (int i = 0; i < nb; ++i) {
      std::vector<int> kept;
      for (const int k : all[i])
        if (only[k]) kept.push_back(k);
      EXPECT_EQ(flagged[i], kept) << "block " << i << ", " << threads << " threads";
      calls += flagged[i].size();
      expected_calls += kept.size();
    }
    EXPECT_EQ(calls, expected_calls);
    EXPECT_GT(sys.rounds(), 1);  // the straddling items ran in rounds
  }
  // Serially as well (a grain above the item count).
  const int saved = parallel_grain();
  set_parallel_grain(100000);
  BlockSystem sys;
  sys.reset(nb, items);
  int called = 0, flagged = 0;
  sys.scatter([&](int k) { called += only[k] ? 1 : 1000; }, &only);
  for (const auto f : only) flagged += f;
  set_parallel_grain(saved);
  EXPECT_EQ(called, flagged);
}

// V1 (docs/validation.md) at phi = 20 with the solver forced to PCG: the same 1 % as
// with CHOLMOD (see test_v1_sliding.cpp for the model).
TEST(SolverPcg, V1SlidingWithinOnePercent) {
  const double alpha = deg2rad(30.0), phi = 20.0;
  ModelInput in;
  in.geometry.blocks.push_back(test::make_block(test::rotated(test::rectangle(0, -1, 8, 1), alpha)));
  in.geometry.blocks.push_back(test::make_block(test::rotated(test::rectangle(6, 0, 1, 1), alpha)));
  in.materials = {test::rock(2000, 5e10)};
  JointProperties j;
  j.friction_deg = phi;
  in.joint_sets = {j};
  in.control.dt = 1e-3;
  in.control.solver = "pcg";
  for (const double x : {0.5, 4.0, 7.5}) in.fixed_points.push_back({"base", test::rotated(Vec2(x, -0.5), alpha), 0, {}});
  in.measurements.push_back({"slider", test::rotated(Vec2(6.5, 0.5), alpha), 1});
  Simulation sim(build_model(in));
  sim.run_until(1.0);
  const double s = sim.histories()[0].back().displacement.norm();
  const double expected = 0.5 * 9.81 * (std::sin(alpha) - std::cos(alpha) * std::tan(deg2rad(phi)));
  const SolverStats st = sim.solver().stats();
  std::printf("V1 phi=20 PCG: s=%.6f expected=%.6f rel.err=%.2e, %ld PCG solves, %.1f iterations each\n", s,
              expected, std::abs(s - expected) / expected, st.pcg_solves,
              static_cast<double>(st.pcg_iterations) / st.pcg_solves);
  EXPECT_LE(std::abs(s - expected) / expected, 0.01);
  EXPECT_GT(st.pcg_solves, 900);
  EXPECT_EQ(st.fallbacks, 0);
}

}  // namespace
}  // namespace dda::df
