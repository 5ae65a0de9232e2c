// The start-up relaxation's test for a friction fixed point that runs away
// (FrictionRunaway, df/src/core/start_up_relax.hpp), on hand-made sequences of
// the largest change of a sliding contact's friction between iterates.
#include <gtest/gtest.h>

#include "core/start_up_relax.hpp"

namespace dda::df {
namespace {

// The jointed cube's divergence: each change 1.65 times the last, states
// unchanged. The first update only sets the reference; the fourth growth
// in a row (the fifth update) gives the solve up.
TEST(FrictionRunaway, GeometricGrowthWithoutStateChangesIsARunaway) {
  FrictionRunaway r;
  double change = 1e3;
  EXPECT_FALSE(r.diverging(false, change));
  for (int growth = 1; growth <= 3; ++growth) EXPECT_FALSE(r.diverging(false, change *= 1.65)) << growth;
  EXPECT_TRUE(r.diverging(false, change *= 1.65));
}

// A converging fixed point (changes shrinking by half) is never one, nor
// growth interrupted by a state change or by one smaller change.
TEST(FrictionRunaway, ConvergenceOrInterruptedGrowthIsNot) {
  FrictionRunaway shrinking;
  for (double change = 1e3; change > 1e-3; change /= 2) EXPECT_FALSE(shrinking.diverging(false, change));

  FrictionRunaway state_change;
  const double grows[] = {1, 2, 4, 8, 16, 32};
  for (int k = 0; k < 6; ++k) EXPECT_FALSE(state_change.diverging(k == 3, grows[k])) << k;

  FrictionRunaway dip;
  const double dips[] = {1, 2, 4, 3, 6, 12, 24, 48};
  for (int k = 0; k < 7; ++k) EXPECT_FALSE(dip.diverging(false, dips[k])) << k;
  EXPECT_TRUE(dip.diverging(false, dips[7]));  // 3 -> 6 -> 12 -> 24 -> 48: growing four updates running
}

}  // namespace
}  // namespace dda::df
