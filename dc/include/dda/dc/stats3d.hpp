#pragma once
// Statistics of 3D blocks (`dda stats blocks3d.h5`): what an engineer reads
// before a forward run, counted per rock body (a non-convex body of several
// convex parts counts once).
#include <nlohmann/json.hpp>

#include "dda/common/polyhedron_model.hpp"

namespace dda::dc {

// Keys: dimension (3), bodies, blocks (convex parts), total_volume,
// domain_volume, excavated_volume, unfinished_cuts, volume{...},
// equivalent_diameter{...}, aspect{...}, faces{...} (distributions as in
// stats.hpp), removability {mode: count}, removable_volume, per_layer[...],
// definitions{...}.
nlohmann::json block_statistics_3d(const PolyhedronModel& model, int bins = 20);

}  // namespace dda::dc
