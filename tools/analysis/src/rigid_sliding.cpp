// Exact rigid-block sliding for a piecewise-linear record (rigid_sliding.hpp).
#include "dda/analysis/rigid_sliding.hpp"

#include <algorithm>
#include <cmath>

#include "dda/common/error.hpp"

namespace dda::analysis {

namespace {

// Smallest s in (0, limit] with v + e s + k s^2 / 2 = 0, or -1 if none.
// v >= 0 is the velocity at s = 0, e the excess acceleration there, k its slope.
double first_stop(double v, double e, double k, double limit) {
  double best = -1.0;
  auto consider = [&](double s) {
    if (s > 0.0 && s <= limit && (best < 0.0 || s < best)) best = s;
  };
  const double A = 0.5 * k, B = e, C = v;
  if (std::abs(A) * limit < 1e-14 * (std::abs(B) + 1e-300)) {  // linear
    if (B < 0.0) consider(-C / B);
    return best;
  }
  if (C == 0.0) {  // roots 0 and -B/A
    consider(-B / A);
    return best;
  }
  const double disc = B * B - 4.0 * A * C;
  if (disc < 0.0) return best;
  // Stable pair of roots: q = -(B + sgn(B) sqrt(disc)) / 2, roots q/A and C/q.
  const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
  if (q != 0.0) {
    consider(q / A);
    consider(C / q);
  } else {
    consider(std::sqrt(-C / A));
  }
  return best;
}

}  // namespace

RigidSliding rigid_sliding(const std::vector<double>& a, double dt, double yield_acceleration, bool keep_history) {
  if (a.size() < 2) throw InputError("Rigid sliding: a record needs at least two samples.");
  if (!(dt > 0.0) || !std::isfinite(dt)) throw InputError("Rigid sliding: the time step must be positive.");
  if (!(yield_acceleration >= 0.0) || !std::isfinite(yield_acceleration))
    throw InputError("Rigid sliding: the yield acceleration must be zero or positive.");
  RigidSliding r;
  if (keep_history) r.velocity.assign(a.size(), 0.0);
  double v = 0.0, d = 0.0;
  for (std::size_t i = 0; i + 1 < a.size(); ++i) {
    const double e0 = a[i] - yield_acceleration;
    const double k = (a[i + 1] - a[i]) / dt;  // slope of the excess acceleration
    double tau = 0.0;                         // position within the step
    // At most: slide, stop, start again once (the excess is linear).
    for (int pass = 0; pass < 4 && tau < dt; ++pass) {
      double e = e0 + k * tau;
      if (v == 0.0) {  // sticking: find where the excess turns positive
        if (e <= 0.0) {
          if (!(k > 0.0)) break;
          const double start = -e0 / k;
          if (start >= dt) break;
          tau = std::max(tau, start);
          e = 0.0;
        }
        ++r.slip_episodes;
      }
      const double rest = dt - tau;
      const double stop = first_stop(v, e, k, rest);
      const double s = stop > 0.0 ? stop : rest;
      d += v * s + 0.5 * e * s * s + k * s * s * s / 6.0;
      const double v_end = v + e * s + 0.5 * k * s * s;
      // Peak velocity inside the sub-interval: where the excess is zero.
      if (k != 0.0) {
        const double s_peak = -e / k;
        if (s_peak > 0.0 && s_peak < s) r.max_velocity = std::max(r.max_velocity, v + 0.5 * e * s_peak);
      }
      v = stop > 0.0 ? 0.0 : std::max(0.0, v_end);
      r.max_velocity = std::max(r.max_velocity, v);
      tau += s;
      if (stop <= 0.0) break;
    }
    if (keep_history) r.velocity[i + 1] = v;
  }
  r.displacement = d;
  return r;
}

}  // namespace dda::analysis
