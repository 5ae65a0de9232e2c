#pragma once
// Earthquake input, once for both dimensions (scenario key
// loading.earthquake, docs/scenario.md; the equations in docs/formulation.md).
//
// A GroundMotion<dim> is the processed ground acceleration a_g(t) in model
// axes (2D: x horizontal, y up; 3D: x east, y north, z up), m/s^2, piecewise
// linear between the record's samples and zero outside them. Its velocity
// and displacement are the exact integrals of that polygon from rest at the
// first sample, so no quadrature error enters the foundation's path or the
// incident wave, whatever the record's sampling and the steps.
//
// A GroundMotionMode says how the motion reaches the blocks. Each mode
// drives one of three routes, and every kernel has all three:
//  * loading (route body_force): the blocks outside the foundation feel the
//    motion in the frame of the ground, as the body force -rho a_g added to
//    gravity; the foundation is held where it is;
//  * displacement (route foundation): the foundation follows the ground
//    displacement d_g(t); the other blocks feel it only through their
//    contacts, as on a shaking table;
//  * incident (route incident_wave): the record is the outcrop motion of
//    the base rock; a free surface doubles an incident wave, so a wave of
//    half its velocity enters through the viscous boundary's input sides,
//    which also let out what comes back down.
// For a rigid foundation the first two give the same motion relative to it,
// as long as they see the same a_g: the baseline correction (which changes
// a_g by -P''(t), common/record.hpp) is part of the processing and applies
// to every mode alike.
//
// What a kernel calls the foundation is its own: 2D, fixed points (by
// default all of them); 3D, the fixed blocks.
//
// Adding a mode: a route it drives (or a new route every kernel learns),
// and one line in the table of ground_motion.cpp.
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "dda/common/record.hpp"

namespace dda::df {

template <int dim>
class GroundMotion {
 public:
  using Vec = Eigen::Matrix<double, dim, 1>;

  GroundMotion() = default;
  // InputError (naming `source`) unless there is at least one sample, the
  // times strictly increase and every value is finite.
  GroundMotion(std::vector<double> t, std::vector<Vec> a, std::string source = "ground motion");

  Vec acceleration(double t) const;
  Vec velocity(double t) const;      // zero up to the first sample, the final velocity after the last
  Vec displacement(double t) const;  // zero up to the first sample, drifting on at the final velocity after
  // (v(t1) - v(t0)) / (t1 - t0): the exact impulse of a step; a(t0) if t1 <= t0.
  Vec mean_acceleration(double t0, double t1) const;

  bool empty() const { return t_.empty(); }
  double start() const { return t_.front(); }
  double end() const { return t_.back(); }
  const std::vector<double>& times() const { return t_; }
  const std::vector<Vec>& samples() const { return a_; }  // a_g at times()
  const std::string& source() const { return source_; }   // the record file, for messages

  // The sample times with every interval split into equal parts no longer
  // than `step`: tables linear (or Hermite) between these rows follow the
  // motion as finely as the solver steps through it.
  std::vector<double> refined_times(double step) const;

 private:
  std::size_t interval(double t) const;  // k with t in [t_k, t_k+1], t inside the record
  std::vector<double> t_;
  std::vector<Vec> a_, v_, d_;  // at the samples
  std::string source_;
};

// InputError naming the record file when it has a component the model
// cannot use (2D: a non-zero z).
template <int dim>
void check_record_fits(const AccelRecord& record);

// The motion of a read and processed record (common/record.hpp): its
// first `dim` components, once check_record_fits has passed.
template <int dim>
GroundMotion<dim> ground_motion_of(const AccelRecord& record);

enum class GroundMotionRoute { body_force, foundation, incident_wave };

struct GroundMotionMode {
  std::string name;
  GroundMotionRoute route = GroundMotionRoute::body_force;
  // Degree of the baseline correction when the scenario gives none: 0 for
  // a body force (the record acts as given); 3 where the ground's path or
  // velocity matters, so that it does not drift away with the record's mean
  // velocity (the foundation) or push on the base for ever (the wave).
  int default_baseline = 0;

  // The acceleration added to gravity over the step [t, t + dt] on every
  // block outside the foundation (-a_g, averaged exactly over the step;
  // a_g(t) itself when dt is 0, as while settling).
  template <int dim>
  Eigen::Matrix<double, dim, 1> body_acceleration(const GroundMotion<dim>& g, double t, double dt) const {
    if (route != GroundMotionRoute::body_force) return Eigen::Matrix<double, dim, 1>::Zero();
    return -g.mean_acceleration(t, t + dt);
  }
  // Where the foundation is at t, relative to where it started.
  template <int dim>
  Eigen::Matrix<double, dim, 1> foundation_displacement(const GroundMotion<dim>& g, double t) const {
    if (route != GroundMotionRoute::foundation) return Eigen::Matrix<double, dim, 1>::Zero();
    return g.displacement(t);
  }
};

// The mode called `name`; InputError naming the known ones otherwise.
const GroundMotionMode& ground_motion_mode(const std::string& name);
std::vector<std::string> ground_motion_mode_names();

// The incident mode's wave: half the outcrop velocity, as rows at the
// record's refined times (`step` apart at most), and a zero row a step after
// the record (the wave stops): the table the viscous boundary follows
// (linear between rows).
template <int dim>
std::vector<std::pair<double, Eigen::Matrix<double, dim, 1>>> incident_velocity_rows(const GroundMotion<dim>& g,
                                                                                      double step);

}  // namespace dda::df
