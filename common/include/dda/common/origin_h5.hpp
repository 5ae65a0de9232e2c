#pragma once
// The local origin of a model (coordinate_range.hpp) in the pipeline's
// HDF5 files: float64 attributes origin_x, origin_y (and origin_z in 3D) on
// the object that carries the file's identity (the root, or /model of a 3D
// results file). They are written only when the origin is not zero, so a
// model near the origin writes the same file as before local origins, and a
// file without them (written before, or near the origin) means origin 0.
#include "dda/common/geometry.hpp"
#include "dda/common/geometry3d.hpp"
#include "dda/common/h5_util.hpp"

namespace dda::io {

void write_origin(h5::Writer& w, hid_t obj, const Vec2& origin);
void write_origin(h5::Writer& w, hid_t obj, const Vec3& origin);
// InputError naming the file for an origin that is not finite or beyond
// kFarthestCoordinate. `where` names `obj` in messages ("the file", "/model").
Vec2 read_origin2(const h5::Reader& r, hid_t obj, const std::string& where = "the file");
Vec3 read_origin3(const h5::Reader& r, hid_t obj, const std::string& where = "the file");

}  // namespace dda::io
