// The 3D results file (df/io/results3d.hpp): what is written reads back, and a
// run stopped after N steps, written, read and resumed in a fresh
// Simulation3 ends bit for bit where the uninterrupted run ends.
#include <gtest/gtest.h>

#include <filesystem>

#include "dda/common/error.hpp"
#include "dda/df/io/results3d.hpp"
#include "df_io_test_models3d.hpp"

namespace dda::df3 {
namespace {

namespace fs = std::filesystem;

using testing::incline_blocks;

// The cube held by a soft fixed point, pushed by a small point load and
// measured at its top.
Model3 incline_model(const PolyhedronModel& blocks) {
  const Matrix3d r = testing::plane_rotation(20, 90);
  Model3 m;
  m.blocks = blocks.blocks;
  m.fixed = {true, false};
  m.materials = {{2600, 1e10, 0.25}};
  df::JointProperties j;
  j.friction_deg = 10;
  m.joint_sets = {j};
  m.normal_penalty = m.shear_penalty = 1e9;
  m.contact_reach = 0.01;
  m.control.dt = 1e-3;
  m.control.steps = 40;
  m.measurements.push_back({"top", 1, r * Vec3(0, 0, 1)});
  FixedPoint3 fp;
  fp.block = 1;
  fp.position = r * Vec3(0.2, 0, 0.5);
  fp.penalty = 1e3;
  m.fixed_points.push_back(fp);
  PointLoad3 load;
  load.block = 1;
  load.position = r * Vec3(0, 0, 0.5);
  load.force.t = {0, 0.02};
  load.force.value = {Vec3(0, 0, 0), Vec3(0, 100, 0)};
  m.loads.push_back(load);
  return m;
}

Results3 fresh(const PolyhedronModel& blocks) { return testing::fresh_results3(blocks); }

fs::path temp(const std::string& name) { return fs::temp_directory_path() / ("dda_results3d_" + name); }

TEST(Results3d, WritesAndReadsBack) {
  const PolyhedronModel blocks = incline_blocks();
  Simulation3 sim(incline_model(blocks));
  Results3 r = fresh(blocks);
  const std::string path = temp("round.h5").string();
  ASSERT_EQ(run_recorded(sim, r, path, RunControl3{}), df::RunEnd::Finished);

  const Results3 back = read_results3_h5(path);
  EXPECT_TRUE(back.complete);
  EXPECT_EQ(back.source.blocks_path, "blocks3d.h5");
  EXPECT_EQ(back.output.every, 10);
  ASSERT_EQ(back.point_names, std::vector<std::string>{"top"});
  EXPECT_EQ(back.point_blocks, std::vector<int>{1});
  EXPECT_EQ(back.fixed, (std::vector<bool>{true, false}));
  ASSERT_EQ(back.log.size(), sim.log().size());
  for (std::size_t i = 0; i < back.log.size(); ++i) {
    EXPECT_EQ(back.log[i].time, sim.log()[i].time);
    EXPECT_EQ(back.log[i].sliding, sim.log()[i].sliding);
    EXPECT_EQ(back.log[i].max_displacement, sim.log()[i].max_displacement);
  }
  ASSERT_EQ(back.histories.size(), 1u);
  ASSERT_EQ(back.histories[0].size(), sim.histories()[0].size());
  const MeasurementSample3& a = back.histories[0].back();
  const MeasurementSample3& b = sim.histories()[0].back();
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.displacement, b.displacement);
  EXPECT_EQ(a.velocity, b.velocity);
  EXPECT_EQ(a.stress, b.stress);
  EXPECT_GT(a.displacement.norm(), 0);
  // The blocks the run started from, as written.
  ASSERT_EQ(back.blocks.blocks.size(), 2u);
  EXPECT_EQ(back.blocks.blocks[1].vertices, blocks.blocks[1].vertices);
  EXPECT_EQ(back.blocks.blocks[0].faces[1].set, 0);
  EXPECT_EQ(back.blocks.sets[0].name, "slide");
  // Frames 0, 10, 20, 30, 40.
  ASSERT_EQ(back.frames.size(), 5u);
  EXPECT_EQ(back.frames.back().step, 40);
  EXPECT_EQ(back.frames.back().vertices.size(), 16u);
  // The checkpoint holds the contacts as they are.
  ASSERT_TRUE(back.checkpoint.has_value());
  const SimulationState3 s = sim.state();
  ASSERT_EQ(back.checkpoint->contacts.size(), s.contacts.size());
  EXPECT_FALSE(s.contacts.empty());
  for (std::size_t k = 0; k < s.contacts.size(); ++k) {
    const Contact3 &x = back.checkpoint->contacts[k], &y = s.contacts[k];
    EXPECT_EQ(x.i, y.i);
    EXPECT_EQ(x.state, y.state);
    EXPECT_EQ(x.ref_j, y.ref_j);
    EXPECT_EQ(x.shear_force, y.shear_force);
    EXPECT_EQ(x.geo.point_j, y.geo.point_j);
    EXPECT_EQ(x.friction.slip, y.friction.slip);
  }
  EXPECT_EQ(back.checkpoint->dt, s.dt);
  EXPECT_EQ(back.checkpoint->fixed_at, s.fixed_at);
  fs::remove(path);
}

// Runs `model` from the start and stops it after `steps` steps, saving to
// `path` (a results file with a checkpoint, as `dda df --stop-at-step`).
void run_stopped_at(const Model3& model, const PolyhedronModel& blocks, const std::string& path, int steps) {
  Simulation3 s(model);
  Results3 r = fresh(blocks);
  RunControl3 rc;
  rc.stop_at_step = steps;
  ASSERT_EQ(run_recorded(s, r, path, rc), df::RunEnd::Stopped);
}

// Resumes the run saved in `path` to its end, as `dda df --resume`.
Simulation3 resumed_to_end(const Model3& model, const PolyhedronModel& blocks, const std::string& path) {
  Results3 saved = read_results3_h5(path);
  EXPECT_FALSE(saved.complete);
  Simulation3 b(model);
  b.restore(*saved.checkpoint);
  Results3 rb = fresh(blocks);
  rb.frames = saved.frames;
  EXPECT_EQ(run_recorded(b, rb, path, RunControl3{}), df::RunEnd::Finished);
  return b;
}

TEST(Results3d, ResumeReproducesTheUninterruptedRun) {
  const PolyhedronModel blocks = incline_blocks();
  const Model3 model = incline_model(blocks);
  const std::string whole = temp("whole.h5").string(), part = temp("part.h5").string();
  Simulation3 a(model);
  Results3 ra = fresh(blocks);
  ASSERT_EQ(run_recorded(a, ra, whole, RunControl3{}), df::RunEnd::Finished);

  run_stopped_at(model, blocks, part, 17);
  ASSERT_EQ(read_results3_h5(part).log.size(), 17u);
  const Simulation3 b = resumed_to_end(model, blocks, part);

  const Results3 x = read_results3_h5(whole), y = read_results3_h5(part);
  ASSERT_EQ(x.log.size(), y.log.size());
  for (std::size_t i = 0; i < x.log.size(); ++i) EXPECT_EQ(x.log[i].time, y.log[i].time) << i;
  for (std::size_t s = 0; s < x.histories[0].size(); ++s) {
    EXPECT_EQ(x.histories[0][s].position, y.histories[0][s].position) << "sample " << s;
    EXPECT_EQ(x.histories[0][s].velocity, y.histories[0][s].velocity) << "sample " << s;
  }
  for (std::size_t i = 0; i < a.blocks().size(); ++i) EXPECT_EQ(a.blocks()[i].vertices, b.blocks()[i].vertices);
  ASSERT_EQ(x.frames.size(), y.frames.size());
  EXPECT_EQ(x.frames.back().vertices, y.frames.back().vertices);
  fs::remove(whole);
  fs::remove(part);
}

// With initial_equilibrium the run relaxes once, before its first step.
// The checkpoint says that it has (`started`), so a run resumed from the
// results file does not relax again and ends where the uninterrupted run
// ends; a file saved before the first step has not started.
TEST(Results3d, ResumedRunDoesNotRelaxAgain) {
  const PolyhedronModel blocks = incline_blocks();
  Model3 model = incline_model(blocks);
  model.control.initial_equilibrium = true;
  const std::string whole = temp("settled_whole.h5").string(), part = temp("settled_part.h5").string();
  Simulation3 a(model);
  Results3 ra = fresh(blocks);
  ASSERT_EQ(run_recorded(a, ra, whole, RunControl3{}), df::RunEnd::Finished);
  EXPECT_GT(a.settle_iterations(), 0);
  run_stopped_at(model, blocks, part, 0);
  EXPECT_FALSE(read_results3_h5(part).checkpoint->started);
  run_stopped_at(model, blocks, part, 17);
  ASSERT_TRUE(read_results3_h5(part).checkpoint.has_value());
  EXPECT_TRUE(read_results3_h5(part).checkpoint->started);
  const Simulation3 b = resumed_to_end(model, blocks, part);
  EXPECT_EQ(b.settle_iterations(), 0);
  EXPECT_EQ(b.start_up().stuck_iterations, 0);
  ASSERT_EQ(a.log().size(), b.log().size());
  EXPECT_EQ(a.time(), b.time());
  for (std::size_t i = 0; i < a.blocks().size(); ++i) EXPECT_EQ(a.blocks()[i].vertices, b.blocks()[i].vertices);
  fs::remove(whole);
  fs::remove(part);
}

TEST(Results3d, RefusesOtherFiles) {
  const PolyhedronModel blocks = incline_blocks();
  Simulation3 sim(incline_model(blocks));
  Results3 r = fresh(blocks);
  const std::string path = temp("other.h5").string();
  RunControl3 rc;
  rc.stop_at_step = 2;
  run_recorded(sim, r, path, rc);
  try {
    df::read_results_h5(path);
    FAIL() << "a 3D results file read as a 2D one";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": is a dda-results3d file, expected a dda-results file.");
  }
  fs::remove(path);
}

}  // namespace
}  // namespace dda::df3
