#pragma once
// The rock-bolt law, one for both dimensions (the 2D solver's bolts.hpp and
// the 3D solver's bolts3d.hpp put it in their step systems).
//
// A bolt is an elastic bar between a material point of one block (the
// anchor) and one of another (the head). Its axial force, tension positive,
// is T = pretension + k (L - L0), L its current and L0 its initial length;
// it acts along the current bolt direction (so it pushes back when squeezed
// below L0 - pretension / k). After a step in which T exceeds the breaking
// force the bolt is broken for good: its force is 0 and the energy its bar
// held, T^2 / 2k, is released (the ledger's `breakage`).
//
// In a step, with u the unit vector anchor -> head at the start of the step
// and dL = u . (u_head - u_anchor) the linearised change of length, the bolt
// adds the energy T dL + k/2 dL^2: its stiffness k e e^T and the load -T e,
// e the gradient of dL with respect to the two blocks' unknowns. The spec
// type is the dimension's bolt (df::Bolt, df3::Bolt3): any type with
// `stiffness`, `pretension` and `breaking_force` (std::optional<double>).
#include <Eigen/Core>

namespace dda::df {

template <int dim>
struct BoltStateOf {
  using Point = Eigen::Matrix<double, dim, 1>;
  Point anchor = Point::Zero(), head = Point::Zero();  // current end positions
  double rest_length = 0;                              // L0, m (initial length)
  double force = 0;                                    // N, tension positive; 0 once broken
  bool broken = false;
};

// One sample of a bolt's history (sample 0 is the initial state).
struct BoltSample {
  double time = 0;
  double force = 0;   // N, tension positive
  double length = 0;  // m
  bool broken = false;
};

template <class Spec, class Point>
auto initial_bolt_state(const Spec& bolt, const Point& anchor, const Point& head) {
  BoltStateOf<Point::RowsAtCompileTime> s;
  s.anchor = anchor;
  s.head = head;
  s.rest_length = (head - anchor).norm();
  s.force = bolt.pretension;
  return s;
}

// The axial force at the bolt's current length (intact or not).
template <class Spec, int dim>
double bolt_force_now(const Spec& bolt, const BoltStateOf<dim>& s) {
  return bolt.pretension + bolt.stiffness * ((s.head - s.anchor).norm() - s.rest_length);
}

// After the ends have moved with their blocks: the new force, and breakage
// when it exceeds the strength. Returns the energy the break released (0
// when it did not break in this step).
template <class Spec, int dim>
double update_bolt_force(const Spec& bolt, BoltStateOf<dim>& s) {
  if (s.broken) return 0;
  s.force = bolt_force_now(bolt, s);
  if (bolt.breaking_force && s.force > *bolt.breaking_force) {
    const double released = s.force * s.force / (2 * bolt.stiffness);
    s.broken = true;
    s.force = 0;
    return released;
  }
  return 0;
}

// Elastic energy in the bar, T^2 / (2 k); 0 once broken.
template <class Spec, int dim>
double bolt_energy(const Spec& bolt, const BoltStateOf<dim>& s) {
  return s.broken ? 0.0 : s.force * s.force / (2 * bolt.stiffness);
}

template <int dim>
BoltSample bolt_sample(double time, const BoltStateOf<dim>& s) {
  return {time, s.force, (s.head - s.anchor).norm(), s.broken};
}

}  // namespace dda::df
