// Empirical Newmark-displacement regressions against hand computations of
// their equations (docs/analytical.md, "Empirical regressions").
#include <gtest/gtest.h>

#include <cmath>

#include "dda/analysis/displacement_regressions.hpp"

using namespace dda::analysis;

// Jibson (2007), k_c/a_max model, k_y = 0.1, PGA = 0.4 g, r = 0.25:
// log(0.75) = -0.1249387, log(0.25) = -0.6020600;
// log D = 0.215 + 2.341 (-0.1249387) - 1.438 (-0.6020600)
//       = 0.215 - 0.2924815 + 0.8657623 = 0.7882807 -> D = 6.14159 cm.
TEST(DisplacementRegressions, JibsonRatio) {
  const Regression r = jibson2007_ratio(0.1, 0.4);
  EXPECT_NEAR(r.median_cm, 6.14159, 5e-5);
  EXPECT_DOUBLE_EQ(r.sigma, 0.510);
  EXPECT_EQ(jibson2007_ratio(0.5, 0.4).median_cm, 0.0);  // k_y above the PGA: no sliding
}

// Jibson (2007), Arias and k_c model, Ia = 1.2 m/s, k_y = 0.1:
// log D = 2.401 log 1.2 - 3.481 log 0.1 - 3.230 = 2.401 (0.0791812) + 3.481 - 3.230
//       = 0.1901142 + 0.251 = 0.4411142 -> D = 2.76130 cm.
TEST(DisplacementRegressions, JibsonArias) {
  const Regression r = jibson2007_arias(0.1, 1.2);
  EXPECT_NEAR(r.median_cm, 2.76130, 5e-5);
  EXPECT_DOUBLE_EQ(r.sigma, 0.656);
}

// Jibson (2007), Arias and k_c/a_max model, Ia = 1.2 m/s, k_y / PGA = 0.1 / 0.4:
// log D = 0.561 (0.0791812) - 3.833 (-0.6020600) - 1.474
//       = 0.0444207 + 2.3076960 - 1.474 = 0.8781167 -> D = 7.55295 cm.
TEST(DisplacementRegressions, JibsonAriasRatio) {
  const Regression r = jibson2007_arias_ratio(0.1, 0.4, 1.2);
  EXPECT_NEAR(r.median_cm, 7.55295, 5e-5);
  EXPECT_DOUBLE_EQ(r.sigma, 0.616);
}

// Bray and Travasarou (2007), k_y = 0.1, Sa(1.5 Ts) = 0.6 g, Ts = 0.3 s, M 6.5:
// ln k_y = -2.3025851, ln Sa = -0.5108256;
// ln D = -1.10 + 6.5163158 - 0.333 (5.3018981) + 0.566 (1.1762195) + 3.04 (-0.5108256)
//        - 0.244 (0.2609428) + 1.50 (0.3) + 0.278 (-0.5)
//      = -1.10 + 6.5163158 - 1.7655321 + 0.6657402 - 1.5529099 - 0.0636700 + 0.45 - 0.139
//      = 3.0109440 -> D = 20.30656 cm.
TEST(DisplacementRegressions, BrayTravasarou) {
  const Regression r = bray_travasarou2007(0.1, 0.6, 0.3, 6.5);
  EXPECT_NEAR(r.median_cm, 20.30656, 2e-4);
  EXPECT_DOUBLE_EQ(r.sigma, 0.66);
  // Ts < 0.05 s: constant -0.22, no Ts term; k_y = 0.1, Sa = PGA = 0.4 g, M 7.5:
  // ln Sa = -0.9162907; ln D = -0.22 + 6.5163158 - 1.7655321 + 0.566 (2.1098374)
  //   + 3.04 (-0.9162907) - 0.244 (0.8395887) + 0.278 (0.5)
  //   = -0.22 + 6.5163158 - 1.7655321 + 1.1941680 - 2.7855238 - 0.2048596 + 0.139
  //   = 2.8735683 -> D = 17.70006 cm.
  EXPECT_NEAR(bray_travasarou2007(0.1, 0.4, 0.0, 7.5).median_cm, 17.70006, 2e-4);
}

// P(D = 0) for k_y = 0.2, Sa = 0.4 g, Ts = 0.3 s: ln k_y = -1.6094379,
// ln Sa = -0.9162907; x = -1.76 + 5.1823901 + 0.2336904 - 3.2253434 = 0.4307371
// 1 - Phi(0.4307371) = 0.33333 (tables of Phi).
TEST(DisplacementRegressions, BrayTravasarouZeroProbability) {
  EXPECT_NEAR(probability_zero_bt2007(0.2, 0.4, 0.3), 0.33333, 2e-5);
}

// Saygili and Rathje (2008), PGA-PGV model, k_y = 0.1, PGA = 0.4 g, PGV = 30 cm/s,
// r = 0.25: ln D = -1.56 - 1.145 - 1.3025 + 0.6992188 - 0.1191406
//   - 0.64 (-0.9162907) + 1.55 (3.4011974)
//   = -1.56 - 1.145 - 1.3025 + 0.6992188 - 0.1191406 + 0.5864260 + 5.2718560
//   = 2.4308602 -> D = 11.36866 cm; sigma = 0.405 + 0.524 (0.25) = 0.536.
TEST(DisplacementRegressions, SaygiliRathje) {
  const Regression r = saygili_rathje2008(0.1, 0.4, 30.0);
  EXPECT_NEAR(r.median_cm, 11.36866, 1e-4);
  EXPECT_NEAR(r.sigma, 0.536, 1e-12);
  EXPECT_EQ(saygili_rathje2008(0.4, 0.4, 30.0).median_cm, 0.0);
}

TEST(DisplacementRegressions, OutsideTheDomainIsNotANumber) {
  EXPECT_TRUE(std::isnan(jibson2007_ratio(0.0, 0.4).median_cm));
  EXPECT_TRUE(std::isnan(jibson2007_arias(0.1, 0.0).median_cm));
  EXPECT_TRUE(std::isnan(saygili_rathje2008(0.1, 0.4, 0.0).median_cm));
  EXPECT_TRUE(std::isnan(bray_travasarou2007(0.1, 0.4, 0.3, NAN).median_cm));
}
