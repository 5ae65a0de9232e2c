#pragma once
// DC in 3D: cuts the domain box of a FractureModel into convex polyhedral
// blocks with exact predicates (see dc/src/exact_plane.hpp), removes the
// excavations, and groups the convex parts of non-convex rock bodies.
//
// The order of work, and why:
//  1. Persistent planes (shape Plane, e.g. persistent sets, bed boundaries)
//     cut every block they cross.
//  2. Finite fractures (discs, polygons) cut a block only where they reach
//     right through it: every point of the block's section by the fracture
//     plane lies on the fracture. A fracture that ends inside a block leaves
//     it whole (that block stays convex; the fracture is counted in
//     `unfinished_cuts`). Since a cut by one fracture can make a smaller
//     block that another fracture then crosses completely, finite fractures
//     are passed over again until a pass cuts nothing, so the result does
//     not depend on the order of the fractures.
//  3. Excavations (convex regions) remove what lies inside them. A block
//     partly inside keeps the parts outside as convex pieces glued along
//     kArtificialSet faces: one body, flagged exposed.
//  4. Hole points remove the body that contains them.
//  5. Each exposed body is classified by block theory (removability.hpp).
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "dda/common/fracture_model.hpp"
#include "dda/common/polyhedron_model.hpp"
#include "dda/common/yaml_reader.hpp"

namespace dda::dc {

struct Cut3dOptions {
  // Faces of the domain box that are free surfaces rather than rock that
  // goes on beyond the model, by name: "x-", "x+", "y-", "y+", "z-", "z+".
  // Default: the ground surface "z+".
  std::vector<std::string> free_boundaries{"z+"};
  Vec3 gravity_direction{0, 0, -1};
  // Vertices closer than this (m) to a cutting plane count as on it, so
  // that planes meant to pass through one point or line do; a cut that
  // would leave a part thinner than this is not made. 0 = 1e-9 times the
  // domain's diagonal.
  double snap_tolerance = 0;
};

// The 3D keys of the `cutting:` section (absent = defaults).
Cut3dOptions parse_cut3d_options(const std::optional<YamlNode>& cutting);

struct Cut3dResult {
  PolyhedronModel model;
  nlohmann::json report;  // counts: planes, fractures, cuts, passes, unfinished, removed
};

Cut3dResult cut_blocks_3d(const FractureModel& fractures, const Cut3dOptions& options = {});

}  // namespace dda::dc
