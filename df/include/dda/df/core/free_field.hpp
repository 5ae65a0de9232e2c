#pragma once
// The free field of a vertically incident plane wave, in any dimension: one
// home for the motion and stresses the free-field boundaries of both solvers
// apply (viscous_boundary.hpp in 2D, viscous_boundary3d.hpp in 3D).
//
// A uniform half-space, its free surface at height `surface`, is shaken by
// a plane wave of particle velocity v_in(t) travelling up from the height
// `base` (where the wave enters the model). The vertical is the last axis
// (y in 2D, z in 3D): the vertical component of v_in travels as a P wave at
// Vp, each horizontal one as an S wave at Vs. At height h the free field is
// the up-going wave plus its reflection from the free surface (which then
// leaves through the absorbing base):
//   v_up(t) = v_in(t - (h - base) / c),  v_dn(t) = v_in(t - (2 surface - h - base) / c),
//   v_ff = v_up + v_dn.
// A wave f(t - z/c) has strain -v/c along its path and f(t + z/c) +v/c, so
// its stresses are, for each horizontal axis i and the vertical v,
//   sigma_iv = rho Vs (v_dn,i - v_up,i),   sigma_vv = rho Vp (v_dn,v - v_up,v),
//   sigma_ii = r sigma_vv                  (no lateral strain in a plane wave),
// r = nu / (1 - nu) where the lateral strain is held (3D, 2D plane strain)
// and nu in 2D plane stress; the horizontal-horizontal shears are zero.
// A face of outward normal n with dashpots D (lysmer_dashpot.hpp) then
// receives t = D v_ff + sigma n besides its dashpots' -D v.
//
// The velocities are means over a step [t0, t1] (the history's exact
// average), as the rest of the incident input.
#include <Eigen/Core>

namespace dda::df {

template <int N>
struct FreeFieldMotion {
  using Vector = Eigen::Matrix<double, N, 1>;
  Vector velocity = Vector::Zero();                    // v_ff
  Vector up = Vector::Zero(), down = Vector::Zero();  // its up- and down-going parts
};

// The free field at height h over [t0, t1]. History: any table with
// average(t0, t1) returning an N-vector (TimeHistory, TimeHistory3).
template <int N, class History>
FreeFieldMotion<N> free_field_motion(const History& incident, double vs, double vp, double h, double base,
                                     double surface, double t0, double t1) {
  const auto delayed = [&](double distance, double speed) {
    const double delay = distance / speed;
    return incident.average(t0 - delay, t1 - delay);
  };
  const double rise = h - base, fall = 2 * surface - h - base;  // path lengths up, and up and back down
  FreeFieldMotion<N> ff;
  ff.up = delayed(rise, vs);  // the horizontal components; the vertical one next
  ff.down = delayed(fall, vs);
  ff.up[N - 1] = delayed(rise, vp)[N - 1];
  ff.down[N - 1] = delayed(fall, vp)[N - 1];
  ff.velocity = ff.up + ff.down;
  return ff;
}

// sigma_ff of the header comment; lateral_ratio is r.
template <int N>
Eigen::Matrix<double, N, N> free_field_stress(const FreeFieldMotion<N>& ff, double density, double vs, double vp,
                                              double lateral_ratio) {
  Eigen::Matrix<double, N, N> s = Eigen::Matrix<double, N, N>::Zero();
  const int v = N - 1;
  s(v, v) = density * vp * (ff.down[v] - ff.up[v]);
  for (int i = 0; i < v; ++i) {
    s(i, v) = s(v, i) = density * vs * (ff.down[i] - ff.up[i]);
    s(i, i) = s(v, v) * lateral_ratio;
  }
  return s;
}

}  // namespace dda::df
