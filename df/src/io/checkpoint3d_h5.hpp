#pragma once
// The /checkpoint group of a 3D results file: the parts of a
// SimulationState3 that are not already in /steps (the log) and /series
// (the histories). Private to results3d_h5.cpp; layout in docs/formats.md.
#include <vector>

#include "dda/common/h5_util.hpp"
#include "dda/df/3d/simulation3d.hpp"

namespace dda::df3 {

void write_checkpoint3(h5::Writer& w, const SimulationState3& s);

// Reads /checkpoint (log and histories are the caller's). `vertex_counts`
// gives the vertices of each block of the model.
SimulationState3 read_checkpoint3(const h5::Reader& r, const std::vector<std::size_t>& vertex_counts);

}  // namespace dda::df3
