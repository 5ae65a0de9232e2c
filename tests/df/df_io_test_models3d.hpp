#pragma once
// The blocks of the 3D scenario and results tests: V1 in 3D as DC would
// write it, a 1 m cube on a 10 x 10 x 1 m base whose top is a plane dipping
// 20 deg east, the plane's top face and the cube's bottom of joint set 0
// ("slide"), optionally with points of the blocks file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "dda/common/polyhedron_model.hpp"
#include "dda/df/3d/block3d.hpp"
#include "dda/df/io/results3d.hpp"
#include "df_test_models3d.hpp"

namespace dda::df3::testing {

inline PolyhedronModel incline_blocks(std::vector<ModelPoint3> points = {}) {
  const Eigen::Matrix3d r = plane_rotation(20, 90);
  PolyhedronModel m;
  m.blocks = {box({-5, -5, -1}, {5, 5, 0}, r), box({-0.5, -0.5, 0}, {0.5, 0.5, 1}, r)};
  m.blocks[0].faces[1].set = 0;  // the plane's top
  m.blocks[1].faces[0].set = 0;  // the cube's bottom
  for (Polyhedron& p : m.blocks) refresh_geometry(p), p.body = -1;
  m.sets = {{"slide", "plane"}};
  m.points = std::move(points);
  return m;
}

// An empty results file for `blocks`: frames every 10 steps, made-up
// provenance.
inline Results3 fresh_results3(const PolyhedronModel& blocks) {
  Results3 r;
  r.blocks = blocks;
  r.source.provenance.scenario_path = "test";
  r.source.blocks_path = "blocks3d.h5";
  r.output.every = 10;
  return r;
}

// The checkpoint tests' two runs of `model`: one in one go, and one
// stopped at step `stop_at`, written to a results file, read back and
// resumed in a fresh Simulation3 to the end. `stopped` is the first half as
// it was when written, `saved` the file read at the stop. `name` keeps the
// files of tests running in parallel apart; they are removed.
struct WholeAndResumed3 {
  std::unique_ptr<Simulation3> whole, stopped, resumed;
  Results3 saved;
};

inline WholeAndResumed3 run_whole_and_resumed3(const Model3& model, const PolyhedronModel& blocks, int stop_at,
                                               const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path();
  const std::string stem = "dda_" + name + "_" + std::to_string(::getpid());
  const std::string whole = (dir / (stem + "_whole.h5")).string(), part = (dir / (stem + "_part.h5")).string();
  WholeAndResumed3 out;
  out.whole = std::make_unique<Simulation3>(model);
  Results3 rw = fresh_results3(blocks);
  EXPECT_EQ(run_recorded(*out.whole, rw, whole, RunControl3{}), df::RunEnd::Finished);
  out.stopped = std::make_unique<Simulation3>(model);
  Results3 rs = fresh_results3(blocks);
  RunControl3 rc;
  rc.stop_at_step = stop_at;
  EXPECT_EQ(run_recorded(*out.stopped, rs, part, rc), df::RunEnd::Stopped);
  out.saved = read_results3_h5(part);
  if (!out.saved.checkpoint) throw std::runtime_error(part + " holds no checkpoint");
  out.resumed = std::make_unique<Simulation3>(model);
  out.resumed->restore(*out.saved.checkpoint);
  Results3 rr = fresh_results3(blocks);
  rr.frames = out.saved.frames;
  EXPECT_EQ(run_recorded(*out.resumed, rr, part, RunControl3{}), df::RunEnd::Finished);
  fs::remove(whole);
  fs::remove(part);
  return out;
}

}  // namespace dda::df3::testing
