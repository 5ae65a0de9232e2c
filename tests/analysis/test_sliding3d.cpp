// The 3D analytical sliding solution (seed report, ch. 2): docs/validation.md V1
// (closed form under gravity), V3 (block on 20/090 under horizontal
// sinusoid), V4 (wedge under gravity alone), contact changes, and a block on
// one plane shaken along its strike, its dip, and by two- and
// three-component records, each against a second integrator written here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "dda/analysis/sliding3d.hpp"
#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"

using namespace dda::analysis;

namespace {

constexpr double kG = 9.81;

SlidingModel single(double dip, double dipdir, double phi, Excitation input) {
  SlidingModel m;
  m.planes = {Plane{dip, dipdir}};
  m.friction = {FrictionLaw::constant_angle(phi)};
  m.input = std::move(input);
  m.gravity = kG;
  return m;
}

SlidingModel v4_wedge(double phi, Excitation input) {
  SlidingModel m;
  m.planes = {Plane{51.4, 65.8}, Plane{51.4, 295.2}};
  m.friction = {FrictionLaw::constant_angle(phi), FrictionLaw::constant_angle(phi)};
  m.input = std::move(input);
  m.gravity = kG;
  return m;
}

}  // namespace

// docs/validation.md V1, alpha = 30, phi = 20: a = 1.81281 m/s^2, s(1 s) = 0.90641 m,
// down the dip; the trapezoidal scheme is exact for constant acceleration.
TEST(Sliding3d, V1ClosedForm) {
  const SlidingRun run = run_sliding(single(30, 135, 20, no_input()), 1e-3, 1.0);
  const SlidingState& end = run.samples.back();
  EXPECT_NEAR(end.t, 1.0, 1e-12);
  EXPECT_NEAR(end.u.norm(), 0.90641, 1e-5);
  EXPECT_NEAR(end.u.normalized().dot(Plane{30, 135}.dip_vector()), 1.0, 1e-12);
  EXPECT_NEAR(end.n1 / kG, std::cos(dda::deg2rad(30)), 1e-12);
  // phi >= alpha: it stays.
  EXPECT_DOUBLE_EQ(run_sliding(single(30, 135, 30.5, no_input()), 1e-3, 1.0).samples.back().u.norm(), 0.0);
}

// docs/validation.md V3: plane 20/090, phi 30, r = g [0.5 sin 10t, 0, -1] (body input
// 0.5 g sin 10t along +x), t = 2 pi: D = (1.165, 0, -0.424), |D| = 1.239 m
// (seed algorithm, dt 1e-4). We get |D| = 1.23812 m at dt 1e-4 and 1e-5, as
// dda newmark (test_newmark.cpp) and the second integrator below (to 1e-7):
// the motion is on a line. The 0.07 % gap is the 3-digit rounding of the
// published value, and perhaps its scheme's stops. (Before the slow-block
// rule of SlidingSimulator::step we got 1.23796 m at dt 1e-4, 1.23819 m at
// 1e-5: round-off across the dip, amplified after every start, stopped the
// block spuriously, by an amount that changed with dt.)
TEST(Sliding3d, V3HorizontalSinusoid) {
  const Excitation in = sinusoid(Vec3::UnitX(), 0.5 * kG, 10.0, 0.0, InputMeaning::body);
  const SlidingRun run = run_sliding(single(20, 90, 30, in), 1e-4, 2.0 * dda::kPi);
  const SlidingState& end = run.samples.back();
  EXPECT_NEAR(end.t, 2.0 * dda::kPi, 1e-9);
  EXPECT_NEAR(end.u.norm(), 1.239, 0.01 * 1.239);
  EXPECT_NEAR(end.u.norm(), 1.238121, 2e-6);
  EXPECT_NEAR(end.u.x(), 1.165, 0.01 * 1.165);
  // Cross-slope: zero up to round-off (the normal of 20/090 has a y part of
  // 1e-17; it used to grow to 5e-9 m, amplified at every start).
  EXPECT_NEAR(end.u.y(), 0.0, 1e-15);
  EXPECT_NEAR(end.u.z(), -0.424, 0.01 * 0.424);
  // Downslope only: no upslope motion, yield up is 1.19 g (never reached).
  for (const auto& s : run.samples) EXPECT_GE(s.v.x(), -1e-12);
  // The same input as a ground acceleration of the opposite sign is identical.
  const Excitation ground = sinusoid(-Vec3::UnitX(), 0.5 * kG, 10.0, 0.0, InputMeaning::ground);
  const SlidingRun g = run_sliding(single(20, 90, 30, ground), 1e-4, 2.0 * dda::kPi);
  EXPECT_NEAR((g.samples.back().u - end.u).norm(), 0.0, 1e-12);
}

