// The step-length rule of both solvers (df/src/core/step_control.hpp): cut by 3
// when the contacts do not settle, to 0.9 of what the displacement limit
// allows (at least by half) when a vertex moves too far, never below the
// shortest step, and 10 % regrowth after easy steps. Every expected number
// is worked by hand from those rules, written next to it.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "core/step_control.hpp"

namespace dda::df {
namespace {

// control.dt 0.01 s, min_dt_ratio 1e-3 (shortest step 1e-5 s), and a vertex
// may move 0.002 m in a step (g2 0.01 of a half-size of 0.2 m).
const StepControl rule(0.01, 1e-5, 0.002);

TEST(StepControl, TriesTheCurrentStepOrTheShorterOneAskedFor) {
  const StepControl::Try whole = StepControl::next_try(0.01, 1e300);
  EXPECT_EQ(whole.dt, 0.01);
  EXPECT_FALSE(whole.shortened);
  // The run's end 4 ms away: a 4 ms step, marked shortened.
  const StepControl::Try end = StepControl::next_try(0.01, 0.004);
  EXPECT_EQ(end.dt, 0.004);
  EXPECT_TRUE(end.shortened);
}

TEST(StepControl, KeepsAStepThatSettledWithinTheLimit) {
  EXPECT_FALSE(rule.redo_dt(true, 0.001, 0.01));
  EXPECT_FALSE(rule.redo_dt(true, 0.002, 0.01));  // at the limit is within it
}

TEST(StepControl, CutsByThreeWhenTheContactsDoNotSettle) {
  // 9 ms / 3 = 3 ms.
  EXPECT_DOUBLE_EQ(rule.redo_dt(false, 0.001, 0.009).value(), 0.003);
}

TEST(StepControl, CutsToWhatTheDisplacementLimitAllows) {
  // 3 mm moved: 0.9 * 2 / 3 = 0.6, more than a half, so the step halves: 5 ms.
  EXPECT_DOUBLE_EQ(rule.redo_dt(true, 0.003, 0.01).value(), 0.005);
  // 9 mm moved: 0.9 * 2 / 9 = 0.2 of 10 ms = 2 ms.
  EXPECT_DOUBLE_EQ(rule.redo_dt(true, 0.009, 0.01).value(), 0.002);
  // Not settled and too far: the displacement's cut (2 ms), not the third (3.33 ms).
  EXPECT_DOUBLE_EQ(rule.redo_dt(false, 0.009, 0.01).value(), 0.002);
}

TEST(StepControl, NeverCutsBelowTheShortestStep) {
  // 20 us / 3 = 6.7 us is below the shortest step: 10 us.
  EXPECT_EQ(rule.redo_dt(false, 0.001, 2e-5).value(), 1e-5);
  // At the shortest step (to round-off) the try is kept, settled or not.
  EXPECT_TRUE(rule.at_min_dt(1e-5));
  EXPECT_TRUE(rule.at_min_dt(1e-5 * (1 + 1e-10)));
  EXPECT_FALSE(rule.redo_dt(false, 0.5, 1e-5));
  EXPECT_FALSE(rule.redo_dt(false, 0.5, 1e-5 * (1 + 1e-10)));
  // One part in 10^4 above it is a step that can still be cut.
  EXPECT_FALSE(rule.at_min_dt(1.0001e-5));
  EXPECT_EQ(rule.redo_dt(false, 0.001, 1.0001e-5).value(), 1e-5);
}

TEST(StepControl, GrowsBackByTenPerCentAfterEasySteps) {
  EXPECT_DOUBLE_EQ(rule.after_step(0.005, false, 0), 0.0055);
  // 9.5 ms * 1.1 = 10.45 ms is capped at the user's 10 ms.
  EXPECT_EQ(rule.after_step(0.0095, false, 0), 0.01);
  // A step that was cut, or shortened to land on an end, does not grow.
  EXPECT_EQ(rule.after_step(0.005, false, 1), 0.005);
  EXPECT_EQ(rule.after_step(0.005, true, 0), 0.005);
}

TEST(StepControl, AHardStepAndTheWayBackToTheUsersStep) {
  // A step whose contacts settle only on the third try: 10 ms, 3.33 ms,
  // then kept at 1.11 ms with two cuts, which it keeps for the next step.
  double dt = 0.01;
  int cuts = 0;
  std::optional<double> redo;
  for (bool settled : {false, false, true}) {
    redo = rule.redo_dt(settled, 0.001, dt);
    if (!redo) break;
    dt = *redo;
    ++cuts;
  }
  EXPECT_EQ(cuts, 2);
  EXPECT_DOUBLE_EQ(dt, 0.01 / 9);
  dt = rule.after_step(dt, false, cuts);
  EXPECT_DOUBLE_EQ(dt, 0.01 / 9);
  // Easy steps from there: back at 10 ms after ceil(ln 9 / ln 1.1) =
  // ceil(23.05) = 24 of them.
  int easy = 0;
  while (dt < 0.01) dt = rule.after_step(dt, false, 0), ++easy;
  EXPECT_EQ(easy, 24);
  EXPECT_EQ(dt, 0.01);
}

}  // namespace
}  // namespace dda::df
