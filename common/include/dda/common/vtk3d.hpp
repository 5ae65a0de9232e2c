#pragma once
// ParaView output of the 3D pipeline (.vtu, VTK XML UnstructuredGrid; the
// 2D files are in vtk.hpp). Layouts in docs/formats.md.
#include <string>

#include "dda/common/fracture_model.hpp"
#include "dda/common/polyhedron_model.hpp"

namespace dda {

// Sides of the polygon that stands for a disc fracture.
inline constexpr int kDiscPolygonSides = 48;

// One VTK_POLYGON cell per fracture: a disc as a regular 48-gon, a polygon
// as itself, a plane clipped to the domain box (a plane that misses the box,
// or any fracture with a zero normal, gives no cell). Cell data: set, kind,
// shape, layer, fracture_id (index into model.fractures). Then one
// VTK_TRIANGLE per triangle of the domain's surface (set -1) and of the
// excavations' surfaces (set -2), with shape 3 and fracture_id -1.
void write_fractures_vtu(const std::string& path, const FractureModel& model);

// One VTK_POLYHEDRON cell per block. Cell data: block_id, body, volume,
// layer, removability (the code of the block's body, -1 if it has none).
void write_polyhedra_vtu(const std::string& path, const PolyhedronModel& model);

}  // namespace dda
