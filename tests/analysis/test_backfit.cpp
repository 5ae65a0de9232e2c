// Friction back-analysis (seed report ch. 2, three-segment fits and mu vs
// ln v): synthetic "measured" histories made by the forward solution with
// known friction must be recovered.
#include <gtest/gtest.h>

#include <cmath>

#include "dda/analysis/backfit.hpp"
#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"

using namespace dda::analysis;

namespace {

constexpr double kG = 9.81;

SlidingModel shaking_table_wedge() {
  // The V4 wedge on a table shaken at 2 Hz along the line (north), 0.45 g
  // body acceleration ramped up over 1 s.
  SlidingModel m;
  m.planes = {Plane{51.4, 65.8}, Plane{51.4, 295.2}};
  m.friction = {FrictionLaw::constant_angle(30), FrictionLaw::constant_angle(30)};
  m.input = sinusoid(Vec3::UnitY(), 0.45 * kG, 2.0 * dda::kPi * 2.0, 1.0, InputMeaning::body);
  m.gravity = kG;
  return m;
}

MeasuredHistory sample(const SlidingRun& run, double every, bool vector_form) {
  MeasuredHistory h;
  h.vector_form = vector_form;
  double next = every;
  for (std::size_t i = 1; i < run.samples.size(); ++i) {
    const auto& a = run.samples[i - 1];
    const auto& b = run.samples[i];
    while (next <= b.t + 1e-12) {
      const double w = (next - a.t) / (b.t - a.t);
      const Vec3 u = (1 - w) * a.u + w * b.u;
      h.t.push_back(next);
      if (vector_form)
        h.u.push_back(u);
      else
        h.s.push_back(u.dot(run.reference));
      next += every;
    }
  }
  return h;
}

}  // namespace

// Three segments with 32, 30, 28 degrees (the seed's Table 4 pattern of
// degradation); the synthetic history is made at dt 1e-4, the fit uses
// dt 5e-4, so the recovery is not an exact inverse: within 0.1 degree.
TEST(Backfit, ThreeSegmentsRecovered) {
  SlidingModel truth = shaking_table_wedge();
  const FrictionLaw table = FrictionLaw::table({0, 4, 4, 8, 8}, {32, 32, 30, 30, 28}, "test");
  truth.friction = {table, table};
  const SlidingRun run = run_sliding(truth, 1e-4, 12.0);
  const MeasuredHistory measured = sample(run, 0.01, false);
  ASSERT_GT(measured.s.back(), 0.05);  // it slides in every segment (checked below)
  BackfitOptions o;
  o.breaks = {4.0, 8.0};
  o.dt = 5e-4;
  o.phi_min = 20;
  o.phi_max = 45;
  const BackfitResult r = backfit(shaking_table_wedge(), measured, o);
  ASSERT_EQ(r.segments.size(), 3u);
  const double expected[3] = {32, 30, 28};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(r.segments[static_cast<std::size_t>(k)].phi_deg, expected[k], 0.1) << "segment " << k;
    EXPECT_GT(r.segments[static_cast<std::size_t>(k)].mean_speed, 0.0);
  }
  EXPECT_LT(r.rms, 1e-3);
  // Degrading friction with faster sliding: the regression slope is negative.
  ASSERT_TRUE(r.regression.valid);
  EXPECT_LT(r.regression.b, 0.0);
}

// mu = 0.6 - 0.02 ln(v) (v in m/s, floored at 1e-3) on a 30/180 plane shaken
// along the dip at 1 Hz: the direct fit of (a, b) to the whole displacement
// history recovers them within a few percent (fit at dt 2e-4 against a
// history made at dt 1e-4: about 1% off in b from the step difference).
TEST(Backfit, LogVelocityRecovered) {
  SlidingModel truth;
  truth.planes = {Plane{30, 180}};
  truth.friction = {FrictionLaw::log_velocity(0.6, -0.02, 1.0, 1e-3)};
  truth.input = sinusoid(Vec3(0, -1, 0), 0.4 * kG, 2.0 * dda::kPi, 0.5, InputMeaning::body);
  truth.gravity = kG;
  const SlidingRun run = run_sliding(truth, 1e-4, 6.0);
  const MeasuredHistory measured = sample(run, 0.01, true);
  SlidingModel start = truth;
  start.friction = {FrictionLaw::constant_angle(30)};
  BackfitOptions o;
  o.breaks = {2.0, 4.0};
  o.dt = 2e-4;
  o.fit_log_velocity = true;
  o.v_min = 1e-3;
  const BackfitResult r = backfit(start, measured, o);
  ASSERT_TRUE(r.direct.valid);
  EXPECT_NEAR(r.direct.a, 0.6, 0.03 * 0.6);
  EXPECT_NEAR(r.direct.b, -0.02, 0.05 * 0.02);
  EXPECT_LT(r.direct.rms, r.rms + 1e-12);  // at least as good as the piecewise fit
}

TEST(Backfit, BadInput) {
  MeasuredHistory h;
  h.t = {0.0, 1.0};
  h.s = {0.0, 0.0};
  BackfitOptions o;
  o.breaks = {2.0};  // outside the measured span
  EXPECT_THROW(backfit(shaking_table_wedge(), h, o), dda::InputError);
  o.breaks = {};
  o.phi_min = 40;
  o.phi_max = 30;
  EXPECT_THROW(backfit(shaking_table_wedge(), h, o), dda::InputError);
}

// Samples every 0.01 s from 0.01 to 12 s, segments cut at 4 and 8 s: a
// sample at a boundary belongs to the segment that ends there, so the
// segments hold 400, 400 and 400 samples whatever the fitting step (the
// time reached by summing steps differs from 4, 8 and 12 by rounding, which
// used to push boundary samples into the next segment or drop the last one).
TEST(Backfit, BoundarySamplesBelongToTheSegmentThatEndsThere) {
  SlidingModel truth = shaking_table_wedge();
  const SlidingRun run = run_sliding(truth, 1e-4, 12.0);
  const MeasuredHistory measured = sample(run, 0.01, false);
  ASSERT_EQ(measured.t.size(), 1200u);
  for (const double dt : {1e-3, 5e-4, 3e-4, 2e-4, 1e-4}) {
    BackfitOptions o;
    o.breaks = {4.0, 8.0};
    o.dt = dt;
    o.phi_min = 25;
    o.phi_max = 35;
    o.tolerance_deg = 1e-2;
    const BackfitResult r = backfit(shaking_table_wedge(), measured, o);
    ASSERT_EQ(r.segments.size(), 3u);
    for (const SegmentFit& s : r.segments) EXPECT_EQ(s.samples, 400) << "dt " << dt << ", segment at " << s.t0;
  }
}

