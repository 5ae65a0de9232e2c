#pragma once
// The scenario's loading.earthquake entry (private to DF; keys, units and
// defaults in docs/scenario.md, the physics in ground_motion.hpp).
#include <optional>
#include <string>
#include <vector>

#include "dda/common/yaml_reader.hpp"
#include "dda/df/ground_motion.hpp"

namespace dda::df {

struct EarthquakeEntry {
  YamlNode node;                           // loading.earthquake, for messages
  std::string mode = "loading";
  GroundMotionSpec spec;                   // path resolved against the scenario's folder
  GroundMotion motion;                     // read and processed (so bad records fail early)
  // Fixed point names or sides (bottom, top, left, right: the fixed.boundary
  // points of that side) with their nodes; none: every fixed point.
  std::optional<std::vector<std::pair<YamlNode, std::string>>> foundation;
};

// Checks every key and reads the record; InputError with the scenario file,
// line and key path (and the record file and line for a bad record).
EarthquakeEntry read_earthquake(const YamlNode& node);

// Puts the motion into the model input, once every fixed point (named and
// boundary ones) is in `in`. `boundary_sides`: the sides of fixed.boundary.
void apply_earthquake(const EarthquakeEntry& e, const std::vector<std::string>& boundary_sides, ModelInput& in);

}  // namespace dda::df
