#pragma once
// Fracture intensity of a disc network (Dershowitz & Herda 1992 notation):
// P10 discs crossed per unit length of a scan line, P21 trace length per unit
// area of a sampling plane, P32 fracture area per unit volume. All exact (no
// sampling), so they can check a generator against stereology: for uniformly
// oriented discs, P10 = P32 / 2 and P21 = (pi / 4) P32.
#include <Eigen/Core>
#include <vector>

#include "dda/dl/dfn3d.hpp"

namespace dda::dl {

// Area of the part of the disc inside the box, exactly: the box cuts the
// disc's plane in a convex polygon, and the area of a circle and a convex
// polygon is a sum of circle-triangle areas over the polygon's edges.
double disc_area_in_box(const Disc& disc, const Box3& box);

// Sum of disc_area_in_box over the discs divided by the box volume.
double p32_in_box(const std::vector<Disc>& discs, const Box3& box);

// Discs the segment [a, b] meets (it meets the disc's plane at a point within
// the radius of the centre; a segment in the disc's plane, a null-measure
// case, is not counted) divided by its length; InputError if a == b.
double p10_along(const std::vector<Disc>& discs, const Eigen::Vector3d& a, const Eigen::Vector3d& b);

// A sampling rectangle: origin + s e1 + t e2, s, t in [0, 1], e1 and e2
// orthogonal and non-zero.
struct Rectangle3 {
  Eigen::Vector3d origin{0, 0, 0};
  Eigen::Vector3d e1{1, 0, 0};
  Eigen::Vector3d e2{0, 1, 0};
};

// Length of the chords the discs cut in the rectangle's plane, clipped to the
// rectangle, divided by its area (discs parallel to the plane leave no trace);
// InputError if e1 or e2 is zero or they are not orthogonal.
double p21_on(const std::vector<Disc>& discs, const Rectangle3& rect);

}  // namespace dda::dl