// docs/validation.md V4: phi = 10 under gravity: a = 2.3731 m/s^2 along the line
// (trend 000.5, plunge 27.63), reactions 0.629 W each.
TEST(Sliding3d, V4WedgeUnderGravity) {
  const SlidingRun run = run_sliding(v4_wedge(10, no_input()), 1e-3, 2.0);
  const SlidingState& end = run.samples.back();
  const double a = 2.0 * end.u.norm() / (2.0 * 2.0);
  EXPECT_NEAR(a, 2.3731, 1e-4);
  EXPECT_NEAR(end.v.norm() / 2.0, 2.3731, 1e-4);
  const TrendPlunge tp = trend_plunge(end.u);
  EXPECT_NEAR(tp.trend_deg, 0.5, 0.005);
  EXPECT_NEAR(tp.plunge_deg, 27.63, 0.005);
  EXPECT_NEAR(end.n1 / kG, 0.629, 5e-4);
  EXPECT_NEAR(end.n2 / kG, 0.629, 5e-4);
  EXPECT_EQ(end.mode, ContactMode::double_face);
  EXPECT_TRUE(run.events.empty());
}

// Strong shaking along the line (north-south), starting with a pull to the
// south (up the line): the V4 wedge with phi 10 first slides up the line
// (driving 0.87 g up against about 0.45 g of friction at the peak, by hand),
// then its velocity reverses and it slides down.
TEST(Sliding3d, VelocityCanReverse) {
  const Excitation in = sinusoid(-Vec3::UnitY(), 1.5 * kG, 2.0 * dda::kPi * 1.0, 0.0, InputMeaning::body);
  const SlidingRun run = run_sliding(v4_wedge(10, in), 1e-4, 2.0);
  bool up = false, down = false;
  const Vec3 ref = run.reference;
  for (const auto& s : run.samples) {
    up = up || s.v.dot(ref) < -1e-3;
    down = down || s.v.dot(ref) > 1e-3;
    // Velocity stays on the line of intersection.
    EXPECT_LT((s.v - s.v.dot(ref) * ref).norm(), 1e-9);
  }
  EXPECT_TRUE(up);
  EXPECT_TRUE(down);
}

// A strong push towards the east unloads plane 1 (the west flank) of the V4
// wedge: the solver reports the loss of contact and continues on plane 2 alone; an upward body
// acceleration above g lifts a single-face block off: reported, run ends.
TEST(Sliding3d, ContactLossAndLiftOff) {
  const Excitation east = sinusoid(Vec3::UnitX(), 2.0 * kG, 2.0, 0.0, InputMeaning::body);
  const SlidingRun run = run_sliding(v4_wedge(30, east), 1e-3, 1.0);
  ASSERT_FALSE(run.events.empty());
  EXPECT_NE(run.events.front().what.find("lost contact with plane 1"), std::string::npos);
  bool single2 = false;
  for (const auto& s : run.samples) single2 = single2 || s.mode == ContactMode::face2;
  EXPECT_TRUE(single2);

  const Excitation up = sinusoid(Vec3::UnitZ(), 2.0 * kG, 2.0, 0.0, InputMeaning::body);
  const SlidingRun lift = run_sliding(single(20, 90, 30, up), 1e-3, 2.0);
  EXPECT_EQ(lift.samples.back().mode, ContactMode::lifted);
  ASSERT_EQ(lift.events.size(), 1u);
  EXPECT_NE(lift.events[0].what.find("lift-off"), std::string::npos);
  // 2 sin(2t) = 1 first at t = asin(0.5)/2 = 0.2618 s (hand calculation).
  EXPECT_NEAR(lift.events[0].t, std::asin(0.5) / 2.0, 1.5e-3);
}

