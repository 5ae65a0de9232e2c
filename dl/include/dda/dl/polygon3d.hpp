#pragma once
// Planar convex polygons in 3D: the geometry that polygon fractures, layered
// joints and trace planes share (clip to half-spaces, cut a plane with a box,
// area and centroid).
//
// A Polygon3 is a vertex list without a repeated closing vertex; "counter-
// clockwise about n" means its vector area (Newell) points along n.
#include <vector>

#include "dda/common/geometry3d.hpp"

namespace dda::dl {

using Polygon3 = std::vector<Vec3>;

// The part of the convex polygon inside the closed half-space
// (Sutherland-Hodgman for one plane; the orientation is kept). Vertices within
// `tol` (absolute, metres) of the plane count as on it, so a polygon touching
// the plane does not gain a sliver.
Polygon3 clip_polygon(const Polygon3& poly, const HalfSpace& h, double tol = 0);
// The same for every half-space of a convex region.
Polygon3 clip_polygon(const Polygon3& poly, const ConvexRegion& region, double tol = 0);

// The convex polygon where the plane normal . x = offset (unit normal) cuts
// the box, counter-clockwise about `normal`; empty if it misses the box or
// only touches it at an edge or corner.
Polygon3 plane_in_box(const Vec3& normal, double offset, const Box3& box);

// Vector area (Newell): half the sum of p_i x p_{i+1}; its norm is the area and
// its direction the normal about which the polygon is counter-clockwise.
Vec3 vector_area(const Polygon3& poly);
double polygon_area(const Polygon3& poly);
// Area centroid (the vertex mean for fewer than three vertices or no area).
Vec3 polygon_centroid(const Polygon3& poly);

// Drops vertices within `tol` of their predecessor (and a last vertex within
// `tol` of the first), as clipping through a vertex leaves them.
void remove_duplicate_vertices(Polygon3& poly, double tol);

// The area of the polygon inside the box (exact: the polygon clipped to the box).
double polygon_area_in_box(const Polygon3& poly, const Box3& box);

}  // namespace dda::dl
