#pragma once
// HDF5 files of the 3D pipeline: fractures (DL -> DC) and polyhedral blocks
// (DC -> DF), the 3D counterparts of model_io.hpp's lines and blocks.
//
// Both are self-describing like the 2D files: root attributes `format`
// ("dda-fractures" or "dda-blocks3d"), `format_version`, `units`,
// `program_version`, `scenario_path`, `scenario`, `seed`, `created_utc`.
// Variable-length data (polygon fractures, excavation half-spaces, block
// vertices and faces, body parts) is stored flat with offsets. Every dataset
// is documented in docs/formats.md. Writes are atomic; h5_format_of
// (model_io.hpp) names these formats too. A file that is missing, not HDF5,
// not of the expected format or inconsistent is an InputError naming the file.
#include <string>

#include "dda/common/fracture_model.hpp"
#include "dda/common/polyhedron_model.hpp"

namespace dda {

inline constexpr const char* kFracturesFormat = "dda-fractures";
inline constexpr const char* kBlocks3dFormat = "dda-blocks3d";

void write_fractures_h5(const std::string& path, const FractureModel& model);
FractureModel read_fractures_h5(const std::string& path);

void write_polyhedra_h5(const std::string& path, const PolyhedronModel& model);
PolyhedronModel read_polyhedra_h5(const std::string& path);

}  // namespace dda
