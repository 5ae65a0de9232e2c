#pragma once
// The scenario's `points` list by name (private to DF), so that a problem
// with a point of the blocks file (outside every block, in a fixed block)
// names the scenario line that placed it, in 2D and 3D alike.
#include <optional>
#include <string>

#include "dda/common/yaml_reader.hpp"

namespace dda::df {

// The item of the scenario's `points` list with this name, if any.
std::optional<YamlNode> scenario_point(const YamlNode& root, const std::string& name);

}  // namespace dda::df
