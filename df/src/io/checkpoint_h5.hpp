#pragma once
// The /checkpoint group of a results file: the parts of a SimulationState
// that are not already in /steps (the log) and /series (the histories).
// Private to results_h5.cpp; the layout is in docs/formats.md.
#include "dda/common/h5_util.hpp"
#include "dda/df/2d/simulation.hpp"

namespace dda::df {

void write_checkpoint(h5::Writer& w, const SimulationState& s);

// Reads /checkpoint into `s` (log and histories are filled by the caller).
// `vertex_counts` gives the vertices of each block of the model.
void read_checkpoint(const h5::Reader& r, const std::vector<std::size_t>& vertex_counts, SimulationState& s);

}  // namespace dda::df
