// dda report RUN_FOLDER|RESULTS.h5 -o DIR
//
// One self-contained HTML page of a run (tools/plot/dda_report.py,
// docs/plots.md): provenance, model, run statistics, energy balance,
// warnings, the figures of `dda plot` embedded, and the measurement points'
// final and peak values.
#include <filesystem>

#include "commands.hpp"
#include "dda/common/error.hpp"
#include "dda/common/model_io.hpp"
#include "dda/common/output_guard.hpp"
#include "pipeline.hpp"
#include "plot_runner.hpp"

namespace dda::cli {

namespace fs = std::filesystem;

void write_run_report(const std::string& results, const std::string& folder, bool quiet) {
  run_report_script({results, "-o", folder});
  say(quiet, "report written to " + (fs::path(folder) / "report.html").string() + "\n");
}

void report_after_run(const std::string& results, const fs::path& dir, const OutputOptions& out, bool quiet) {
  if (!out.plots || !out.report) return;
  if (!plotting_available()) {
    say(quiet, "report skipped: /usr/bin/python3 with matplotlib and h5py is not installed\n");
    return;
  }
  write_run_report(results, dir.string(), quiet);
}

void add_report_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    std::string target, output;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "report",
      "Write DIR/report.html, a self-contained page of a run (2D or 3D): scenario and provenance, model, steps, dt, "
      "solves per step, energy balance, warnings, figures and the measurement points' final and peak values");
  cmd->add_option("run", opt->target, "A run folder written by `dda run` (it holds results.h5), or a results file")
      ->required();
  cmd->add_option("-o,--output", opt->output, "Folder to write report.html in (created if missing)")->required();
  cmd->callback([opt, &global] {
    std::string results = opt->target;
    if (fs::is_directory(results)) results = (fs::path(results) / "results.h5").string();
    if (!fs::exists(results))
      throw InputError(opt->target + (fs::is_directory(opt->target)
                                          ? ": holds no results.h5 (give a run folder of dda run, or a results file)."
                                          : ": file not found."));
    const std::string format = h5_format_of(results);
    if (format != "dda-results" && format != "dda-results3d")
      throw InputError(results + ": is not a results file (" + (format.empty() ? "no dda format" : format) +
                       "); dda report reads the results.h5 of dda df or dda run.");
    refuse_overwriting_inputs({results}, {(fs::path(opt->output) / "report.html").string()});
    if (!plotting_available())
      throw InputError("dda report needs /usr/bin/python3 with matplotlib and h5py, which is not installed.");
    write_run_report(results, opt->output, global.quiet);
  });
}

}  // namespace dda::cli
