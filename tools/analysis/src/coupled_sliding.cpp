// Coupled sliding of a first-mode shear beam (coupled_sliding.hpp).
#include "dda/analysis/coupled_sliding.hpp"

#include <algorithm>
#include <cmath>

#include "dda/analysis/rigid_sliding.hpp"
#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"

namespace dda::analysis {

namespace {

struct State {
  double q = 0.0, qd = 0.0, qdd = 0.0;  // modal coordinate
  double D = 0.0, Dd = 0.0, Ddd = 0.0;  // sliding
  bool sliding = false;
};

class Stepper {
 public:
  Stepper(double omega, double damping, double yield) : w2_(omega * omega), c_(2.0 * damping * omega), ay_(yield) {}

  // Base-shear demand of a sticking mass: the acceleration the base must give.
  double demand(const State& s, double ag) const { return ag + kMassFraction * s.qdd; }

  // q'' and D'' from the equations of motion in the state's mode, at the
  // ground acceleration ag (q'' is continuous at a start of sliding, where
  // D'' = 0; at a stop it jumps by -Gamma D'', with the base acceleration).
  void settle(State& s, double ag) const {
    const double m = s.sliding ? 1.0 - kMassFraction * kParticipation : 1.0;
    const double f = s.sliding ? -kParticipation * ay_ : -kParticipation * ag;
    s.qdd = (f - c_ * s.qd - w2_ * s.q) / m;
    s.Ddd = s.sliding ? ag + kMassFraction * s.qdd - ay_ : 0.0;
  }

  // One trapezoidal step of length h to the ground acceleration ag1, in the
  // state's mode (sticking or sliding); the sliding state's D' may turn negative.
  State step(const State& s, double h, double ag1) const {
    State n = s;
    // q1 = q + h q' + h^2/4 (q'' + q1''), q1' = q' + h/2 (q'' + q1''):
    // m q1'' + c q1' + w2 q1 = f, solved for q1''.
    const double q_pred = s.q + h * s.qd + 0.25 * h * h * s.qdd;
    const double qd_pred = s.qd + 0.5 * h * s.qdd;
    const double m = s.sliding ? 1.0 - kMassFraction * kParticipation : 1.0;
    const double f = s.sliding ? -kParticipation * ay_ : -kParticipation * ag1;
    n.qdd = (f - c_ * qd_pred - w2_ * q_pred) / (m + 0.5 * h * c_ + 0.25 * h * h * w2_);
    n.qd = qd_pred + 0.5 * h * n.qdd;
    n.q = q_pred + 0.25 * h * h * n.qdd;
    if (s.sliding) {
      n.Ddd = ag1 + kMassFraction * n.qdd - ay_;
      n.Dd = s.Dd + 0.5 * h * (s.Ddd + n.Ddd);
      n.D = s.D + 0.5 * h * (s.Dd + n.Dd);
    }
    return n;
  }

 private:
  double w2_, c_, ay_;
};

}  // namespace

CoupledSliding coupled_sliding(const std::vector<double>& a, double dt, double yield_acceleration,
                               const ShearBeam& beam, bool keep_history) {
  if (!(beam.period >= 0.0) || !std::isfinite(beam.period))
    throw InputError("Coupled sliding: the period Ts must be zero or positive.");
  if (!(beam.damping >= 0.0 && beam.damping < 1.0))
    throw InputError("Coupled sliding: the damping ratio must lie in 0..1.");
  CoupledSliding r;
  if (beam.period == 0.0) {  // rigid: the exact block
    const RigidSliding rigid = rigid_sliding(a, dt, yield_acceleration, keep_history);
    r.displacement = rigid.displacement;
    r.max_velocity = rigid.max_velocity;
    if (keep_history) {
      r.q.assign(a.size(), 0.0);
      r.q_rate.assign(a.size(), 0.0);
      r.sliding_rate = rigid.velocity;
      r.sliding.assign(a.size(), 0.0);
      for (std::size_t i = 1; i < a.size(); ++i)
        r.sliding[i] = r.sliding[i - 1] + 0.5 * dt * (r.sliding_rate[i - 1] + r.sliding_rate[i]);
    }
    return r;
  }
  if (a.size() < 2) throw InputError("Coupled sliding: a record needs at least two samples.");
  if (!(dt > 0.0) || !std::isfinite(dt)) throw InputError("Coupled sliding: the time step must be positive.");
  if (!(yield_acceleration >= 0.0) || !std::isfinite(yield_acceleration))
    throw InputError("Coupled sliding: the yield acceleration must be zero or positive.");
  const Stepper stepper(2.0 * kPi / beam.period, beam.damping, yield_acceleration);
  State s;
  stepper.settle(s, a[0]);
  if (stepper.demand(s, a[0]) > yield_acceleration) {
    s.sliding = true;
    stepper.settle(s, a[0]);
  }
  auto record = [&](const State& st) {
    if (!keep_history) return;
    r.q.push_back(st.q);
    r.q_rate.push_back(st.qd);
    r.sliding.push_back(st.D);
    r.sliding_rate.push_back(st.Dd);
  };
  record(s);
  constexpr int kMaxPasses = 4;  // a start, a stop and a start again, then the rest of the step as it is
  for (std::size_t i = 0; i + 1 < a.size(); ++i) {
    const double a0 = a[i], a1 = a[i + 1];
    auto ground = [&](double tau) { return a0 + (a1 - a0) * tau / dt; };
    double tau = 0.0;
    for (int pass = 1; pass <= kMaxPasses; ++pass) {
      const double h = dt - tau;
      if (h <= 1e-12 * dt) break;  // the split fell on the end of the step
      const State n = stepper.step(s, h, a1);
      const bool starts = !s.sliding && stepper.demand(n, a1) > yield_acceleration;
      const bool stops = s.sliding && !(n.Dd > 0.0);
      if (pass == kMaxPasses || !(starts || stops)) {
        s = n;
        if (s.sliding) s.Dd = std::max(0.0, s.Dd);
        break;
      }
      // Split the step where the demand reaches a_y (a start) or D' reaches
      // zero (a stop), both linear in the step, and change mode there.
      double w = 0.0;
      if (starts) {
        const double d0 = stepper.demand(s, ground(tau)), d1 = stepper.demand(n, a1);
        w = d1 > d0 ? std::clamp((yield_acceleration - d0) / (d1 - d0), 0.0, 1.0) : 0.0;
      } else {
        w = s.Dd > 0.0 ? std::clamp(s.Dd / (s.Dd - n.Dd), 0.0, 1.0) : 0.0;
      }
      if (w > 0.0) s = stepper.step(s, w * h, ground(tau + w * h));
      tau += w * h;
      s.sliding = starts;
      if (stops) s.Dd = 0.0;
      stepper.settle(s, ground(tau));
    }
    r.max_velocity = std::max(r.max_velocity, s.Dd);
    record(s);
  }
  r.displacement = s.D;
  return r;
}

}  // namespace dda::analysis
