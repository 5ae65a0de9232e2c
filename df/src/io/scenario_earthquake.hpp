#pragma once
// The scenario's loading.earthquake entry (private to DF; keys, units and
// defaults in docs/scenario.md, the physics in core/ground_motion.hpp and
// 2d/ground_motion.hpp).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dda/common/yaml_reader.hpp"
#include "dda/df/2d/ground_motion.hpp"
#include "io/scenario_record.hpp"

namespace dda::df {

// The viscous boundary edges of each side of boundaries.viscous, by index
// into ModelInput::viscous_boundary->edges.
using ViscousSides = std::map<std::string, std::vector<std::size_t>>;

struct EarthquakeEntry {
  YamlNode node;                           // loading.earthquake, for messages
  EarthquakeRecord<2> record;              // the mode, and the motion read and processed
  // Fixed point names or sides (bottom, top, left, right: the fixed.boundary
  // points of that side) with their nodes; none: every fixed point. In the
  // incident mode: the sides of boundaries.viscous the wave enters through
  // (none: bottom).
  std::optional<std::vector<std::pair<YamlNode, std::string>>> foundation;
};

// Checks every key and reads the record; InputError with the scenario file,
// line and key path (and the record file and line for a bad record).
EarthquakeEntry read_earthquake(const YamlNode& node);

// Puts the motion into the model input, once every fixed point (named and
// boundary ones) and the viscous boundary are in `in`. `boundary_sides`: the
// sides of fixed.boundary; `viscous`: the edges of boundaries.viscous.
void apply_earthquake(const EarthquakeEntry& e, const std::vector<std::string>& boundary_sides,
                      const ViscousSides& viscous, ModelInput& in);

}  // namespace dda::df
