// The run loop's one writer interface (df::RunWriter, run_loop.hpp): every
// registered writer is told of each frame and each save, in the order it
// was registered, on the schedule the loop promises; the results file is
// one such writer (ResultsFileWriter). The expected calls follow from the
// schedule by hand, as written next to each check.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "dda/df/io/results.hpp"
#include "df_io_test_models.hpp"
#include "df_test_models.hpp"

namespace dda::df {
namespace {

namespace fs = std::filesystem;

// Writes down what it is told, with its name, into a shared list.
class Recorder : public RunWriter<Simulation, Results> {
 public:
  Recorder(std::string name, std::vector<std::string>& events) : name_(std::move(name)), events_(events) {}
  void frame(const Simulation&, const Results& r, std::size_t index) override {
    EXPECT_EQ(index + 1, r.frames.size());  // told after the frame is in the results
    events_.push_back(name_ + " frame " + std::to_string(index));
  }
  void save(const Simulation&, const Results&, bool complete) override {
    events_.push_back(name_ + (complete ? " save complete" : " save"));
  }

 private:
  std::string name_;
  std::vector<std::string>& events_;
};

TEST(RunWriters, EveryWriterHearsEachFrameAndSaveInOrder) {
  const fs::path dir = fs::temp_directory_path() / "dda_run_writers";
  fs::create_directories(dir);
  const std::string path = (dir / "r.h5").string();
  const ModelInput in = test::drop_model();
  Simulation sim(build_model(in));
  Results r;
  r.blocks = in.geometry;
  r.output.interval = 0.1;
  std::vector<std::string> events;
  Recorder a("a", events), b("b", events);
  ResultsFileWriter<Simulation, Results> file(path);
  RunControl rc;
  rc.checkpoint_seconds = 0;  // saves on the step count only, so the test does not hang on the clock
  rc.checkpoint_steps = 50;
  ASSERT_EQ(run_recorded_loop(sim, r, {&a, &file, &b}, rc), RunEnd::Finished);

  // Frames at t = 0, 0.1, 0.2, 0.3 s (output interval 0.1 s); a save after
  // every 50 steps and a complete one at the end: n / 50 (whole) + 1 saves.
  const std::size_t n = sim.log().size();
  std::vector<std::string> frames, saves;
  for (const std::string& e : events) (e.find("frame") != std::string::npos ? frames : saves).push_back(e);
  EXPECT_EQ(frames, (std::vector<std::string>{"a frame 0", "b frame 0", "a frame 1", "b frame 1", "a frame 2",
                                              "b frame 2", "a frame 3", "b frame 3"}));
  std::vector<std::string> expected_saves;
  for (std::size_t k = 0; k < n / 50; ++k) expected_saves.insert(expected_saves.end(), {"a save", "b save"});
  expected_saves.insert(expected_saves.end(), {"a save complete", "b save complete"});
  EXPECT_EQ(saves, expected_saves);

  // The results file writer wrote the whole run.
  const Results back = read_results_h5(path);
  EXPECT_TRUE(back.complete);
  EXPECT_EQ(back.frames.size(), 4u);
  EXPECT_EQ(back.log.size(), n);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace dda::df
