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
  if (!model_.water.empty()) {
    if (model_.water.size() != model_.planes.size())
      throw InputError("Sliding analysis: give one water force per plane.");
    for (std::size_t k = 0; k < model_.water.size(); ++k) {
      if (!(model_.water[k] >= 0.0 && std::isfinite(model_.water[k])))
        throw InputError("Sliding analysis: a water force must be >= 0 (a fraction of the weight).");
      water_ += model_.gravity * model_.water[k] * (k == 0 ? n1_ : n2_);
    }
  }
  settle_mode();
}

SlidingSimulator::Eval SlidingSimulator::evaluate(double t, const Vec3& v, ContactMode mode) const {
  Eval ev;
  Vec3 r = Vec3(0.0, 0.0, -model_.gravity) + model_.input.body(t);
  if (!model_.water.empty()) r += water_;  // dry: r exactly as before
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
      ev.m = r.dot(e_) * e_;
      ev.cap = model_.friction[0].mu(t, speed) * ev.n1 + model_.friction[1].mu(t, speed) * ev.n2;
      ev.s = ev.m - resistance(ev.m, ev.cap, v.dot(e_) * e_);
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
      ev.m = r + N * n;
      ev.cap = model_.friction[k].mu(t, speed) * N;
      ev.s = ev.m - resistance(ev.m, ev.cap, v - v.dot(n) * n);
      return ev;
    }
    case ContactMode::lifted:
      ev.m = ev.s = r;
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
  if (!a1.feasible) a1 = a0;  // the mode changes at t1; keep the step consistent
  const Vec3 S = 0.5 * (a0.s + a1.s);
  const double v0n = v0.norm();
  // Friction impulse of the step (its size; the direction is decided below).
  const double impulse = 0.5 * (a0.cap + a1.cap) * dt;
  const bool slow = v0n > 0.0 && v0n <= impulse;
  Vec3 vn;
  bool stops = false;
  if (slow) {
    // Slow block: the step's friction impulse F dt is at least its momentum.
    // The seed's rule, friction along v0 for the whole step, breaks down
    // here. Whenever the driving part m is not parallel to v0 (on a single
    // face as soon as the shaking has a part along the strike, and through
    // round-off even without one) the velocity across m is multiplied by
    // 1 - F dt / |v0| <= 0 in one step: it reverses, and grows, instead of
    // dying out. The velocity then turns by more than 90 degrees, the block
    // is stopped and restarts from rest, and so on: after every start it
    // stutters until |m| - F has grown to a fixed fraction of F. That takes
    // the same time whatever dt, so the error does not vanish as dt -> 0 (a
    // block on 20/090 shaken along the strike converged 1.1 % short; see
    // tests/analysis/test_sliding3d.cpp). Here Coulomb's law acts on the
    // velocity at the end of the step: with z = v0 + M dt, the velocity the
    // driving alone would give (M the step's mean driving part), the block
    // stops within the step if |z| <= F dt; otherwise it ends with
    // v = z (1 - F dt / |z|), friction against its own direction. On a line
    // (a wedge sliding on both planes, a single face shaken in its dip plane)
    // this is the seed's step exactly. Faster blocks keep the seed's rule:
    // there it damps the velocity across m without reversing it.
    const Vec3 z = v0 + 0.5 * (a0.m + a1.m) * dt;
    const double zn = z.norm();
    if (zn > impulse && z.dot(v0) > 0.0) {
      vn = z * (1.0 - impulse / zn);
    } else {
      stops = true;
    }
  } else {
    vn = v0 + S * dt;
    stops = v0n > 0.0 && vn.dot(v0) <= 0.0;
  }
  if (stops) {
    // The block stops within the step: friction takes all its momentum, or
    // the driving turns its velocity by more than 90 degrees (then it
    // restarts from rest in the next step, as in the seed).
    const double decel = -S.dot(v0) / v0n;  // > 0
    const double tau = decel > 0.0 ? std::min(dt, v0n / decel) : dt;
    state_.u += 0.5 * v0 * tau;
    vn = Vec3::Zero();
  } else if (slow) {
    state_.u += 0.5 * (v0 + vn) * dt;
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