TEST(Sliding3d, BadSetups) {
  SlidingModel m = v4_wedge(30, no_input());
  m.planes[1] = m.planes[0];
  EXPECT_THROW(SlidingSimulator(m, 1e-3), dda::InputError);
  SlidingModel n = single(20, 90, 30, no_input());
  n.friction.clear();
  EXPECT_THROW(SlidingSimulator(n, 1e-3), dda::InputError);
  EXPECT_THROW(SlidingSimulator(single(20, 90, 30, no_input()), 0.0), dda::InputError);
}

// ---------------------------------------------------------------------------
// A second integrator of the same physics (one plane, Coulomb friction), for
// the comparisons below. It shares the friction law and nothing of the
// production step:
//  * it works in the plane's own coordinates, (down the dip, along the
//    strike), not with 3D vectors kept on the plane;
//  * sliding is classical RK4 on dw/dt = m(t) - F(t) w/|w|, friction always
//    against the current velocity (no friction state held over a step);
//    steps are at most h and end on the record's samples (its kinks) and on
//    the output times;
//  * this equation is stiff at low speed (the velocity's direction relaxes
//    towards the driving at the rate F/|w|), so steps are also kept below
//    kAlpha |w| / (F + |m|): RK4 stays stable down to rest;
//  * from rest the block starts when |m| first exceeds F (located by
//    bisection); during its first step (h) the stiff relaxation keeps the
//    velocity along the driving, w' = (|m| - F) m/|m|, which is integrated
//    there by Simpson's rule;
//  * it stops when friction decelerates it and the speed falls below 1e-11
//    m/s; it stays if |m| <= F, otherwise it starts again at once.
// Lift-off (N < 0) ends the integration.
namespace second {

using V2 = Eigen::Vector2d;

struct Sample {
  double t = 0.0;
  Vec3 u = Vec3::Zero();
};

struct Motion {
  std::vector<Sample> samples;  // at the requested output times
  Vec3 u = Vec3::Zero(), v = Vec3::Zero();
  double t = 0.0;
  bool lifted = false;
  int starts = 0;
};

Motion slide(const SlidingModel& model, double h, double duration, std::vector<double> outputs,
             std::vector<double> kinks = {}) {
  constexpr double kAlpha = 0.5, kRest = 1e-11;
  const Vec3 n = model.planes.at(0).normal(), d = model.planes[0].dip_vector(), s = n.cross(d);
  const FrictionLaw& law = model.friction.at(0);
  struct Load {
    V2 m;      // driving part in (dip, strike) coordinates
    double N;  // normal reaction
  };
  auto load = [&](double t) {
    const Vec3 r = Vec3(0, 0, -model.gravity) + model.input.body(t);
    return Load{V2(r.dot(d), r.dot(s)), -r.dot(n)};
  };
  auto excess = [&](double t) {  // |m| - F of a block at rest
    const Load L = load(t);
    return L.m.norm() - law.mu(t, 0.0) * L.N;
  };
  auto accel = [&](double t, const V2& w) -> V2 {
    const Load L = load(t);
    const double speed = w.norm();
    return L.m - law.mu(t, speed) * L.N * w / speed;
  };
  auto along_driving = [&](double t) -> V2 {  // (|m| - F)+ m/|m|
    const Load L = load(t);
    const double mm = L.m.norm(), F = law.mu(t, 0.0) * L.N;
    return mm > F ? V2((mm - F) * L.m / mm) : V2(0, 0);
  };

  std::vector<double> ends = kinks;
  ends.insert(ends.end(), outputs.begin(), outputs.end());
  ends.push_back(duration);
  std::sort(ends.begin(), ends.end());
  std::sort(outputs.begin(), outputs.end());

  Motion out;
  double t = 0.0;
  V2 x(0, 0), w(0, 0);
  enum class State { rest, starting, sliding } state = excess(0.0) <= 0.0 ? State::rest : State::starting;
  std::size_t next_end = 0, next_out = 0;
  auto record = [&] {
    while (next_out < outputs.size() && t >= outputs[next_out] - 1e-12) {
      out.samples.push_back({outputs[next_out], x.x() * d + x.y() * s});
      ++next_out;
    }
  };
  while (t < duration - 1e-13) {
    while (next_end < ends.size() && ends[next_end] <= t + 1e-13) ++next_end;
    const double t_next = std::min(t + h, next_end < ends.size() ? ends[next_end] : duration);
    if (load(t).N < 0.0) {
      out.lifted = true;
      break;
    }
    switch (state) {
      case State::rest:
        if (excess(t_next) <= 0.0) {
          t = t_next;
        } else {  // it starts within this step
          double a = t, b = t_next;
          for (int k = 0; k < 200 && b - a > 1e-15; ++k) {
            const double c = 0.5 * (a + b);
            (excess(c) > 0.0 ? b : a) = c;
          }
          t = b;
          state = State::starting;
        }
        break;
      case State::starting: {  // a full step h (or to the end), along the driving
        ++out.starts;
        const double hh = std::min(h, duration - t);
        const V2 e0 = along_driving(t), e1 = along_driving(t + hh / 4), e2 = along_driving(t + hh / 2),
                 e3 = along_driving(t + 3 * hh / 4), e4 = along_driving(t + hh);
        const V2 w_half = hh / 12 * (e0 + 4 * e1 + e2), w_end = w_half + hh / 12 * (e2 + 4 * e3 + e4);
        x += hh / 6 * (4 * w_half + w_end);
        w = w_end;
        t += hh;
        state = w.norm() > 0.0 ? State::sliding : State::rest;
        break;
      }
      case State::sliding: {
        const double speed = w.norm();
        const Load L = load(t);
        const double F = law.mu(t, speed) * L.N;
        if (speed < kRest && F > L.m.dot(w) / speed) {
          // Comes to rest (what is left of its motion is negligible).
          w.setZero();
          state = excess(t) <= 0.0 ? State::rest : State::starting;
          break;
        }
        const double hs = std::min(t_next - t, kAlpha * speed / (F + L.m.norm()));
        const V2 k1 = accel(t, w);
        const V2 k2 = accel(t + hs / 2, w + hs / 2 * k1);
        const V2 k3 = accel(t + hs / 2, w + hs / 2 * k2);
        const V2 k4 = accel(t + hs, w + hs * k3);
        x += hs / 6 * (w + 2 * (w + hs / 2 * k1) + 2 * (w + hs / 2 * k2) + (w + hs * k3));
        w += hs / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
        t += hs;
        break;
      }
    }
    record();
  }
  out.t = t;
  out.u = x.x() * d + x.y() * s;
  out.v = w.x() * d + w.y() * s;
  return out;
}

}  // namespace second

