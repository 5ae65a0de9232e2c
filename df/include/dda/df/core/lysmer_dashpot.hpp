#pragma once
// The Lysmer-Kuhlemeyer (1969) dashpots of a non-reflecting boundary, in any
// dimension: one home for the law both solvers use (viscous_boundary.hpp in
// 2D, viscous_boundary3d.hpp in 3D).
//
// A boundary stands for the same material continuing outside the model.
// Dashpots of rho Vp on the velocity along the outward unit normal n and of
// rho Vs on the tangential velocity take out exactly the traction a plane
// wave arriving at normal incidence carries, so it leaves without
// reflection:
//   t = -D v,   D = rho (Vp n n^T + Vs (I - n n^T)).
// With an incident wave of particle velocity v_in coming in from outside,
// t = D (2 v_in - v) (Joyner & Chen 1975).
#include <Eigen/Core>
#include <cmath>

namespace dda::df {

// Vs = sqrt(E / (2 (1 + nu) rho)), m/s, in 2D and 3D alike.
inline double shear_wave_speed(double young, double poisson, double density) {
  return std::sqrt(young / (2 * (1 + poisson) * density));
}

// D for outward unit normal n (N s/m^3: a traction per velocity). The
// tangential part is rho Vs s s^T in 2D (s the tangent, as the 2D solver
// always computed it, so that 2D runs stay bit for bit) and
// rho Vs (I - n n^T) in 3D (two tangents); the two are equal but for
// rounding.
template <int N>
Eigen::Matrix<double, N, N> lysmer_dashpot(double density, double vp, double vs,
                                           const Eigen::Matrix<double, N, 1>& n) {
  static_assert(N == 2 || N == 3, "a dashpot in 2D or 3D");
  Eigen::Matrix<double, N, N> tangential;
  if constexpr (N == 2) {
    const Eigen::Matrix<double, 2, 1> s(-n.y(), n.x());
    tangential = vs * s * s.transpose();
  } else {
    tangential = vs * (Eigen::Matrix<double, N, N>::Identity() - n * n.transpose());
  }
  return density * (vp * n * n.transpose() + tangential);
}

}  // namespace dda::df
