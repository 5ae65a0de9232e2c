#pragma once
// The scenario's `water` section, 2D and 3D (private to DF; keys in
// docs/scenario.md): a phreatic surface and the unit weight of water. The
// per-set saturation is a key of `joints` (scenario_joints.cpp).
#include <optional>

#include "dda/common/yaml_reader.hpp"
#include "dda/df/core/water.hpp"

namespace dda::df {

// None when the scenario has no `water`; InputError naming the file, line
// and key for anything wrong in it.
template <int dim>
std::optional<WaterTable<dim>> read_water(const YamlNode& root);

}  // namespace dda::df