namespace {

// Largest distance between the production history (every 0.1 s) and the
// second integrator's, relative to the largest displacement of the latter;
// and the same for the final displacement alone.
struct Gap {
  double path = 0.0, end = 0.0;
};

Gap gap(const SlidingModel& model, double dt, double duration, const second::Motion& ref) {
  const int every = static_cast<int>(std::lround(0.1 / dt));
  const SlidingRun run = run_sliding(model, dt, duration, every);
  EXPECT_EQ(run.samples.size(), ref.samples.size() + 1);  // + the start
  double worst = 0.0, largest = 0.0;
  const std::size_t n = std::min(run.samples.size() - 1, ref.samples.size());
  for (std::size_t k = 0; k < n; ++k) {
    EXPECT_NEAR(run.samples[k + 1].t, ref.samples[k].t, 1e-9);
    worst = std::max(worst, (run.samples[k + 1].u - ref.samples[k].u).norm());
    largest = std::max(largest, ref.samples[k].u.norm());
  }
  Gap g;
  g.path = worst / largest;
  g.end = (run.samples.back().u - ref.u).norm() / ref.u.norm();
  return g;
}

std::vector<double> every_tenth(double duration) {
  std::vector<double> t;
  for (int k = 1; k * 0.1 < duration - 1e-9; ++k) t.push_back(k * 0.1);
  t.push_back(duration);
  return t;
}

// A synthetic three-component record (m/s^2, east, north, up) sampled every
// 0.01 s over 6 s: a few sines per component under an envelope that rises
// over 1 s, holds to 4 s and dies out at 6 s. Piecewise linear between the
// samples, as every record.
std::shared_ptr<const dda::AccelRecord> record3(double vertical) {
  auto rec = std::make_shared<dda::AccelRecord>();
  rec->source = "synthetic";
  for (int i = 0; i <= 600; ++i) {
    const double t = 0.01 * i;
    const double env = std::min({1.0, t, (6.0 - t) / 2.0}), w = 2 * dda::kPi * t;  // w: 2 pi t
    rec->t.push_back(t);
    rec->a[0].push_back(env * kG * (0.30 * std::sin(1.3 * w) + 0.12 * std::sin(3.1 * w + 1)));
    rec->a[1].push_back(env * kG * (0.25 * std::sin(0.9 * w + 2) + 0.10 * std::cos(2.2 * w)));
    rec->a[2].push_back(env * kG * vertical * std::sin(2.7 * w + 0.5));
  }
  return rec;
}

constexpr double kStrikeDuration = 2.0 * dda::kPi;

// The case that showed the error: the V3 block (20/090, phi 30) shaken
// along the strike (north) by a body acceleration 0.5 g sin 10t.
SlidingModel strike_case() {
  return single(20, 90, 30, sinusoid(Vec3::UnitY(), 0.5 * kG, 10.0, 0.0, InputMeaning::body));
}

}  // namespace

