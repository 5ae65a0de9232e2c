#pragma once
// Block theory for one body (Goodman & Shi 1985): can it translate out of
// the rock mass, and in which mode does gravity move it?
//
// The faces a body shares with other rock (outward unit normals n_i, from
// the body towards its neighbour) stop any translation d with d . n_i > 0
// for some i. The body is removable if a d != 0 exists with d . n_i <= 0
// for every i: a closed convex cone that is not {0}. Its extreme rays lie on the n_i or on the lines n_i x n_j, so
// those candidates decide the question exactly (up to `tol`). Under gravity
// g the mode is, in order: lifting (g itself is admissible: the body falls),
// sliding on one face i (g projected on face i, where g . n_i > 0), sliding
// on two faces i, j (along +/- n_i x n_j, the sign with a downward
// component), else the body is removable but gravity alone holds it.
#include <vector>

#include "dda/common/geometry3d.hpp"
#include "dda/common/polyhedron_model.hpp"

namespace dda::dc {

struct RemovabilityResult {
  Removability mode = Removability::NotExposed;
  Vec3 direction{0, 0, 0};  // unit: the fall or sliding direction, when gravity moves the body
  std::vector<int> sliding_faces;  // indices into the normals for SlidesOne / SlidesTwo
};

// `contact_normals`: outward unit normals of the body's faces against rock;
// `exposed`: whether the body has a free face at all; `gravity`: unit.
RemovabilityResult classify_removability(const std::vector<Vec3>& contact_normals, bool exposed,
                                         const Vec3& gravity, double tol = 1e-9);

}  // namespace dda::dc
