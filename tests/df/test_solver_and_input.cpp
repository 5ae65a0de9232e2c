// The step solver (CHOLMOD against Eigen's LDL^T on the same block system,
// pattern reuse) and the InputError sentences of build_model.
#include <gtest/gtest.h>

#include <random>

#include "df_test_models.hpp"
#include "dda/common/error.hpp"
#include "dda/df/core/block_system.hpp"
#include "dda/df/core/linear_solver.hpp"
#include "dda/df/2d/simulation.hpp"

namespace dda::df {
namespace {

// A chain of n blocks: SPD diagonal blocks plus random couplings, made
// diagonally dominant so the system is positive definite.
BlockSystem random_chain(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  BlockSystem sys(n);
  for (int i = 0; i < n; ++i) {
    Matrix6d a;
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 6; ++c) a(r, c) = u(rng);
    sys.diagonal(i) += a * a.transpose() + 30 * Matrix6d::Identity();
    for (int r = 0; r < 6; ++r) sys.rhs(i)[r] = u(rng);
  }
  for (int i = 1; i < n; ++i) {
    Matrix6d k;
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 6; ++c) k(r, c) = u(rng);
    sys.add_coupling(i, i - 1, k);
    if (i > 2) sys.add_coupling(i - 3, i, 0.5 * k);
  }
  return sys;
}

TEST(LinearSolver, CholmodMatchesEigenAndResidualIsSmall) {
  const BlockSystem sys = random_chain(40, 3);
  const auto cholmod = make_cholmod_solver();
  const auto eigen = make_eigen_solver();
  const Eigen::VectorXd x = cholmod->solve(sys.lower(), sys.rhs());
  const Eigen::VectorXd y = eigen->solve(sys.lower(), sys.rhs());
  EXPECT_LE((x - y).norm(), 1e-12 * y.norm());
  EXPECT_LE((sys.full() * x - sys.rhs()).norm(), 1e-12 * sys.rhs().norm());
}

TEST(LinearSolver, CholmodReusesAnalysisWhilePatternHolds) {
  const auto solver = make_cholmod_solver();
  BlockSystem a = random_chain(10, 1), b = random_chain(10, 2), c = random_chain(11, 1);
  solver->solve(a.lower(), a.rhs());
  solver->solve(b.lower(), b.rhs());  // same pattern, new numbers
  EXPECT_EQ(solver->analyses(), 1);
  solver->solve(c.lower(), c.rhs());  // new pattern
  EXPECT_EQ(solver->analyses(), 2);
}

TEST(LinearSolver, NotPositiveDefiniteIsAnInternalError) {
  BlockSystem sys(1);
  sys.diagonal(0) = -Matrix6d::Identity();
  EXPECT_THROW(make_cholmod_solver()->solve(sys.lower(), sys.rhs()), InternalError);
}

ModelInput valid_input() {
  ModelInput in;
  in.geometry.blocks.push_back(test::make_block(test::rectangle(0, 0, 1, 1)));
  in.materials = {test::rock()};
  in.control.dt = 0.01;
  return in;
}

// build_model(in) must throw an InputError whose sentence contains `words`.
void expect_input_error(const ModelInput& in, const std::string& words) {
  try {
    build_model(in);
    ADD_FAILURE() << "no InputError; expected one mentioning '" << words << "'";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(ModelInput, ValidInputBuildsWithDefaults) {
  const Model m = build_model(valid_input());
  EXPECT_DOUBLE_EQ(*m.control.w0, 0.5);                 // half the model height
  EXPECT_DOUBLE_EQ(m.joint_pn.back(), 50 * 1e9);        // 50 E
  EXPECT_DOUBLE_EQ(m.joint_ps.back(), m.joint_pn.back());
  EXPECT_DOUBLE_EQ(m.search_distance, 2.5 * 0.01 * 0.5);
}

TEST(ModelInput, BadInputGivesOneSentence) {
  ModelInput in = valid_input();
  in.materials[0].density = 0;
  expect_input_error(in, "non-positive density");

  in = valid_input();
  in.control.dt = -1;
  expect_input_error(in, "time step dt must be positive, or 0 to take it from the model");

  in = valid_input();
  in.measurements.push_back({"m1", {5, 5}, -1});
  expect_input_error(in, "lies outside every block");

  in = valid_input();
  in.fixed_points.push_back({"f1", {0.5, 0.5}, 3, {}});
  expect_input_error(in, "refers to block 3");

  in = valid_input();
  in.control.dynamic = 1.5;
  expect_input_error(in, "dynamic parameter k");

  in = valid_input();
  in.default_joint.friction_law = "magic";
  expect_input_error(in, "Unknown friction law 'magic'");

  in = valid_input();
  in.geometry.blocks[0].vertices = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};  // clockwise
  expect_input_error(in, "not counter-clockwise");

  in = valid_input();
  in.materials[0].poisson = 0.5;
  expect_input_error(in, "Poisson's ratio");

  in = valid_input();
  in.joint_sets.push_back({});
  in.joint_sets[0].friction_deg = -5;
  expect_input_error(in, "friction angle");
}

TEST(ModelInput, PointsFromBlockModelNeedLoadForces) {
  ModelInput in = valid_input();
  in.geometry.points.push_back({{"push", PointKind::Load, {0.5, 0.5}}, 0});
  in.geometry.points.push_back({{"probe", PointKind::Measurement, {0.2, 0.2}}, 0});
  EXPECT_THROW(add_points_from_block_model(in.geometry, {}, in), InputError);
  ModelInput ok = valid_input();
  add_points_from_block_model(in.geometry, {{"push", Vec2(1, 0)}}, ok);
  ASSERT_EQ(ok.loads.size(), 1u);
  EXPECT_EQ(ok.measurements.size(), 1u);
  EXPECT_NO_THROW(build_model(ok));
}

}  // namespace
}  // namespace dda::df
