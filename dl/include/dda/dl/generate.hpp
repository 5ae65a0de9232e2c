#pragma once
// DL: the 2D line generator. Reads the DL sections of a scenario (domain,
// joint_sets, layering, excavations, lines, traces, geometry, points) and
// produces the LineModel that DC cuts, with a report of what was generated
// against what was asked.
#include <nlohmann/json.hpp>
#include <string>

#include "dda/common/line_model.hpp"
#include "dda/common/yaml_reader.hpp"

namespace dda::dl {

struct DlResult {
  LineModel model;
  nlohmann::json report;  // per set and per layer: asked vs realised (see report.hpp)
};

// `root` is the whole scenario (load_scenario). Provenance (scenario text,
// path, seed, version) is filled in.
DlResult generate_from_scenario(const YamlNode& root);

// A DDA-for-Windows geometry file (.geo, XML "DDAML" form) as a LineModel.
LineModel import_geo(const std::string& path);

// Human-readable table of the report, for the terminal.
std::string format_report(const nlohmann::json& report);

}  // namespace dda::dl
