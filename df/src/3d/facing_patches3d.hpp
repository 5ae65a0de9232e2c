#pragma once
// Where two blocks' faces lie on each other (private to DF): the patch of a
// face-to-face contact, the polygon both faces cover. The joint water loads
// it (water_faces3d.cpp) and the joint's bond spreads over it
// (simulation3d_bonds.cpp).
#include <cstddef>
#include <functional>
#include <vector>

#include "dda/df/3d/simulation3d.hpp"

namespace dda::df {

struct FacingPatch3 {
  std::size_t contact = 0;      // the contact that found it (index into the list given)
  int face_i = -1;              // the face of block i (the contact's i) ...
  Eigen::Vector3d normal{0, 0, 0};  // ... lying on face ids[1] of block j, whose outward unit normal this is
  std::vector<Eigen::Vector3d> polygon;  // in face j's plane, counter-clockwise seen along `normal`; >= 3 corners
};

// The faces of the vertex-face contacts that `accept` lets through: the face
// of block j and each face of block i at the vertex antiparallel to it within
// 10 degrees, all of whose corners lie within `reach` of its plane; each pair
// of faces once (found by its first contact); the patch is face i projected
// on face j's plane and clipped by face j (empty overlaps are left out).
// Edge-edge contacts add no patch: a face lying on a face has vertex-face
// contacts. Faces of the artificial set (cuts inside one rock body) are no
// joint and have none.
std::vector<FacingPatch3> facing_patches3(const std::vector<Polyhedron>& blocks,
                                          const std::vector<df3::Contact3>& contacts, double reach,
                                          const std::function<bool(const df3::Contact3&)>& accept);

// Area of a planar polygon (m^2).
double polygon_area3(const std::vector<Eigen::Vector3d>& polygon);

}  // namespace dda::df
