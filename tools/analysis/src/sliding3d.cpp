#include "dda/analysis/sliding3d.hpp"

#include <cmath>
#include <sstream>

#include "dda/common/error.hpp"

namespace dda::analysis {

const char* mode_name(ContactMode mode) {
  switch (mode) {
    case ContactMode::double_face:
      return "double-face";
    case ContactMode::face1:
      return "single-face-1";
    case ContactMode::face2:
      return "single-face-2";
    case ContactMode::lifted:
      return "lifted";
  }
  return "?";
}

namespace {

// Friction resistance for driving part m, total friction capacity F, velocity v.
Vec3 resistance(const Vec3& m, double capacity, const Vec3& v) {
  const double speed = v.norm();
  if (speed > 0.0) return capacity * v / speed;
  const double mm = m.norm();
  if (mm <= capacity || mm == 0.0) return m;
  return capacity * m / mm;
}

std::string at_time(double t) {
  std::ostringstream s;
  s << "t = " << t << " s";
  return s.str();
}

}  // namespace

SlidingSimulator::SlidingSimulator(SlidingModel model, double dt) : model_(std::move(model)), dt_(dt) {
  if (!(dt_ > 0.0)) throw InputError("Sliding analysis: the time step must be positive.");
  if (model_.planes.empty() || model_.planes.size() > 2)
    throw InputError("Sliding analysis: give one plane (single face) or two planes (wedge).");
  if (model_.friction.size() != model_.planes.size())
    throw InputError("Sliding analysis: give one friction law per plane.");
  if (!model_.input.body) model_.input = no_input();
  n1_ = model_.planes[0].normal();
  if (model_.planes.size() == 2) {
    n2_ = model_.planes[1].normal();
    const Vec3 I = n1_.cross(n2_);
    if (I.norm() < 1e-9) throw InputError("Sliding analysis: the two planes are parallel (no line of intersection).");
    e_ = I.normalized();
    reference_ = e_.z() > 0.0 ? Vec3(-e_) : e_;
    state_.mode = ContactMode::double_face;
  } else {
    n2_ = Vec3::Zero();
    e_ = Vec3::Zero();
    reference_ = model_.planes[0].dip_vector();
    state_.mode = ContactMode::face1;
  }
  settle_mode();
}

SlidingSimulator::Eval SlidingSimulator::evaluate(double t, const Vec3& v, ContactMode mode) const {
  Eval ev;
  const Vec3 r = Vec3(0.0, 0.0, -model_.gravity) + model_.input.body(t);
  const double speed = v.norm();
  switch (mode) {
    case ContactMode::double_face: {
      const Vec3 I = n1_.cross(n2_);
      const double I2 = I.squaredNorm();
      ev.n1 = -r.cross(n2_).dot(I) / I2;
      ev.n2 = r.cross(n1_).dot(I) / I2;
      if (ev.n1 < 0.0 || ev.n2 < 0.0) {
        ev.feasible = false;
        return ev;
      }
      const Vec3 m = r.dot(e_) * e_;
      const double cap = model_.friction[0].mu(t, speed) * ev.n1 + model_.friction[1].mu(t, speed) * ev.n2;
      ev.s = m - resistance(m, cap, v.dot(e_) * e_);
      return ev;
    }
    case ContactMode::face1:
    case ContactMode::face2: {
      const std::size_t k = mode == ContactMode::face1 ? 0 : 1;
      const Vec3& n = k == 0 ? n1_ : n2_;
      const double N = -r.dot(n);
      (k == 0 ? ev.n1 : ev.n2) = N;
      if (N < 0.0) {
        ev.feasible = false;
        return ev;
      }
      const Vec3 m = r + N * n;
      ev.s = m - resistance(m, model_.friction[k].mu(t, speed) * N, v - v.dot(n) * n);
      return ev;
    }
    case ContactMode::lifted:
      ev.s = r;
      return ev;
  }
  return ev;
}

// Chooses the contact mode at the current time from the reactions.
void SlidingSimulator::settle_mode() {
  for (int guard = 0; guard < 3; ++guard) {
    if (state_.mode == ContactMode::lifted) return;
    Eval ev = evaluate(state_.t, state_.v, state_.mode);
    if (ev.feasible) {
      state_.n1 = ev.n1;
      state_.n2 = ev.n2;
      return;
    }
    if (state_.mode == ContactMode::double_face) {
      // Keep the plane that still presses; the other one opens.
      const bool keep1 = ev.n1 >= ev.n2;
      state_.mode = keep1 ? ContactMode::face1 : ContactMode::face2;
      // Velocity in double-face sliding lies on the line, thus on both planes.
      events_.push_back({state_.t, "lost contact with plane " + std::string(keep1 ? "2" : "1") +
                                       ": single-face sliding on plane " + (keep1 ? "1" : "2") + " (" +
                                       at_time(state_.t) + ")"});
    } else {
      state_.mode = ContactMode::lifted;
      state_.n1 = state_.n2 = 0.0;
      events_.push_back({state_.t, "lift-off: the block leaves its last plane (" + at_time(state_.t) +
                                       "); the analysis stops"});
      return;
    }
  }
}

void SlidingSimulator::step(double h) {
  if (finished()) return;
  const double dt = h > 0.0 ? h : dt_;
  const double t0 = state_.t, t1 = t0 + dt;
  const Vec3 v0 = state_.v;
  const Eval a0 = evaluate(t0, v0, state_.mode);
  Eval a1 = evaluate(t1, v0, state_.mode);
  if (!a1.feasible) a1.s = a0.s;  // the mode changes at t1; keep the step consistent
  const Vec3 S = 0.5 * (a0.s + a1.s);
  Vec3 vn = v0 + S * dt;
  const double v0n = v0.norm();
  if (v0n > 0.0 && vn.dot(v0) <= 0.0) {
    // The block stops within the step (velocity turns by more than 90 degrees).
    const double decel = -S.dot(v0) / v0n;  // > 0
    const double tau = decel > 0.0 ? std::min(dt, v0n / decel) : dt;
    state_.u += 0.5 * v0 * tau;
    vn = Vec3::Zero();
  } else {
    state_.u += v0 * dt + 0.5 * S * dt * dt;
  }
  state_.v = vn;
  state_.t = t1;
  // Keep the motion on its constraint: round-off off the plane (or line) would
  // tilt the friction direction of a slowly moving block and grow.
  constrain();
  // Re-contact with the plane a wedge lost.
  if (model_.planes.size() == 2 && (state_.mode == ContactMode::face1 || state_.mode == ContactMode::face2)) {
    const Vec3& lost = state_.mode == ContactMode::face1 ? n2_ : n1_;
    if (state_.u.dot(lost) < 0.0) {
      state_.u = state_.u.dot(e_) * e_;
      state_.v = state_.v.dot(e_) * e_;
      const Eval test = evaluate(t1, state_.v, ContactMode::double_face);
      if (test.feasible) {
        state_.mode = ContactMode::double_face;
        events_.push_back({t1, "back in contact with both planes: double-face sliding (" + at_time(t1) + ")"});
      }
    }
  }
  settle_mode();
}

void SlidingSimulator::constrain() {
  switch (state_.mode) {
    case ContactMode::double_face:
      state_.u = state_.u.dot(e_) * e_;
      state_.v = state_.v.dot(e_) * e_;
      break;
    case ContactMode::face1:
    case ContactMode::face2: {
      const Vec3& n = state_.mode == ContactMode::face1 ? n1_ : n2_;
      state_.u -= state_.u.dot(n) * n;
      state_.v -= state_.v.dot(n) * n;
      break;
    }
    case ContactMode::lifted:
      break;
  }
}

SlidingRun run_sliding(const SlidingModel& model, double dt, double duration, int every) {
  if (!(duration > 0.0)) throw InputError("Sliding analysis: the duration must be positive.");
  if (every < 1) every = 1;
  SlidingSimulator sim(model, dt);
  SlidingRun run;
  run.reference = sim.reference_direction();
  run.samples.push_back(sim.state());
  const auto steps = static_cast<long>(std::llround(std::ceil(duration / dt - 1e-9)));
  for (long i = 1; i <= steps && !sim.finished(); ++i) {
    sim.step(i == steps ? duration - sim.state().t : dt);
    if (i % every == 0 || i == steps || sim.finished()) run.samples.push_back(sim.state());
  }
  run.events = sim.events();
  return run;
}

}  // namespace dda::analysis
