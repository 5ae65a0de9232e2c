#pragma once
// `dda plot` draws with matplotlib (tools/plot/dda_plot.py) under Debian's
// /usr/bin/python3, which has h5py and matplotlib; the script is found next
// to the installed program, at the source-tree path known at build time, or
// where DDA_PLOT_SCRIPT points.
#include <string>
#include <vector>

namespace dda::cli {

// Runs the plot script with `args`; InputError with the script's own one-line
// message if it fails.
void run_plot_script(const std::vector<std::string>& args);
// Runs the report script (tools/plot/dda_report.py) with `args`, the same way.
void run_report_script(const std::vector<std::string>& args);
// Runs `script` (a file next to dda_plot.py) with `args`.
void run_script(const std::string& script, const std::vector<std::string>& args);

// Runs the plot script on a CSV the command produced (`csv`): on `written`
// when the command has written it there (-o), otherwise on a temporary copy
// removed afterwards. `args` follow the CSV's path on the script's command
// line (-o FIG, --kind ...).
void plot_csv(const std::string& csv, const std::string& written, const std::vector<std::string>& args);

// True when python3 with matplotlib and h5py can be found (used by `dda run`
// to skip figures with a note instead of failing).
bool plotting_available();

}  // namespace dda::cli