// The second integrator itself: the first slip of V3 (shaking in the dip
// plane, a line motion) has a closed form, a(t) = A sin 10t + B with
// A = 0.5 g (cos 20 + tan 30 sin 20), B = g (sin 20 - tan 30 cos 20), from
// rest at sin 10t* = -B/A; and it gives the same strike-case history at h and
// h/2.
TEST(Sliding3dSecondIntegrator, ClosedFormAndConvergence) {
  const SlidingModel v3 = single(20, 90, 30, sinusoid(Vec3::UnitX(), 0.5 * kG, 10.0, 0.0, InputMeaning::body));
  const double c = std::cos(dda::deg2rad(20)), s = std::sin(dda::deg2rad(20)), mu = std::tan(dda::deg2rad(30));
  const double A = 0.5 * kG * (c + mu * s), B = kG * (s - mu * c);
  const double ts = std::asin(-B / A) / 10.0, T = 0.2;
  const double u = -A / 100.0 * (std::sin(10 * T) - std::sin(10 * ts)) + A / 10.0 * std::cos(10 * ts) * (T - ts) +
                   B * (T - ts) * (T - ts) / 2.0;
  const second::Motion first = second::slide(v3, 1e-3, T, {});
  EXPECT_NEAR(first.u.norm(), u, 1e-10 * u);  // 0.0280895 m
  EXPECT_EQ(first.starts, 1);

  const SlidingModel strike = strike_case();
  const second::Motion a = second::slide(strike, 1e-4, kStrikeDuration, every_tenth(kStrikeDuration));
  const second::Motion b = second::slide(strike, 5e-5, kStrikeDuration, every_tenth(kStrikeDuration));
  ASSERT_EQ(a.samples.size(), b.samples.size());
  for (std::size_t k = 0; k < a.samples.size(); ++k)
    EXPECT_LT((a.samples[k].u - b.samples[k].u).norm(), 1e-8 * a.u.norm());
  EXPECT_EQ(a.starts, 20);  // two slips per cycle, one each way along the strike
  EXPECT_FALSE(a.lifted);
}

