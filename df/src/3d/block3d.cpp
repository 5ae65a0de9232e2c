// 3D block displacement field, mass and elasticity matrices, block terms and
// the exact rotation update (docs/formulation.md, "3D").
#include "dda/df/3d/block3d.hpp"

#include <cmath>

namespace dda::df3 {

BlockGeometry3 block_geometry(const Polyhedron& p) { return {p.volume, p.centroid, p.second_moment}; }

BlockGeometry3 block_geometry(const std::vector<Vec3>& vertices, const std::vector<PolyFace>& faces) {
  std::vector<std::vector<int>> loops;
  loops.reserve(faces.size());
  for (const auto& f : faces) loops.push_back(f.vertices);
  const PolyhedronMoments m = polyhedron_moments(vertices, loops);
  return {m.volume, m.centroid, m.second_moment};
}

Matrix3x12d displacement_matrix(const Vec3& x, const Vec3& centroid) {
  const double X = x.x() - centroid.x(), Y = x.y() - centroid.y(), Z = x.z() - centroid.z();
  Matrix3x12d t;
  // Columns: translation | r x X | E X with E built from the engineering
  // strains (shears halved, so gxy is the full change of the right angle).
  t << 1, 0, 0,  0, Z, -Y,  X, 0, 0,  0, Z / 2, Y / 2,
       0, 1, 0,  -Z, 0, X,  0, Y, 0,  Z / 2, 0, X / 2,
       0, 0, 1,  Y, -X, 0,  0, 0, Z,  Y / 2, X / 2, 0;
  return t;
}

Matrix12d mass_matrix(const BlockGeometry3& g, double density) {
  // T = A0 + sum_k A_k X_k is affine in X, so
  //   integral T^T T = V A0^T A0 + sum_kl S_kl A_k^T A_l,
  // the A0-A_k cross terms dropping out with the first moments. The A's are
  // read off displacement_matrix itself, so M cannot disagree with T.
  const Vec3 c = g.centroid;
  const Matrix3x12d a0 = displacement_matrix(c, c);
  Matrix3x12d a[3];
  for (int k = 0; k < 3; ++k) a[k] = displacement_matrix(c + Vec3::Unit(k), c) - a0;
  Matrix12d m = g.volume * a0.transpose() * a0;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) m += g.second_moment(k, l) * a[k].transpose() * a[l];
  // S is symmetric; make M exactly so (eval: m appears on both sides).
  return density * (0.5 * (m + m.transpose())).eval();
}

Matrix6d elastic_matrix(const Material3& m) {
  const double e = m.young, nu = m.poisson;
  const double lambda = e * nu / ((1 + nu) * (1 - 2 * nu)), mu = e / (2 * (1 + nu));
  Matrix6d d = Matrix6d::Zero();
  d.topLeftCorner<3, 3>().setConstant(lambda);
  d.topLeftCorner<3, 3>().diagonal().array() += 2 * mu;
  d.bottomRightCorner<3, 3>().diagonal().setConstant(mu);  // engineering shear: tau = mu gamma
  return d;
}

Matrix12d elastic_stiffness(const BlockGeometry3& g, const Material3& m) {
  // Constant strain in the block: energy V/2 e^T D e on the strain unknowns.
  Matrix12d k = Matrix12d::Zero();
  k.block<6, 6>(kStrain, kStrain) = g.volume * elastic_matrix(m);
  return k;
}

void add_inertia(const BlockGeometry3& g, double density, const Vector12d& velocity, double dt, Matrix12d& k,
                 Vector12d& f) {
  // Constant acceleration a = 2 (d - v0 dt) / dt^2 within the step: the
  // inertia force M a gives K += 2/dt^2 M and F += 2/dt M v0.
  const Matrix12d m = mass_matrix(g, density);
  k += (2.0 / (dt * dt)) * m;
  f += (2.0 / dt) * (m * velocity);
}

void add_elasticity(const BlockGeometry3& g, const Material3& m, const Vector6d& stress, double damping,
                    Matrix12d& k, Vector12d& f) {
  k += (1.0 + damping) * elastic_stiffness(g, m);
  // The stress already carried does work V sigma^T e in the step, so the
  // potential gains +V sigma^T e and its minimum moves F by -V sigma: the
  // same sign as 2D (block_terms.cpp: rhs.tail<3>() -= area * stress).
  // Tension positive; sigma pairs with engineering shears (tyz with gyz).
  f.segment<6>(kStrain) -= g.volume * stress;
}

void add_body_force(const BlockGeometry3& g, double density, const Vec3& b, Vector12d& f) {
  // integral of T^T rho b: the rotation and strain columns are linear in X
  // and integrate to zero about the centroid, leaving rho V b.
  f.segment<3>(kTranslation) += density * g.volume * b;
}

void add_point_load(const BlockGeometry3& g, const Vec3& x, const Vec3& force, Vector12d& f) {
  f += displacement_matrix(x, g.centroid).transpose() * force;
}

void add_point_spring(const BlockGeometry3& g, const Vec3& x, const Vec3& gap, double p, Matrix12d& k,
                      Vector12d& f) {
  const Matrix3x12d t = displacement_matrix(x, g.centroid);
  k += p * t.transpose() * t;
  f += p * t.transpose() * gap;
}

Matrix3d rotation_matrix(const Vec3& r) {
  const double angle = r.norm();
  if (angle == 0) return Matrix3d::Identity();
  const Vec3 n = r / angle;
  Matrix3d nx;
  nx << 0, -n.z(), n.y(), n.z(), 0, -n.x(), -n.y(), n.x(), 0;
  // Rodrigues: R = I + sin(a) [n]x + (1 - cos(a)) [n]x^2; orthogonal to
  // rounding for any angle, unlike I + [r]x.
  return Matrix3d::Identity() + std::sin(angle) * nx + (1 - std::cos(angle)) * nx * nx;
}

Vec3 move_point(const Vec3& centroid, const Vector12d& d, const Vec3& x) {
  const Vec3 rel = x - centroid;
  // The strain part E X is exactly the strain columns of T.
  Vector12d strain_only = Vector12d::Zero();
  strain_only.segment<6>(kStrain) = d.segment<6>(kStrain);
  const Vec3 strained = displacement_matrix(x, centroid) * strain_only;
  return centroid + d.segment<3>(kTranslation) + rotation_matrix(d.segment<3>(kRotation)) * rel + strained;
}

void refresh_geometry(Polyhedron& p) {
  const BlockGeometry3 g = block_geometry(p.vertices, p.faces);
  p.volume = g.volume;
  p.centroid = g.centroid;
  p.second_moment = g.second_moment;
  for (auto& f : p.faces) {
    Vec3 n(0, 0, 0);
    for (size_t k = 0; k < f.vertices.size(); ++k)
      n += p.vertices[f.vertices[k]].cross(p.vertices[f.vertices[(k + 1) % f.vertices.size()]]);
    f.normal = n.normalized();
  }
}

}  // namespace dda::df3
