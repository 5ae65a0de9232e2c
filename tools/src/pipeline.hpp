#pragma once
// The pipeline stages as the commands use them: each stage reads what the
// previous one wrote, reports what it did, and writes its file atomically.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "dda/common/block_model.hpp"
#include "dda/common/error.hpp"
#include "dda/common/line_model.hpp"
#include "dda/common/sentence_tail.hpp"
#include "dda/dc/cut.hpp"
#include "dda/dl/scenario3d.hpp"

namespace dda::cli {

struct StageOutput {
  std::string lines_h5;
  std::string blocks_h5;
};

// DL: a scenario (.yaml) or a DDA-for-Windows geometry file (.geo).
struct DlOutcome {
  LineModel lines;
  nlohmann::json report;
};
DlOutcome run_dl(const std::string& input_path);

// 3 for a scenario with `dimension: 3`, else 2 (a .geo file, or a path that
// run_dl will report as missing, counts as 2D).
int dl_input_dimension(const std::string& input_path);

// DL in 3D: the fractures of a `dimension: 3` scenario, with the report and
// the scenario's trace planes.
dl::DlResult3 run_dl3(const std::string& input_path);

// `<stem of base>.<name><suffix>` in base's folder: where `dda dl` writes the
// section of a scenario trace plane next to the fractures file (suffix
// ".lines.h5") or its ParaView file (".lines.vtu").
std::string section_path(const std::string& base, const std::string& name, const std::string& suffix);

// The `cutting:` section of the scenario stored in a lines file, if any.
dc::CutOptions cut_options_of(const LineModel& lines);

// Command-line overrides of the sliver filter (unset values keep the file's).
struct SliverOverrides {
  std::optional<double> min_area;
  std::optional<double> max_aspect;
  std::optional<std::string> action;  // "merge" or "report"
};
void apply(const SliverOverrides& o, dc::CutOptions& options);
void add_sliver_options(CLI::App* cmd, SliverOverrides& o);

// One line describing a cut: block count and area, and where it went.
std::string describe_cut(const BlockModel& blocks, const std::string& path);
// Said on stderr after a 2D cut whose blocks do not cover the rock it cut
// (domain less excavations): faces the cutter dropped as degenerate (joints
// nearly meeting at one point round to a face that is no simple polygon).
// Nothing below 1e-9 of the domain. The report's `degenerate` lists them.
void warn_of_lost_area(const BlockModel& blocks);

// Runs fn; an input error it throws is said again after the name of the file
// it came from ("l.h5: the domain polygon has no area ..."): the cutters see
// models, not files.
template <class Fn>
auto naming_input(const std::string& file, Fn&& fn) -> decltype(fn()) {
  try {
    return fn();
  } catch (const InputError& e) {
    throw InputError(file + ": " + with_lowered_start(e.what()));
  }
}

// Creates a folder (and its parents); InputError naming it if that fails.
void make_dir(const std::filesystem::path& dir);

// Prints `text` unless quiet.
void say(bool quiet, const std::string& text);

// Writes a JSON document atomically, pretty-printed.
void write_json(const std::string& path, const nlohmann::json& doc);

}  // namespace dda::cli