// Shaking along the strike of a single plane: the block slides down the dip
// and along the strike at once, so its velocity turns while friction acts.
// The second integrator gives |D| = 0.0573836 m at 2 pi s. Before the fix the
// production step converged to 0.05673 m, 1.1 % low (dt 1e-4: -0.31 %, 1e-5:
// -1.24 %, 1e-6: -1.14 %): after every start the block stuttered (stopped and
// restarted every few steps) for a few milliseconds whatever dt. Now it is
// first order: +1.5e-4, +1.5e-5 at dt 1e-4, 1e-5.
TEST(Sliding3d, StrikeShakingAgreesWithSecondIntegrator) {
  const SlidingModel model = strike_case();
  const second::Motion ref = second::slide(model, 1e-4, kStrikeDuration, every_tenth(kStrikeDuration));
  EXPECT_NEAR(ref.u.norm(), 0.0573836, 1e-7);
  // It moves along the strike and back: the path matters, not only the end.
  double across = 0.0;
  for (const auto& s : ref.samples) across = std::max(across, std::abs(s.u.y()));
  EXPECT_GT(across, 0.003);
  const Gap coarse = gap(model, 1e-4, kStrikeDuration, ref);
  const Gap fine = gap(model, 1e-5, kStrikeDuration, ref);
  std::printf("strike: path / end gap %.2e / %.2e at dt 1e-4, %.2e / %.2e at dt 1e-5\n", coarse.path, coarse.end,
              fine.path, fine.end);
  EXPECT_LT(coarse.path, 3e-4);
  EXPECT_LT(coarse.end, 3e-4);
  EXPECT_LT(fine.path, 3e-5);
  EXPECT_LT(fine.end, 3e-5);
  // Converging on the second integrator, not on a value of its own.
  EXPECT_LT(fine.end, 0.2 * coarse.end);
  // The same on a plane of any orientation (35/130, strike towards 220).
  const SlidingModel oblique =
      single(35, 130, 38, sinusoid(horizontal(220), 0.6 * kG, 7.0, 0.5, InputMeaning::ground));
  const second::Motion ref2 = second::slide(oblique, 1e-4, 4.0, every_tenth(4.0));
  const Gap coarse2 = gap(oblique, 1e-4, 4.0, ref2), fine2 = gap(oblique, 1e-5, 4.0, ref2);
  std::printf("strike, 35/130: |D| = %.7f m, path / end gap %.2e / %.2e at dt 1e-4, %.2e / %.2e at dt 1e-5\n",
              ref2.u.norm(), coarse2.path, coarse2.end, fine2.path, fine2.end);
  EXPECT_LT(coarse2.path, 5e-4);
  EXPECT_LT(fine2.path, 5e-5);
  EXPECT_LT(fine2.end, 5e-5);
  EXPECT_LT(fine2.end, 0.2 * coarse2.end);
}

// Shaking in the dip plane (V3): a line motion. The velocity has no part
// across the dip; the production step keeps round-off there at round-off.
TEST(Sliding3d, DipShakingAgreesWithSecondIntegrator) {
  const SlidingModel model = single(20, 90, 30, sinusoid(Vec3::UnitX(), 0.5 * kG, 10.0, 0.0, InputMeaning::body));
  const second::Motion ref = second::slide(model, 1e-4, kStrikeDuration, every_tenth(kStrikeDuration));
  const Gap coarse = gap(model, 1e-4, kStrikeDuration, ref), fine = gap(model, 1e-5, kStrikeDuration, ref);
  std::printf("dip: |D| = %.7f m, path / end gap %.2e / %.2e at dt 1e-4, %.2e / %.2e at dt 1e-5\n", ref.u.norm(),
              coarse.path, coarse.end, fine.path, fine.end);
  EXPECT_LT(coarse.path, 1e-5);
  EXPECT_LT(fine.path, 1e-5);
}

// A record (east and north, and `vertical` times a vertical component, as
// ground acceleration) on a plane 25/130: neither along the dip nor the
// strike. `label` names the case in the printout.
void record_agrees_with_second_integrator(double vertical, const char* label) {
  const auto rec = record3(vertical);
  const SlidingModel model = single(25, 130, 32, excitation_from_record(rec, InputMeaning::ground));
  const second::Motion ref = second::slide(model, 1e-4, 6.0, every_tenth(6.0), rec->t);
  EXPECT_FALSE(ref.lifted);
  EXPECT_GT(ref.starts, 3);
  const Gap coarse = gap(model, 1e-4, 6.0, ref);
  const Gap fine = gap(model, 1e-5, 6.0, ref);
  std::printf("%s: |D| = %.7f m, %d starts, path / end gap %.2e / %.2e at dt 1e-4, %.2e / %.2e at 1e-5\n", label,
              ref.u.norm(), ref.starts, coarse.path, coarse.end, fine.path, fine.end);
  EXPECT_LT(coarse.path, 3e-4);
  EXPECT_LT(coarse.end, 3e-4);
  EXPECT_LT(fine.path, 3e-5);
  EXPECT_LT(fine.end, 3e-5);
}

// Two horizontal components.
TEST(Sliding3d, TwoComponentRecordAgreesWithSecondIntegrator) {
  record_agrees_with_second_integrator(0.0, "two components");
}

// Three components: the vertical one changes the normal reaction, hence the
// friction capacity, all the time.
TEST(Sliding3d, ThreeComponentRecordAgreesWithSecondIntegrator) {
  record_agrees_with_second_integrator(0.3, "three components");
}
