#pragma once
// P10 and P21 of any 3D fractures (planes, discs, convex polygons), exactly,
// as dfn3d_measures.hpp gives them for discs alone: the scenario report
// measures every set, whatever made it, on the same scan lines and planes.
// (P32 of fractures is p32_in_box in fractures3d.hpp.)
#include <vector>

#include "dda/common/fracture_model.hpp"
#include "dda/dl/dfn3d_measures.hpp"  // Rectangle3

namespace dda::dl {

// Does the segment [a, b] meet the fracture? A plane is met when the segment
// crosses it; a disc or polygon when the crossing point lies on it. A
// segment lying in the fracture's plane (a null-measure case) does not count.
bool segment_meets(const Fracture3& f, const Vec3& a, const Vec3& b);

// Fractures the segment [a, b] meets divided by its length; InputError if a == b.
double p10_along(const std::vector<Fracture3>& fractures, const Vec3& a, const Vec3& b);

// Length of the fracture's trace on the rectangle (its chord in the
// rectangle's plane clipped to the rectangle); 0 for a fracture parallel to
// the plane. The rectangle must have orthogonal non-zero sides (not checked
// here; p21_on checks).
double trace_length_on(const Fracture3& f, const Rectangle3& rect);

// Sum of trace_length_on over the fractures divided by the rectangle's area;
// InputError if e1 or e2 is zero or they are not orthogonal.
double p21_on(const std::vector<Fracture3>& fractures, const Rectangle3& rect);

}  // namespace dda::dl
