// dda df SCENARIO.yaml|MODEL.ana --blocks blocks.h5 -o results.h5
// dda df --resume results.h5
//
// The forward run: reads the blocks and the DF sections of a scenario (or a
// DDA for Windows analysis file), steps the simulation to its end with a
// progress bar, and keeps results.h5 up to date (rewritten atomically every
// so often, with a checkpoint), so an interrupted run resumes where it was.
// The job and its resumption are df_job.hpp's, shared with 3D; here is what
// is 2D's own: the analysis file and the 2D types. A 3D blocks file (and a
// 3D results file to resume) goes to cmd_df3d.cpp.
#include <filesystem>
#include <iostream>

#include "commands.hpp"
#include "dda/common/error.hpp"
#include "dda/common/model_io.hpp"
#include "dda/common/model_io3d.hpp"
#include "dda/common/output_guard.hpp"
#include "dda/common/scenario.hpp"
#include "dda/common/text_input.hpp"
#include "dda/df/io/import_ana.hpp"
#include "dda/df/io/results.hpp"
#include "dda/df/io/results3d.hpp"
#include "dda/df/io/scenario.hpp"
#include "df_job.hpp"
#include "pipeline.hpp"

namespace dda::cli {

namespace fs = std::filesystem;

namespace {

// The 2D side of df_job.hpp.
struct Df2 {
  using Simulation = df::Simulation;
  using Results = df::Results;
  using Scenario = df::DfScenario;
  using State = df::SimulationState;
  static Results read_results(const std::string& path) { return df::read_results_h5(path); }
  static DfJob<Df2> job_from_saved(const Results& saved);
  static df::Model model_of(const DfJob<Df2>& job);
};
using Job = DfJob<Df2>;

Job job_from_scenario(const YamlNode& root, const BlockModel& blocks, const std::string& blocks_path) {
  Job job;
  job.scenario = df::read_df_scenario(root, blocks, blocks_path);
  fill_job_from_scenario(job, root, blocks, blocks_path);
  job.results.solver = job.scenario.input.control.solver;
  job.results.output = df::resolve_output_schedule(job.scenario.output, job.scenario.input.control);
  return job;
}

Job job_from_ana(const std::string& text, const std::string& label, const BlockModel& blocks,
                 const std::string& blocks_path, bool quiet) {
  Job job;
  df::AnaImport imp = df::import_ana(text, label, blocks, blocks_path);
  if (!quiet)
    for (const std::string& w : imp.warnings) std::cerr << "dda: note: " << w << "\n";
  job.scenario = std::move(imp.scenario);
  job.input_files = label + " with " + blocks_path;
  df::Results& r = job.results;
  r.source.provenance.scenario_path = label;
  r.source.provenance.scenario_text = text;
  r.source.provenance.seed = blocks.provenance.seed;
  r.source.input_kind = "ana";
  r.source.blocks_path = blocks_path;
  r.blocks = blocks;
  r.solver = job.scenario.input.control.solver;
  r.output = df::resolve_output_schedule(job.scenario.output, job.scenario.input.control);
  return job;
}

Job Df2::job_from_saved(const Results& saved) {
  const df::ResultsSource& src = saved.source;
  if (src.input_kind == "ana")
    return job_from_ana(src.provenance.scenario_text, src.provenance.scenario_path, saved.blocks, src.blocks_path,
                        true);
  return job_from_scenario(stored_scenario(src), saved.blocks, src.blocks_path);
}

// A YAML scenario's model was checked as it was read; what an .ana's model
// still refuses (a fixed point of the .geo outside every block) is a
// problem of its two files, and says which.
df::Model Df2::model_of(const Job& job) {
  return naming_input(job.input_files, [&] { return df::build_model(job.scenario.input); });
}

}  // namespace

void run_df_scenario(const YamlNode& root, const BlockModel& blocks, const std::string& blocks_path,
                     const DfStage& stage) {
  Job job = job_from_scenario(root, blocks, blocks_path);
  execute_job<Df2>(job, stage, std::nullopt);
}

void add_df_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    std::string input, blocks, output, resume, vtk;
    std::optional<int> stop_at_step;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "df", "Forward DDA run of a blocks file: `dda df SCENARIO.yaml --blocks blocks.h5 -o results.h5` "
            "(or MODEL.ana, a DDA for Windows analysis), or `dda df --resume results.h5`");
  cmd->add_option("input", opt->input,
                  "Scenario (.yaml) with materials, joints, loading, fixed and control; or a DDA for Windows "
                  "analysis file (.ana)");
  cmd->add_option("--blocks", opt->blocks, "Blocks file written by `dda dc` (2D, or 3D with a dimension: 3 scenario)");
  cmd->add_option("-o,--output", opt->output,
                  "Results file to write (HDF5); with --resume, defaults to the file resumed");
  cmd->add_option("--resume", opt->resume, "Continue the run saved in this results file from its checkpoint");
  cmd->add_option("--vtk", opt->vtk, "Also write a ParaView series (df.pvd, blocks and contacts) into this folder");
  cmd->add_option("--stop-at-step", opt->stop_at_step,
                  "Stop once the run has this many steps (the results file then holds a checkpoint to resume)")
      ->check(CLI::PositiveNumber);
  cmd->callback([opt, &global] {
    // Not -o against --resume: a resumed run rewrites its own file by design
    // (atomically, so the checkpoint survives until the new one is whole).
    refuse_overwriting_inputs({opt->input, opt->blocks, opt->resume},
                              {opt->resume.empty() ? opt->output : std::string(), opt->vtk});
    DfStage stage;
    stage.results_path = opt->output;
    stage.vtk_dir = opt->vtk;
    stage.stop_at_step = opt->stop_at_step;
    stage.quiet = global.quiet;
    if (!opt->resume.empty()) {
      if (!opt->input.empty() || !opt->blocks.empty())
        throw InputError("--resume continues the run stored in " + opt->resume +
                         "; give no scenario or --blocks with it.");
      if (h5_format_of(opt->resume) == df3::kResults3dFormat)
        resume_df3(opt->resume, stage);
      else
        resume_job<Df2>(opt->resume, stage);
      return;
    }
    if (opt->input.empty()) throw InputError("dda df needs a scenario (.yaml) or analysis (.ana) file, or --resume.");
    if (opt->blocks.empty()) throw InputError("dda df needs --blocks BLOCKS.h5 (written by `dda dc`).");
    if (opt->output.empty()) throw InputError("dda df needs -o RESULTS.h5, the results file to write.");
    if (!fs::exists(opt->input)) throw InputError(opt->input + ": no such file.");
    const bool scenario3d = !df::is_ana_path(opt->input) && dl_input_dimension(opt->input) == 3;
    if (h5_format_of(opt->blocks) == kBlocks3dFormat) {
      if (!scenario3d)
        throw InputError(opt->blocks + ": holds 3D blocks, but " + opt->input +
                         " is not a 3D scenario (add dimension: 3 to it).");
      run_df3_scenario(load_scenario(opt->input), read_polyhedra_h5(opt->blocks), opt->blocks, stage);
      return;
    }
    if (scenario3d)
      throw InputError(opt->input + ": is a 3D scenario, so it needs a 3D blocks file (dda-blocks3d), not " +
                       opt->blocks + ".");
    const BlockModel blocks = read_blocks_h5(opt->blocks);
    Job job;
    if (df::is_ana_path(opt->input)) {
      job = job_from_ana(read_text_file(opt->input, "analysis"), opt->input, blocks, opt->blocks, global.quiet);
    } else {
      const YamlNode root = load_scenario(opt->input);
      job = job_from_scenario(root, blocks, opt->blocks);
    }
    execute_job<Df2>(job, stage, std::nullopt);
  });
}

}  // namespace dda::cli
