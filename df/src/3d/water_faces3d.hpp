#pragma once
// Joint water as loads on the blocks (private to DF; docs/formulation.md,
// "Joint water"). Each kernel finds the pairs of facing joint faces its
// contacts stand on, and the shared water component (dda/df/core/water.hpp)
// integrates the pore pressure over the part of them the two blocks share.
// The resultant pushes both blocks apart along the face normal: an equal
// and opposite pair of point loads at the centre of pressure, constant over
// the step (taken from the geometry at its start, as gravity is).
// This is the 3D kernel's finder; the 2D one is 2d/water_faces.hpp.
#include <vector>

#include "dda/df/3d/simulation3d.hpp"
#include "dda/df/core/water.hpp"

namespace dda::df {

// 3D: the faces of the vertex-face contacts (the face of block j and the
// faces of block i at the vertex antiparallel to it within 10 degrees, all
// of whose corners lie within `reach` of its plane), each pair once; the
// polygon both cover (face i projected on face j's plane, clipped by face
// j) is loaded with u times saturation[joint of the contact]. Edge-edge
// contacts add no pair: a face lying on a face has vertex-face contacts.
// Faces of the artificial set (cuts inside one rock body) carry no water.
std::vector<WaterLoad<3>> water_loads_3d(const WaterTable<3>& water, const std::vector<double>& saturation,
                                         const std::vector<Polyhedron>& blocks,
                                         const std::vector<df3::Contact3>& contacts, double reach);

}  // namespace dda::df
