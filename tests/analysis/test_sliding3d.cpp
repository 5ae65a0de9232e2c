// The 3D analytical sliding solution (seed report, ch. 2): CASES.md V1
// (closed form under gravity), V3 (block on 20/090 under horizontal
// sinusoid), V4 (wedge under gravity alone), and contact changes.
#include <gtest/gtest.h>

#include <cmath>

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

// CASES.md V1, alpha = 30, phi = 20: a = 1.81281 m/s^2, s(1 s) = 0.90641 m,
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

// CASES.md V3: plane 20/090, phi 30, r = g [0.5 sin 10t, 0, -1] (body input
// 0.5 g sin 10t along +x), t = 2 pi: D = (1.165, 0, -0.424), |D| = 1.239 m
// (seed algorithm, dt 1e-4). We get |D| = 1.2381 m (converged: the same to
// 5 digits at dt 1e-5); the 0.07% gap is within the 3-digit rounding plus the
// seed scheme's handling of the stops (its friction direction lags a step).
TEST(Sliding3d, V3HorizontalSinusoid) {
  const Excitation in = sinusoid(Vec3::UnitX(), 0.5 * kG, 10.0, 0.0, InputMeaning::body);
  const SlidingRun run = run_sliding(single(20, 90, 30, in), 1e-4, 2.0 * dda::kPi);
  const SlidingState& end = run.samples.back();
  EXPECT_NEAR(end.t, 2.0 * dda::kPi, 1e-9);
  EXPECT_NEAR(end.u.norm(), 1.239, 0.01 * 1.239);
  EXPECT_NEAR(end.u.x(), 1.165, 0.01 * 1.165);
  // Cross-slope: zero up to round-off (the normal of 20/090 has a y part of
  // 1e-17, which the friction direction of a just-starting block amplifies).
  EXPECT_NEAR(end.u.y(), 0.0, 1e-6);
  EXPECT_NEAR(end.u.z(), -0.424, 0.01 * 0.424);
  // Downslope only: no upslope motion, yield up is 1.19 g (never reached).
  for (const auto& s : run.samples) EXPECT_GE(s.v.x(), -1e-12);
  // The same input as a ground acceleration of the opposite sign is identical.
  const Excitation ground = sinusoid(-Vec3::UnitX(), 0.5 * kG, 10.0, 0.0, InputMeaning::ground);
  const SlidingRun g = run_sliding(single(20, 90, 30, ground), 1e-4, 2.0 * dda::kPi);
  EXPECT_NEAR((g.samples.back().u - end.u).norm(), 0.0, 1e-12);
}

// CASES.md V4: phi = 10 under gravity: a = 2.3731 m/s^2 along the line
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
