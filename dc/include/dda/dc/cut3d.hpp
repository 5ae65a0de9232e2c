#pragma once
// DC in 3D: cuts the domain box of a FractureModel into convex polyhedral
// blocks with exact predicates (see dc/src/exact_plane.hpp), removes the
// excavations, and groups the convex parts of non-convex rock bodies.
//
// The order of work, and why:
//  1. Persistent planes (shape Plane, e.g. persistent sets, bed boundaries)
//     cut every block they cross.
//  2. Finite fractures (discs, polygons) separate rock only where they
//     reach right through it. Two ways (Cut3dOptions::finite_fractures):
//     - glue (default): a fracture splits every block its disc or polygon
//       reaches into; where it ends inside, the two parts stay glued as one
//       non-convex body. A body is separated once fractures (together) cut
//       it through, so intersecting finite fractures make blocks.
//     - through: a fracture cuts a block only if the block's whole section
//       lies on it, else leaves the block whole; passes repeat until
//       nothing changes, so the order of the fractures does not matter.
//       Every block is then convex, but a network of fractures smaller than
//       the blocks cuts nothing.
//     Fractures that end inside a body are counted in `unfinished_cuts`.
//  3. A closed-surface domain (STL/OBJ) keeps what lies inside it, and
//     excavations (convex regions or closed surfaces) remove what lies
//     inside them. A block partly inside keeps its parts as convex pieces
//     glued along kArtificialSet faces: one body (flagged exposed next to an
//     excavation).
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

enum class FiniteFractures { Glue, Through };

struct Cut3dOptions {
  FiniteFractures finite_fractures = FiniteFractures::Glue;
  // Faces of the domain that are free surfaces rather than rock that goes
  // on beyond the model, by name: the box's "x-", "x+", "y-", "y+", "z-",
  // "z+", and "surface" for the faces of a closed-surface domain that are
  // not on its bounding box. Default: the ground, "z+" and "surface".
  std::vector<std::string> free_boundaries{"z+", "surface"};
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
