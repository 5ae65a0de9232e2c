#pragma once
// Subcommands of the `dda` program. Each registers itself on the app with
// its options and a callback; main() only dispatches and reports errors.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <string>

#include "dda/common/block_model.hpp"
#include "dda/common/polyhedron_model.hpp"
#include "dda/common/yaml_reader.hpp"

namespace dda::cli {

struct GlobalOptions {
  bool quiet = false;
};

// Thrown by a command whose error another process prints (every MPI rank of
// a study reads the same study file and fails alike; rank 0 alone says so):
// main() exits with `status` and prints nothing.
struct ReportedElsewhere {
  int status = 1;
};

void add_dl_command(CLI::App& app, const GlobalOptions& global);
void add_dc_command(CLI::App& app, const GlobalOptions& global);
void add_run_command(CLI::App& app, const GlobalOptions& global);
void add_stats_command(CLI::App& app, const GlobalOptions& global);
void add_plot_command(CLI::App& app, const GlobalOptions& global);
void add_info_command(CLI::App& app, const GlobalOptions& global);
void add_df_command(CLI::App& app, const GlobalOptions& global);
void add_history_command(CLI::App& app, const GlobalOptions& global);
void add_trace_command(CLI::App& app, const GlobalOptions& global);  // 3D fractures -> 2D section lines
// Analytical toolkit (tools/analysis; docs/analytical.md).
void add_newmark_command(CLI::App& app, const GlobalOptions& global);
void add_sliding3d_command(CLI::App& app, const GlobalOptions& global);
void add_wedge_command(CLI::App& app, const GlobalOptions& global);
void add_backfit_command(CLI::App& app, const GlobalOptions& global);
void add_record_command(CLI::App& app, const GlobalOptions& global);
void add_compare_command(CLI::App& app, const GlobalOptions& global);  // DDA history vs analytical
void add_spectra_command(CLI::App& app, const GlobalOptions& global);  // Fourier, H/V, spectral ratios, response
void add_report_command(CLI::App& app, const GlobalOptions& global);  // one HTML page of a run
void add_study_command(CLI::App& app, const GlobalOptions& global);   // sweeps and Monte Carlo studies
// Writes FOLDER/report.html for the results file (dda report, and dda run at its end).
void write_run_report(const std::string& results, const std::string& folder, bool quiet);
struct OutputOptions;
// `dda run`'s last stage: report.html in `dir` for `results` when the
// output options ask for it, or a note why not.
void report_after_run(const std::string& results, const std::filesystem::path& dir, const OutputOptions& out,
                      bool quiet);

// The scenario's `output` section (parsed in cmd_run.cpp; docs/scenario.md).
struct OutputOptions {
  bool vtk = true;
  bool plots = true;
  bool report = true;              // DF: report.html at the end (needs plots too: it is made of the figures)
  int histogram_bins = 20;
  double checkpoint_seconds = 60;  // DF: rewrite results.h5 at least this often (wall clock), 0: at the end only
  int checkpoint_steps = 0;        // DF: and every this many steps, 0: off
  bool vtk_contacts = true;        // DF: write the contacts series next to the blocks series
};
OutputOptions parse_output_options(const YamlNode& root);

// `dda run` on a 3D scenario (run3d.cpp): DL, the trace-plane sections cut
// in 2D, DC, statistics, ParaView files and figures into `dir`.
void run_pipeline_3d(const YamlNode& root, const std::filesystem::path& dir, const OutputOptions& out, bool quiet);

// The DF stage (cmd_df.cpp), as `dda df` and `dda run` use it.
struct DfStage {
  std::string results_path;           // results.h5 to write
  std::string vtk_dir;                // "" for no ParaView series
  std::optional<int> stop_at_step;    // stop early with a checkpoint
  bool quiet = false;
};
// A forward run of a YAML scenario on `blocks` (read from `blocks_path`).
void run_df_scenario(const YamlNode& root, const BlockModel& blocks, const std::string& blocks_path,
                     const DfStage& stage);
// The same in 3D (cmd_df3d.cpp): a dimension: 3 scenario on polyhedra.
void run_df3_scenario(const YamlNode& root, const PolyhedronModel& blocks, const std::string& blocks_path,
                      const DfStage& stage);
// `dda df --resume` of a dda-results3d file.
void resume_df3(const std::string& path, DfStage stage);

}  // namespace dda::cli
