#pragma once
// Back-analysis of friction from a measured displacement history with the 3D
// analytical solution (sliding3d.hpp), as in the seed report's shaking-table
// study.
//
// Piecewise-constant friction: the time axis is cut at user-given times into
// segments; one friction angle per segment (the same on every plane). The
// segments are fitted in sequence: for segment k the simulation starts from
// the end state of segment k-1 (with the fitted angles), and a golden-section
// search on [phi_min, phi_max] minimises the RMS misfit between model and
// measurement at the measured samples inside the segment.
//
// mu = a + b ln(v / v_ref), two ways:
//  * regression: least squares of mu_k = tan(phi_k) on ln(v_k / v_ref), v_k the
//    segment's mean sliding speed (path length / duration) in the fitted model;
//    reports R^2 (the seed report's Fig. 21 method);
//  * direct: (a, b) minimising the RMS misfit over the whole history with the
//    log-velocity friction law in the simulation (Nelder-Mead, started from
//    the regression).
//
// The measured quantity is either the displacement along the reference
// direction (down the line of intersection for a wedge, down the dip for a
// single face) or the full vector (ux, uy, uz); model values at measured times
// are interpolated linearly between steps.
#include <optional>
#include <vector>

#include "dda/analysis/sliding3d.hpp"

namespace dda::analysis {

struct MeasuredHistory {
  std::vector<double> t;
  std::vector<Vec3> u;       // vector form, or
  std::vector<double> s;     // displacement along the reference direction
  bool vector_form = false;
};

struct BackfitOptions {
  std::vector<double> breaks;  // interior segment boundaries (s), increasing
  double phi_min = 5.0, phi_max = 60.0;
  double tolerance_deg = 1e-4;
  double dt = 1e-3;
  bool fit_log_velocity = false;
  double v_ref = 1.0, v_min = 1e-6;
};

struct SegmentFit {
  double t0 = 0, t1 = 0;
  double phi_deg = 0, mu = 0;
  double rms = 0;           // m
  double mean_speed = 0;    // m/s, model path length / duration
  int samples = 0;
};

struct LogVelocityFit {
  double a = 0, b = 0, r2 = 0, rms = 0;
  bool valid = false;
  // Direct fit only: the search found nothing better than its start (the
  // regression): the start is already the best, or the misfit is flat there
  // (typically a velocity-weakening law whose friction at v_min is so high
  // that the block never starts to slide, so (a, b) is not a fit at all).
  bool stalled = false;
};

struct BackfitResult {
  std::vector<SegmentFit> segments;
  double rms = 0;  // whole history, piecewise-constant fit
  LogVelocityFit regression;
  LogVelocityFit direct;
};

// `model.friction` is replaced by the fitted laws.
BackfitResult backfit(const SlidingModel& model, const MeasuredHistory& measured, const BackfitOptions& options);

// RMS misfit of a complete simulation with the model's own friction laws.
double history_misfit(const SlidingModel& model, const MeasuredHistory& measured, double dt);

}  // namespace dda::analysis
