#pragma once
// The displacement field of one 2D block and the matrices that follow from it.
//
// With (X, Y) = (x - x0, y - y0) relative to the centroid, a point of the block
// moves by u = T(x, y) d with
//   T = | 1  0  -Y  X  0  Y/2 |
//       | 0  1   X  0  Y  X/2 |
// Every entry is a polynomial of degree <= 1 in (X, Y), so block integrals of
// products of entries need only the area and the second moments about the
// centroid (first moments vanish there): the mass matrix is exact for any
// polygon, convex or not.
#include "dda/df/model.hpp"
#include "dda/df/types.hpp"

namespace dda::df {

// Area and second moments about the centroid (current configuration).
struct BlockGeometry {
  double area = 0;
  Vec2 centroid{0, 0};
  double sxx = 0, syy = 0, sxy = 0;
};

BlockGeometry block_geometry(const Polygon2& vertices);

// T at point p of a block whose centroid is `centroid`.
Matrix26d t_matrix(const Vec2& centroid, const Vec2& p);

// M = rho * integral of T^T T over the block.
Matrix6d mass_matrix(const BlockGeometry& g, double density);

// Plane stress or plane strain elasticity matrix (engineering shear strain).
Matrix3d elastic_matrix(const Material& m);

// New position of point p after the step increment d, with the rotation
// applied exactly (cos/sin of r0) instead of its linearisation -r0*Y, r0*X,
// so a spinning block keeps its area; the strain part stays linear.
Vec2 move_point(const Vec2& centroid, const Vector6d& d, const Vec2& p);

}  // namespace dda::df
