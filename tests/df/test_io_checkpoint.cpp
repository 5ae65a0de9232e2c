// Checkpoints: a run of 2N steps against N steps, a results file, a fresh
// Simulation restored from it and N more steps. Everything a run records
// must agree to 1e-12 (in practice bit for bit).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <unistd.h>

#include "dda/common/error.hpp"
#include "dda/df/io/results.hpp"
#include "df_io_test_models.hpp"
#include "df_test_models.hpp"

namespace dda::df {
namespace {

namespace fs = std::filesystem;

// A block on a 30-degree plane (the plane held by fixed points), a second
// block resting on it pushed by a ramped load, a bolt between the slider
// and the plane, and a measurement point in each moving block.
ModelInput sliding_model(const std::string& solver) {
  const double a = deg2rad(30);
  ModelInput in;
  in.geometry.blocks.push_back(test::make_block(test::rotated(test::rectangle(0, -1, 8, 1), a), 0));
  in.geometry.blocks.push_back(test::make_block(test::rotated(test::rectangle(6, 0, 1, 1), a), 0));
  in.geometry.blocks.push_back(test::make_block(test::rotated(test::rectangle(2, 0, 1, 0.5), a), 0));
  in.geometry.sets = {{"J", "user"}};
  in.materials = {test::rock(2000, 5e10)};
  JointProperties j;
  j.friction_deg = 20;
  in.joint_sets = {j};
  in.control.dt = 1e-3;
  in.control.steps = 60;
  in.control.solver = solver;
  for (const double x : {0.5, 4.0, 7.5}) in.fixed_points.push_back({"base", test::rotated(Vec2(x, -0.5), a), 0, {}});
  PointLoad push{"push", test::rotated(Vec2(2.5, 0.25), a), Vec2(0, 0), 2, std::nullopt};
  push.history = TimeHistory{{0, 0.05}, {Vec2(0, 0), Vec2(2e4, 0)}};
  in.loads.push_back(push);
  Bolt bolt;
  bolt.name = "b";
  bolt.anchor = test::rotated(Vec2(6.5, -0.5), a);
  bolt.head = test::rotated(Vec2(6.5, 0.5), a);
  bolt.stiffness = 1e6;
  in.bolts.push_back(bolt);
  in.measurements.push_back({"slider", test::rotated(Vec2(6.5, 0.5), a), 1});
  in.measurements.push_back({"pushed", test::rotated(Vec2(2.5, 0.25), a), 2});
  return in;
}

void expect_same(const Results& a, const Results& b) {
  ASSERT_EQ(a.log.size(), b.log.size());
  for (std::size_t i = 0; i < a.log.size(); ++i) {
    EXPECT_EQ(a.log[i].step, b.log[i].step);
    EXPECT_NEAR(a.log[i].time, b.log[i].time, 1e-12);
    EXPECT_NEAR(a.log[i].dt, b.log[i].dt, 1e-12);
    EXPECT_EQ(a.log[i].open_close_iterations, b.log[i].open_close_iterations);
    EXPECT_EQ(a.log[i].sliding, b.log[i].sliding);
    EXPECT_EQ(a.log[i].locked, b.log[i].locked);
    EXPECT_NEAR(a.log[i].kinetic_energy, b.log[i].kinetic_energy, 1e-12 * (1 + std::abs(a.log[i].kinetic_energy)));
  }
  ASSERT_EQ(a.histories.size(), b.histories.size());
  for (std::size_t p = 0; p < a.histories.size(); ++p) {
    ASSERT_EQ(a.histories[p].size(), b.histories[p].size());
    for (std::size_t s = 0; s < a.histories[p].size(); ++s) {
      const MeasurementSample &x = a.histories[p][s], &y = b.histories[p][s];
      EXPECT_NEAR((x.displacement - y.displacement).norm(), 0, 1e-12) << "point " << p << " sample " << s;
      EXPECT_NEAR((x.velocity - y.velocity).norm(), 0, 1e-12);
      EXPECT_NEAR((x.stress - y.stress).norm(), 0, 1e-12 * (1 + x.stress.norm()));
    }
  }
  ASSERT_EQ(a.energy.size(), b.energy.size());
  for (std::size_t i = 0; i < a.energy.size(); ++i) {
    EXPECT_NEAR(a.energy[i].residual, b.energy[i].residual, 1e-12 * (1 + std::abs(a.energy[i].gravity_work)));
    EXPECT_NEAR(a.energy[i].friction, b.energy[i].friction, 1e-12 * (1 + std::abs(a.energy[i].friction)));
  }
  ASSERT_EQ(a.bolt_histories.size(), b.bolt_histories.size());
  for (std::size_t k = 0; k < a.bolt_histories.size(); ++k) {
    ASSERT_EQ(a.bolt_histories[k].size(), b.bolt_histories[k].size());
    for (std::size_t s = 0; s < a.bolt_histories[k].size(); ++s)
      EXPECT_NEAR(a.bolt_histories[k][s].force, b.bolt_histories[k][s].force, 1e-9);
  }
  ASSERT_EQ(a.frames.size(), b.frames.size());
  for (std::size_t f = 0; f < a.frames.size(); ++f) {
    EXPECT_EQ(a.frames[f].step, b.frames[f].step);
    for (std::size_t v = 0; v < a.frames[f].vertices.size(); ++v)
      EXPECT_NEAR((a.frames[f].vertices[v] - b.frames[f].vertices[v]).norm(), 0, 1e-12);
  }
}

class IoCheckpoint : public ::testing::TestWithParam<std::string> {};

TEST_P(IoCheckpoint, ResumeReproducesTheUninterruptedRun) {
  const fs::path dir = fs::temp_directory_path() / ("dda_io_checkpoint_" + GetParam());
  fs::create_directories(dir);
  const std::string whole = (dir / "whole.h5").string(), part = (dir / "part.h5").string();
  const ModelInput in = sliding_model(GetParam());

  {  // 2N steps in one go
    Simulation sim(build_model(in));
    Results r = test::fresh_results(in);
    EXPECT_EQ(run_recorded(sim, r, whole, RunControl{}), RunEnd::Finished);
  }
  {  // N steps, stopped
    Simulation sim(build_model(in));
    Results r = test::fresh_results(in);
    RunControl rc;
    rc.stop_at_step = 30;
    EXPECT_EQ(run_recorded(sim, r, part, rc), RunEnd::Stopped);
    EXPECT_EQ(sim.log().size(), 30u);
  }
  {  // a new Simulation from the file: N more
    Results saved = read_results_h5(part);
    EXPECT_FALSE(saved.complete);
    ASSERT_TRUE(saved.checkpoint.has_value());
    EXPECT_EQ(saved.checkpoint->step_count, 30);
    Simulation sim(build_model(in));
    sim.restore(*saved.checkpoint);
    EXPECT_EQ(sim.time(), saved.checkpoint->time);
    Results r = test::fresh_results(in);
    r.frames = saved.frames;
    EXPECT_EQ(run_recorded(sim, r, part, RunControl{}), RunEnd::Finished);
  }
  const Results a = read_results_h5(whole), b = read_results_h5(part);
  EXPECT_TRUE(a.complete);
  EXPECT_TRUE(b.complete);
  EXPECT_EQ(a.log.size(), 60u);
  EXPECT_EQ(a.frames.size(), 7u);  // steps 0, 10, ..., 60
  EXPECT_EQ(a.bolt_names, std::vector<std::string>{"b"});
  expect_same(a, b);
  // Something happened: the slider slid and the pushed block moved.
  EXPECT_GT(a.histories[0].back().displacement.norm(), 1e-3);
  EXPECT_GT(a.histories[1].back().displacement.norm(), 1e-4);
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Solvers, IoCheckpoint, ::testing::Values("cholmod", "pcg"));

// A 1 x 1 m block held by fixed points and a 2 x 1 m block beside it,
// joined by one of DC's artificial cuts: the second hangs on the glue as a
// cantilever, its cut in tension at the top.
ModelInput glued_cantilever() {
  ModelInput in;
  Block left = test::make_block(test::rectangle(0, 0, 1, 1), kBoundarySet);
  Block right = test::make_block(test::rectangle(1, 0, 2, 1), kBoundarySet);
  left.edge_set[1] = kArtificialSet;   // (1,0) -> (1,1)
  right.edge_set[3] = kArtificialSet;  // (1,1) -> (1,0)
  in.geometry.blocks = {left, right};
  in.materials = {test::rock(2000, 1e10)};
  in.control.dt = 1e-3;
  in.control.steps = 60;
  for (const Vec2& p : {Vec2(0.2, 0.2), Vec2(0.8, 0.2), Vec2(0.5, 0.8)}) in.fixed_points.push_back({"f", p, 0, {}});
  in.measurements.push_back({"tip", {2.9, 0.5}, 1});
  return in;
}

TEST(IoCheckpoint, AResumedRunKeepsTheGlueOfArtificialCuts) {
  // The file keeps each contact's bond; a run resumed from it must find
  // its glued contacts glued again, or the cantilever falls off its cut
  // (the joint behind an artificial cut has no tensile strength).
  const fs::path dir = fs::temp_directory_path() / ("dda_io_checkpoint_glue_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string whole = (dir / "whole.h5").string(), part = (dir / "part.h5").string();
  const ModelInput in = glued_cantilever();
  {
    Simulation sim(build_model(in));
    Results r = test::fresh_results(in);
    EXPECT_EQ(run_recorded(sim, r, whole, RunControl{}), RunEnd::Finished);
  }
  {
    Simulation sim(build_model(in));
    Results r = test::fresh_results(in);
    RunControl rc;
    rc.stop_at_step = 30;
    EXPECT_EQ(run_recorded(sim, r, part, rc), RunEnd::Stopped);
  }
  {
    Results saved = read_results_h5(part);
    ASSERT_TRUE(saved.checkpoint.has_value());
    Simulation sim(build_model(in));
    sim.restore(*saved.checkpoint);
    int glued = 0;
    for (const Contact& c : sim.contacts()) glued += c.glued;
    EXPECT_GE(glued, 2) << "the cut's contacts are glued again";
    Results r = test::fresh_results(in);
    r.frames = saved.frames;
    EXPECT_EQ(run_recorded(sim, r, part, RunControl{}), RunEnd::Finished);
  }
  const Results a = read_results_h5(whole), b = read_results_h5(part);
  expect_same(a, b);
  // Hanging on its glue the tip sags by the springs' compliance only.
  EXPECT_LT(a.histories[0].back().displacement.norm(), 1e-3);
  fs::remove_all(dir);
}

TEST(IoCheckpoint, RestoreRefusesAnotherModel) {
  ModelInput in = sliding_model("cholmod");
  Simulation a(build_model(in));
  a.step();
  SimulationState s = a.state();
  in.measurements.pop_back();
  Simulation b(build_model(in));
  EXPECT_THROW(b.restore(s), InputError);
}

}  // namespace
}  // namespace dda::df
