#pragma once
// DL in 3D from a scenario: `dimension: 3` selects it. Reads the 3D sections
// (domain, fracture_sets, persistent_sets, planes, layering, fracture_files,
// excavations, points, trace_planes; docs/scenario.md, "3D scenarios") and
// makes the FractureModel that the fractures file stores, with a report of
// what was generated against what was asked.
//
// Sets are numbered in the order fracture_sets, persistent_sets, planes (one
// set per plane, named after it), layering (its joint sets, then the bedding
// set), fracture_files (the files' sets in file order). Streams: fracture set
// i draws from Stream(seed, "dfn3d.set", i), persistent set i from
// Stream(seed, "persistent3d.set", i), layering as generate_layering3d does.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dda/common/fracture_model.hpp"
#include "dda/common/yaml_reader.hpp"

namespace dda::dl {

// A section plane the scenario asks for (`trace_planes`), checked to cross the
// domain; its frame is trace_frame(point, dip_deg, dip_direction_deg).
struct TracePlaneSpec {
  std::string name;  // letters, digits, '_' and '-' only: it becomes part of a file name
  Vec3 point{0, 0, 0};
  double dip_deg = 0;
  double dip_direction_deg = 0;
};

struct DlResult3 {
  FractureModel model;
  nlohmann::json report;  // see docs/scenario.md, "The 3D DL report"
  std::vector<TracePlaneSpec> trace_planes;
};

// The scenario's `dimension` (default 2); an InputError naming the key unless
// it is 2 or 3.
int scenario_dimension(const YamlNode& root);

// `root` is the whole scenario (load_scenario) with dimension 3. Provenance
// (scenario text, path, seed, version) is filled in.
DlResult3 generate_3d_from_scenario(const YamlNode& root);

// Human-readable tables of the 3D report, for the terminal.
std::string format_report3(const nlohmann::json& report);

}  // namespace dda::dl
