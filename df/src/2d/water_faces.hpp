#pragma once
// Joint water as loads on the blocks (private to DF; docs/formulation.md,
// "Joint water"). Each kernel finds the pairs of facing joint faces its
// contacts stand on, and the shared water component (dda/df/core/water.hpp)
// integrates the pore pressure over the part of them the two blocks share.
// The resultant pushes both blocks apart along the face normal: an equal
// and opposite pair of point loads at the centre of pressure, constant over
// the step (taken from the geometry at its start, as gravity is).
// This is the 2D kernel's finder; the 3D one is 3d/water_faces3d.hpp.
#include <vector>

#include "dda/df/2d/contact.hpp"
#include "dda/df/core/water.hpp"

namespace dda::df {

// 2D: the faces of the contacts (an edge of the edge block and an edge of
// the vertex block at the vertex, antiparallel within 10 degrees, and no
// further apart than `reach`), each pair once, their common stretch on the
// edge block's edge loaded with u times saturation[joint of the contact].
// Glued contacts (DC's artificial cuts) carry no water.
std::vector<WaterLoad<2>> water_loads_2d(const WaterTable<2>& water, const std::vector<double>& saturation,
                                         const std::vector<const Polygon2*>& blocks,
                                         const std::vector<Contact>& contacts, double reach);

}  // namespace dda::df
