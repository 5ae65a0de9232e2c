#pragma once
// The displacement field of one 3D block and the 12x12 matrices that follow
// from it (docs/formulation.md, "3D"): the first increment of the 3D solver.
//
// Namespace dda::df3, not dda::df: the 2D vocabulary (kDofs = 6, Vector6d as
// the block unknowns, Material with a plane mode) would clash.
//
// Unknowns per block, about the centroid c:
//   d = [u0, v0, w0, rx, ry, rz, ex, ey, ez, gyz, gzx, gxy]
// and with X = x - c a point moves by u = u0 + r x X + E X, E the symmetric
// strain tensor (engineering shears enter halved). So u = T(x) d with
//   T = | 1 0 0   0  Z -Y   X 0 0   0  Z/2 Y/2 |
//       | 0 1 0  -Z  0  X   0 Y 0  Z/2  0  X/2 |
//       | 0 0 1   Y -X  0   0 0 Z  Y/2 X/2  0  |
// Every entry has degree <= 1 in X, so block integrals of products need only
// the volume and the second moments about the centroid (first moments vanish
// there): the mass matrix is exact for any polyhedron, convex or not.
#include <Eigen/Core>
#include <vector>

#include "dda/common/geometry3d.hpp"
#include "dda/common/polyhedron_model.hpp"

namespace dda::df3 {

constexpr int kDofs = 12;  // unknowns per 3D block

using Vector12d = Eigen::Matrix<double, kDofs, 1>;
using Matrix12d = Eigen::Matrix<double, kDofs, kDofs>;
using Matrix3x12d = Eigen::Matrix<double, 3, kDofs>;
using Vector6d = Eigen::Matrix<double, 6, 1>;  // stress or strain [xx, yy, zz, yz, zx, xy]
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Matrix3d = Eigen::Matrix3d;

// Offsets of the three groups of unknowns in d.
constexpr int kTranslation = 0, kRotation = 3, kStrain = 6;

struct Material3 {
  double density = 2600;  // kg/m^3
  double young = 1e9;     // Pa
  double poisson = 0.25;
};

// Volume and second moment about the centroid (current configuration).
struct BlockGeometry3 {
  double volume = 0;
  Vec3 centroid{0, 0, 0};
  Matrix3d second_moment = Matrix3d::Zero();  // integral of X X^T dV
};

// As stored in the polyhedron (DC computes them exactly).
BlockGeometry3 block_geometry(const Polyhedron& p);
// Recomputed from moved vertices (faces as in Polyhedron, outward loops).
BlockGeometry3 block_geometry(const std::vector<Vec3>& vertices, const std::vector<PolyFace>& faces);
// Volume, centroid, second moment and face normals (Newell, outward for the
// stored loop order) recomputed from the vertices.
void refresh_geometry(Polyhedron& p);

// T at point x of a block whose centroid is `centroid`.
Matrix3x12d displacement_matrix(const Vec3& x, const Vec3& centroid);

// M = rho * integral of T^T T over the block.
Matrix12d mass_matrix(const BlockGeometry3& g, double density);

// Isotropic elasticity, engineering shear strains:
// sigma = D [ex, ey, ez, gyz, gzx, gxy].
Matrix6d elastic_matrix(const Material3& m);
// K_e = V B^T D B, B picking the strain unknowns 6..11 (constant strain).
Matrix12d elastic_stiffness(const BlockGeometry3& g, const Material3& m);

// Contributions to one block's K (12x12) and F (12), in the sign convention
// of the 2D df/src/2d/block_terms.cpp.

// Inertia, constant acceleration in the step: K += 2/dt^2 M, F += 2/dt M v0.
void add_inertia(const BlockGeometry3& g, double density, const Vector12d& velocity, double dt, Matrix12d& k,
                 Vector12d& f);
// Elasticity and the stress carried from earlier steps
// ([sx, sy, sz, tyz, tzx, txy]): K += V D on the strains, F -= V sigma.
// `damping` = beta / dt of the viscous damping (damping.hpp; 0 for none):
// its stress beta D de/dt at the step's mean strain rate adds damping V D.
void add_elasticity(const BlockGeometry3& g, const Material3& m, const Vector6d& stress, double damping,
                    Matrix12d& k, Vector12d& f);
// Body force b (m/s^2): F += rho V b on the translations only.
void add_body_force(const BlockGeometry3& g, double density, const Vec3& b, Vector12d& f);
// Constant force P at point x: F += T(x)^T P.
void add_point_load(const BlockGeometry3& g, const Vec3& x, const Vec3& force, Vector12d& f);
// Penalty spring p pulling point x by `gap` (fixed or moving point):
// energy p/2 |T d - gap|^2, so K += p T^T T, F += p T^T gap.
void add_point_spring(const BlockGeometry3& g, const Vec3& x, const Vec3& gap, double p, Matrix12d& k,
                      Vector12d& f);

// Rotation by angle |r| about r/|r| (Rodrigues); identity for r = 0.
Matrix3d rotation_matrix(const Vec3& r);

// New position of point x after the step increment d, with the rotation
// applied exactly instead of its linearisation r x X, so a spinning block
// keeps its volume; the strain part stays linear:
//   x' = c + u0 + R(r) X + E X.
Vec3 move_point(const Vec3& centroid, const Vector12d& d, const Vec3& x);

}  // namespace dda::df3
