#pragma once
// The forward-run sections of a `dimension: 3` scenario: materials, joints,
// loading (gravity, point loads, earthquake), fixed (blocks and points),
// control (documented key by key in docs/scenario.md, "The 3D forward run").
//
// read_df3_scenario() turns them, with the polyhedra DC cut, into a Model3.
// Every mistake is an InputError of one sentence naming the scenario file,
// the line and the key (through YamlNode), or the blocks file for a problem
// of the blocks themselves (none at all).
#include <string>
#include <vector>

#include "dda/common/polyhedron_model.hpp"
#include "dda/common/yaml_reader.hpp"
#include "dda/df/io/scenario.hpp"
#include "dda/df/3d/simulation3d.hpp"

namespace dda::df3 {

struct DfScenario3 {
  Model3 model;
  df::OutputSchedule output;  // as given (both 0: unset)
};

// Checks the DF sections of a 3D scenario without blocks (keys, types,
// ranges, the earthquake record), so `dda run` fails before DL on a typo in
// a late section. Returns quietly if the scenario has no DF sections.
void check_df3_scenario(const YamlNode& root);

// The whole forward-run input: `blocks` (read from `blocks_path`, named in
// messages) plus the DF sections of `root`.
DfScenario3 read_df3_scenario(const YamlNode& root, const PolyhedronModel& blocks, const std::string& blocks_path);

// The block holding point p: inside (or on) every face plane of a convex
// block, within `tolerance` (m); the first such block, -1 if none.
int block_containing(const std::vector<Polyhedron>& blocks, const Vec3& p, double tolerance);

// Resolves an unset output schedule as in 2D: 1/20 of the run.
df::OutputSchedule resolve_output_schedule(df::OutputSchedule s, const Control3& control);

}  // namespace dda::df3
