#pragma once
// The 3D stages as the commands use them (the 2D ones are in pipeline.hpp).
#include <string>

#include "dda/common/fracture_model.hpp"
#include "dda/common/polyhedron_model.hpp"
#include "dda/dc/cut3d.hpp"

namespace dda::cli {

// The `cutting:` section of the scenario stored in a fractures file, if any,
// read with the 3D keys.
dc::Cut3dOptions cut3d_options_of(const FractureModel& fractures);

// One line describing a 3D cut: bodies, parts, volume, and where it went.
std::string describe_cut3d(const PolyhedronModel& blocks, const std::string& path);

// The terminal summary of `dda stats` on a 3D blocks file.
std::string format_statistics_3d(const nlohmann::json& st);

}  // namespace dda::cli
