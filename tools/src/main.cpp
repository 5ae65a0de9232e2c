// The `dda` program: one command, one subcommand per pipeline stage.
//
// Exit status: 0 on success; 1 when the input is wrong (one sentence on
// stderr naming the file, key or line); 2 for a command-line usage error;
// 3 for an internal error (a bug: please report it).
#include <CLI/CLI.hpp>
#include <cstdlib>
#include <exception>
#include <iostream>

#include "commands.hpp"
#include "dda/common/memory_policy.hpp"
#include "dda/common/error.hpp"
#include "dda/common/provenance.hpp"
#include "standard_output.hpp"

namespace {

// The exit status of a command that succeeded: still 1 if what it printed
// never reached the standard output (a full disk, a closed pipe).
int finish() {
  if (const auto failure = dda::cli::standard_output_failure()) {
    std::cerr << "dda: could not write to standard output: " << *failure << ".\n";
    return 1;
  }
  return 0;
}

// OpenMP threads that wait for work sleep instead of spinning, unless the
// user chose (OMP_WAIT_POLICY, or libgomp's GOMP_SPINCOUNT). libgomp reads
// its environment once, when it is loaded, before main(); an entry in
// .preinit_array runs before any shared library's initialisation, so the
// choice is made there. Why passive: docs/solver2d.md, "Threads for small
// models".
void prefer_passive_waiting(int, char**, char**) {
  if (!std::getenv("OMP_WAIT_POLICY") && !std::getenv("GOMP_SPINCOUNT")) setenv("OMP_WAIT_POLICY", "PASSIVE", 0);
}
[[gnu::section(".preinit_array"), gnu::used]] void (*const preinit_passive_waiting)(int, char**, char**) =
    prefer_passive_waiting;

}  // namespace

int main(int argc, char** argv) {
  dda::keep_freed_memory();  // memory_policy.hpp: large buffers are re-allocated every iterate
  dda::cli::watch_standard_output();
  CLI::App app{"dda: discontinuous deformation analysis of jointed rock.\n"
               "Pipeline: dl (lines) -> dc (blocks) -> df (forward run) -> history; "
               "`dda run` chains the stages a scenario asks for."};
  app.set_version_flag("--version", std::string("dda ") + dda::version_string());
  app.require_subcommand(1);
  app.fallthrough();
  dda::cli::GlobalOptions global;
  app.add_flag("-q,--quiet", global.quiet, "Print nothing but errors");

  dda::cli::add_dl_command(app, global);
  dda::cli::add_dc_command(app, global);
  dda::cli::add_df_command(app, global);
  dda::cli::add_run_command(app, global);
  dda::cli::add_stats_command(app, global);
  dda::cli::add_plot_command(app, global);
  dda::cli::add_info_command(app, global);
  dda::cli::add_history_command(app, global);
  dda::cli::add_trace_command(app, global);
  dda::cli::add_newmark_command(app, global);
  dda::cli::add_sliding3d_command(app, global);
  dda::cli::add_wedge_command(app, global);
  dda::cli::add_backfit_command(app, global);
  dda::cli::add_record_command(app, global);
  dda::cli::add_compare_command(app, global);
  dda::cli::add_spectra_command(app, global);
  dda::cli::add_report_command(app, global);
  dda::cli::add_study_command(app, global);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version are "errors" with exit code 0 in CLI11.
    const int code = app.exit(e);
    return code == 0 ? finish() : 2;
  } catch (const dda::cli::ReportedElsewhere& e) {
    return e.status;
  } catch (const dda::InputError& e) {
    std::cerr << "dda: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "dda: internal error: " << e.what() << " (please report this)\n";
    return 3;
  }
  return finish();
}
