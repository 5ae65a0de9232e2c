// Block and point terms of the step system (docs/formulation.md, "Global system").
#include "2d/block_terms.hpp"

namespace dda::df {

void add_block_terms(int i, const BlockState& b, const Material& mat, const Matrix3d& emat, const Vec2& gravity,
                     double dt, double beta, BlockSystem& sys) {
  const BlockGeometry& g = b.geometry;
  const Matrix6d m = mass_matrix(g, mat.density);
  // Constant acceleration a = 2 (d - v0 dt) / dt^2 within the step: the
  // inertia force M a gives K += 2/dt^2 M and F += 2/dt M v0.
  sys.diagonal(i) += (2.0 / (dt * dt)) * m;
  sys.rhs(i) += (2.0 / dt) * (m * b.velocity);
  // Constant strain per block: strain energy S/2 e^T E e; the stress
  // already carried does work S sigma^T e. The damping stress beta E de/dt
  // at the step's mean strain rate (de / dt, as the mean velocity is d / dt)
  // adds beta/dt times the elastic stiffness and nothing to F: the trapezoidal
  // rule, unconditionally stable and dissipating beta/dt S de^T E de.
  sys.diagonal(i).bottomRightCorner<3, 3>() += (1.0 + beta / dt) * g.area * emat;
  sys.rhs(i).tail<3>() -= g.area * b.stress;
  // Body force: integral of T^T rho b is rho b S on the translations only
  // (the first moments about the centroid vanish).
  sys.rhs(i).head<2>() += g.area * mat.density * gravity;
}

void add_point_spring(int i, const BlockState& b, const Vec2& at, const Vec2& gap, double p, BlockSystem& sys) {
  const Matrix26d t = t_matrix(b.geometry.centroid, at);
  sys.diagonal(i) += p * t.transpose() * t;
  sys.rhs(i) += p * t.transpose() * gap;
}

void add_point_load(int i, const BlockState& b, const Vec2& at, const Vec2& force, BlockSystem& sys) {
  sys.rhs(i) += t_matrix(b.geometry.centroid, at).transpose() * force;
}

}  // namespace dda::df
