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
#include "dda/df/2d/model.hpp"
#include "dda/df/core/types.hpp"

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

// T^T f: the block's generalised force of a force f at p, or the gradient
// of f . u(p) with respect to the block's unknowns; the _arm form takes
// p - centroid. Written out (inline), as contact geometry needs five of them
// per contact per step (and the open-close iterates form three of them from
// the arms a contact keeps): forming T first made contact_geometry 5.6 % of
// a 10k-block step at rest, not 3.4 %.
inline Vector6d t_transpose_times_arm(const Vec2& arm, const Vec2& f) {
  const double X = arm.x(), Y = arm.y();
  Vector6d g;
  g << f.x(), f.y(), X * f.y() - Y * f.x(), X * f.x(), Y * f.y(), 0.5 * (Y * f.x() + X * f.y());
  return g;
}
inline Vector6d t_transpose_times(const Vec2& centroid, const Vec2& p, const Vec2& f) {
  return t_transpose_times_arm(p - centroid, f);
}

// M = rho * integral of T^T T over the block.
Matrix6d mass_matrix(const BlockGeometry& g, double density);

// Plane stress or plane strain elasticity matrix (engineering shear strain).
Matrix3d elastic_matrix(const Material& m);

// New position of point p after the step increment d, with the rotation
// applied exactly (cos/sin of r0) instead of its linearisation -r0*Y, r0*X,
// so a spinning block keeps its area; the strain part stays linear.
Vec2 move_point(const Vec2& centroid, const Vector6d& d, const Vec2& p);

// The stress tensor [sx, sy, txy] turned with its block by `angle` (rad,
// counter-clockwise): sigma' = R sigma R^T. An accepted step turns the
// accumulated stress by the step's rotation r0 before adding E * strain, so
// a block that turns over carries its stress with it (a block loaded along
// x and turned by 90 degrees is loaded along y).
Vector3d rotate_stress(const Vector3d& stress, double angle);

}  // namespace dda::df
