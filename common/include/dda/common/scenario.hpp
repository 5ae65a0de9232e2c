#pragma once
// The scenario file: one YAML document describing the whole job.
//
// Each stage parses the sections it owns (DL: domain, joint_sets, layering,
// excavations, lines, traces, geometry, points; DC: cutting; tools: output).
// This header holds what they share: the list of top-level sections, so that
// a misspelt section is reported whichever stage reads the file, and the
// resolution of file paths relative to the scenario.
#include <cstdint>
#include <string>
#include <vector>

#include "dda/common/yaml_reader.hpp"

namespace dda {

// Every top-level key a scenario may hold. A stage that adds a section adds
// its name here (and documents it in docs/scenario.md).
const std::vector<std::string>& scenario_sections();

// Loads a scenario and checks its top-level keys.
YamlNode load_scenario(const std::string& path);
// The same for a scenario held in memory (a study's case, built from its
// base); `file_label` names it in messages and is the folder relative paths
// start from, as if the text were that file.
YamlNode load_scenario_text(const std::string& text, const std::string& file_label);

// `seed` at the top level (default 1): the one seed every random generator
// of the job derives its streams from.
std::uint64_t scenario_seed(const YamlNode& root);

// A path written in the scenario is relative to the scenario's folder.
std::string resolve_scenario_path(const YamlNode& node, const std::string& relative);

}  // namespace dda
