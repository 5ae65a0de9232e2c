#pragma once
// A 3D blocks model embedded as a group of another HDF5 file: the 3D results
// file keeps the blocks its run started from under /model, laid out exactly
// as a dda-blocks3d file (model_io3d.hpp) is at its root, the file's identity
// attributes (format, provenance, volumes) on the group.
//
// Includes <hdf5.h> through h5_util.hpp: only for libraries that link HDF5
// themselves (see h5_util.hpp).
#include <string>

#include "dda/common/h5_util.hpp"
#include "dda/common/polyhedron_model.hpp"

namespace dda {

// Creates the group `group` below the root (e.g. "model") and writes the model into it.
void write_polyhedra_group(h5::Writer& w, const std::string& group, const PolyhedronModel& model);
// Reads it back; InputError naming the file for anything missing or wrong.
PolyhedronModel read_polyhedra_group(const h5::Reader& r, const std::string& group);

}  // namespace dda
