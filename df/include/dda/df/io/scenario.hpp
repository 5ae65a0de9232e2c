#pragma once
// The forward-run sections of a scenario: materials, joints, loading, fixed,
// control (documented key by key in docs/scenario.md).
//
// read_df_scenario() turns them, with the blocks DC cut, into a ModelInput.
// Every mistake is an InputError of one sentence naming the scenario file,
// the line and the key (through YamlNode), or the blocks file for a problem
// of the blocks themselves (none at all, a point outside every block).
#include <optional>
#include <string>

#include "dda/common/block_model.hpp"
#include "dda/common/yaml_reader.hpp"
#include "dda/df/2d/model.hpp"

namespace dda::df {

// When block states are saved: every `interval` seconds of model time, or
// every `every` steps (exactly one is non-zero once resolved).
struct OutputSchedule {
  double interval = 0;  // s
  int every = 0;        // steps
};

struct DfScenario {
  ModelInput input;             // control.solver: auto | cholmod | pcg
  OutputSchedule output;
};

// Whether the scenario asks for a forward run: it has a `control` section.
bool scenario_has_df(const YamlNode& root);

// Checks the DF sections without blocks (keys, types, ranges), so `dda run`
// fails before DL on a typo in a late section. Returns quietly if the
// scenario has no DF sections.
void check_df_scenario(const YamlNode& root);

// The whole forward-run input: `blocks` (read from `blocks_path`, named in
// messages) plus the DF sections of `root`.
DfScenario read_df_scenario(const YamlNode& root, const BlockModel& blocks, const std::string& blocks_path);

// Checks that the blocks file can be run at all (it has blocks, every point
// lies in a block); InputError naming `blocks_path` (or, when the point
// comes from the scenario's `points`, the scenario line) otherwise.
void check_blocks_for_df(const BlockModel& blocks, const std::string& blocks_path,
                         const std::optional<YamlNode>& root = std::nullopt);

// Resolves an unset output schedule: 1/20 of the run (total_time / 20, or
// every max(1, steps / 20) steps).
OutputSchedule resolve_output_schedule(OutputSchedule s, const Control& control);
// The same for a run of `total_time` seconds, or of `steps` steps when that is 0.
OutputSchedule resolve_output_schedule(OutputSchedule s, double total_time, int steps);

}  // namespace dda::df
