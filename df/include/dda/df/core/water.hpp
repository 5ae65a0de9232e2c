#pragma once
// Hydrostatic joint water, one component for the 2D and the 3D solver
// (docs/formulation.md, "Joint water"; keys in docs/scenario.md, `water`).
//
// A phreatic surface gives the head h over the horizontal coordinates (x in
// 2D; x, y in 3D, z up), and the pore pressure at a point is
//   u(p) = gamma_w * max(0, h(p) - z(p)),
// z the vertical coordinate (y in 2D). The surface is a level (h constant),
// a polyline h(x) in 2D, or a plane in 3D: piecewise linear, so u is linear
// wherever it is positive on each piece, and its integral over a joint face
// is exact (the face is split at the polyline's knots and at u = 0).
//
// The solvers apply the resultant of u over the part two facing joint faces
// share as equal and opposite loads pushing the two blocks apart, times the
// joint set's saturation factor (df/src/2d/water_faces.cpp, ...3d.cpp).
#include <algorithm>
#include <vector>

#include <Eigen/Core>

namespace dda::df {

template <int dim>
struct WaterTable {
  using Point = Eigen::Matrix<double, dim, 1>;
  static_assert(dim == 2 || dim == 3, "2D or 3D");

  // Unit weight of water, N/m^3 (rho_w g: 1000 kg/m^3 times 9.81 m/s^2).
  double unit_weight = 9810;
  // The surface: `level` when `knots` is empty; in 2D the polyline's knots
  // (x, h) with x increasing (h held constant beyond the ends); in 3D three
  // points (x, y, h) of a plane, not in a vertical plane.
  double level = 0;
  std::vector<Point> knots;

  // The same table about a local origin `o` (coordinate_range.hpp): the
  // level and every knot given in the user's coordinates, less o.
  void move_to_origin(const Point& o) {
    level -= o[dim - 1];
    for (Point& k : knots) k -= o;
  }

  // Head (m) above the horizontal position of p.
  double head(const Point& p) const;
  // gamma_w max(0, h - z), Pa.
  double pressure(const Point& p) const { return unit_weight * std::max(0.0, head(p) - p[dim - 1]); }
};

// The resultant of the pressure over a face: its size and where it acts.
template <int dim>
struct PressureResultant {
  double force = 0;                                        // N (3D) or N/m (2D, per unit thickness)
  Eigen::Matrix<double, dim, 1> centre = Eigen::Matrix<double, dim, 1>::Zero();  // centre of pressure
};

// One of the loads the water puts on the blocks: `force` on material point
// `at` of `block` (the solvers' kernels make them in equal and opposite
// pairs, df/src/2d/water_faces.hpp and df/src/3d/water_faces3d.hpp).
template <int dim>
struct WaterLoad {
  int block = -1;
  Eigen::Matrix<double, dim, 1> at, force;
};

// The integral of u over a flat convex face: a segment [a, b] in 2D, a
// convex polygon (vertices in order) in 3D. Exact for the piecewise-linear
// surfaces above. force 0 (and centre the face's first vertex) when the face
// is dry.
PressureResultant<2> pressure_on_segment(const WaterTable<2>& w, const Eigen::Vector2d& a, const Eigen::Vector2d& b);
PressureResultant<3> pressure_on_polygon(const WaterTable<3>& w, const std::vector<Eigen::Vector3d>& face);

}  // namespace dda::df
