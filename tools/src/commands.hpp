#pragma once
// Subcommands of the `dda` program. Each registers itself on the app with
// its options and a callback; main() only dispatches and reports errors.
#include <CLI/CLI.hpp>
#include <string>

namespace dda::cli {

struct GlobalOptions {
  bool quiet = false;
};

void add_dl_command(CLI::App& app, const GlobalOptions& global);
void add_dc_command(CLI::App& app, const GlobalOptions& global);
void add_run_command(CLI::App& app, const GlobalOptions& global);
void add_stats_command(CLI::App& app, const GlobalOptions& global);
void add_plot_command(CLI::App& app, const GlobalOptions& global);
void add_info_command(CLI::App& app, const GlobalOptions& global);

}  // namespace dda::cli
