#pragma once
// What `dda df` writes, 2D and 3D alike, behind the run loop's one writer
// interface (df::RunWriter, run_loop.hpp): a small registry, one line per
// output in RunOutputs' constructor. Each output is a RunWriter; what
// differs by dimension it reaches by argument-dependent lookup
// (write_results, write_frame_vtu in df/io/results.hpp and df/io/results3d.hpp).
// A new output is a RunWriter here and a line in the constructor.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "dda/df/io/bolts_vtk.hpp"
#include "dda/df/core/run_loop.hpp"
#include "pipeline.hpp"

namespace dda::cli {

// df_blocks_00012.vtu, df_contacts_00012.vtu, df_bolts_00012.vtu.
std::string frame_name(const char* kind, std::size_t frame);
// df.pvd in `dir` listing the blocks (and contacts, and bolts) frame files at `times`.
void write_pvd_series(const std::filesystem::path& dir, const std::vector<double>& times, bool contacts,
                      bool bolts);

// The ParaView series in a folder: a blocks (and contacts, and for a model
// with rock bolts a bolts) file per frame and df.pvd listing all of them, rewritten at each frame so that a run
// stopped at any point leaves a series ParaView opens.
template <class Sim, class Results>
class ParaViewSeries : public df::RunWriter<Sim, Results> {
 public:
  ParaViewSeries(std::filesystem::path dir, bool contacts) : dir_(std::move(dir)), contacts_(contacts) {
    make_dir(dir_);
  }
  void frame(const Sim& sim, const Results& results, std::size_t index) override {
    write_frame_vtu(sim, results, (dir_ / frame_name("blocks", index)).string(),
                    contacts_ ? (dir_ / frame_name("contacts", index)).string() : std::string());
    // The bolts of the frame (df/io/bolts_vtk.hpp), one overload per dimension.
    const bool bolts = !sim.bolts().empty();
    using df::write_bolts_vtu;
    using df3::write_bolts_vtu;
    if (bolts) write_bolts_vtu((dir_ / frame_name("bolts", index)).string(), sim);
    std::vector<double> times;
    for (const auto& f : results.frames) times.push_back(f.time);
    write_pvd_series(dir_, times, contacts_, bolts);
  }

 private:
  std::filesystem::path dir_;
  bool contacts_;
};

// The outputs of one run, in the order the loop calls them.
template <class Sim, class Results>
class RunOutputs {
 public:
  RunOutputs(const DfStage& stage, const OutputOptions& output) {
    add(std::make_unique<df::ResultsFileWriter<Sim, Results>>(stage.results_path));
    if (!stage.vtk_dir.empty()) add(std::make_unique<ParaViewSeries<Sim, Results>>(stage.vtk_dir, output.vtk_contacts));
  }
  const std::vector<df::RunWriter<Sim, Results>*>& writers() const { return writers_; }

 private:
  void add(std::unique_ptr<df::RunWriter<Sim, Results>> w) {
    writers_.push_back(w.get());
    owned_.push_back(std::move(w));
  }
  std::vector<std::unique_ptr<df::RunWriter<Sim, Results>>> owned_;
  std::vector<df::RunWriter<Sim, Results>*> writers_;
};

}  // namespace dda::cli
