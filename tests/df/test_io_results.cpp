// The results file and the ParaView frames (df/io/results.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "dda/common/error.hpp"
#include "dda/common/model_io.hpp"
#include "dda/df/io/results.hpp"
#include "df_io_test_models.hpp"
#include "df_test_models.hpp"

namespace dda::df {
namespace {

namespace fs = std::filesystem;

std::string slurp(const std::string& path) {
  std::ifstream f(path);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

TEST(IoResults, WritesAndReadsBack) {
  const fs::path dir = fs::temp_directory_path() / "dda_io_results";
  fs::create_directories(dir);
  const std::string path = (dir / "r.h5").string();
  const ModelInput in = test::drop_model();
  Simulation sim(build_model(in));
  Results r;
  r.blocks = in.geometry;
  r.source.provenance.scenario_path = "drop.yaml";
  r.source.provenance.scenario_text = "name: drop\n";
  r.source.provenance.seed = 11;
  r.source.blocks_path = "blocks.h5";
  r.output.interval = 0.1;
  std::vector<std::size_t> frames_seen;
  RunControl rc;
  rc.on_frame = [&](const Simulation& s, std::size_t f) {
    frames_seen.push_back(f);
    write_blocks_frame_vtu((dir / ("b" + std::to_string(f) + ".vtu")).string(), s);
    write_contacts_vtu((dir / ("c" + std::to_string(f) + ".vtu")).string(), s);
  };
  ASSERT_EQ(run_recorded(sim, r, path, rc), RunEnd::Finished);
  EXPECT_EQ(frames_seen, (std::vector<std::size_t>{0, 1, 2, 3}));  // t = 0, 0.1, 0.2, 0.3

  EXPECT_EQ(h5_format_of(path), "dda-results");
  const Results back = read_results_h5(path);
  EXPECT_TRUE(back.complete);
  EXPECT_EQ(back.source.provenance.scenario_text, "name: drop\n");
  EXPECT_EQ(back.source.provenance.seed, 11u);
  EXPECT_EQ(back.source.blocks_path, "blocks.h5");
  EXPECT_EQ(back.output.interval, 0.1);
  EXPECT_EQ(back.point_names, std::vector<std::string>{"top"});
  EXPECT_EQ(back.point_blocks, std::vector<int>{1});
  ASSERT_EQ(back.log.size(), sim.log().size());
  ASSERT_EQ(back.histories[0].size(), sim.log().size() + 1);
  EXPECT_EQ(back.histories[0].back().displacement, sim.histories()[0].back().displacement);
  EXPECT_TRUE(back.has_acceleration);
  EXPECT_EQ(back.histories[0].back().acceleration, sim.histories()[0].back().acceleration);
  EXPECT_EQ(back.energy.size(), sim.energy_log().size());
  ASSERT_EQ(back.frames.size(), 4u);
  EXPECT_NEAR(back.frames[1].time, 0.1, 1e-9);
  EXPECT_EQ(back.frames.back().vertices.size(), 8u);
  EXPECT_EQ(back.frames.back().vertices[4], sim.blocks()[1].vertices[0]);
  ASSERT_EQ(back.blocks.blocks.size(), 2u);
  EXPECT_EQ(back.blocks.blocks[1].vertices, in.geometry.blocks[1].vertices);
  EXPECT_EQ(back.blocks.points.size(), 3u);
  // The block fell 0.1 m and landed: it stopped near 0.1 m down.
  EXPECT_NEAR(back.histories[0].back().displacement.y(), -0.1, 0.01);

  const std::string b = slurp((dir / "b3.vtu").string());
  EXPECT_NE(b.find("NumberOfCells=\"2\""), std::string::npos);
  for (const char* name : {"\"displacement\"", "\"velocity\"", "\"stress\"", "\"rotation_rate\""})
    EXPECT_NE(b.find(name), std::string::npos) << name;
  const std::string c = slurp((dir / "c3.vtu").string());
  EXPECT_NE(c.find("Name=\"state\""), std::string::npos);
  EXPECT_NE(c.find("Name=\"normal_force\""), std::string::npos);
  EXPECT_EQ(c.find("NumberOfCells=\"0\""), std::string::npos);  // it is in contact at the end
  fs::remove_all(dir);
}

TEST(IoResults, RefusesOtherFiles) {
  const fs::path dir = fs::temp_directory_path() / "dda_io_results_bad";
  fs::create_directories(dir);
  const std::string blocks = (dir / "b.h5").string();
  write_blocks_h5(blocks, test::drop_model().geometry);
  try {
    read_results_h5(blocks);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), blocks + ": is a dda-blocks file, expected a dda-results file.");
  }
  EXPECT_THROW(read_results_h5((dir / "none.h5").string()), InputError);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace dda::df
