// The draws of `sample:` against their laws: sample means and spreads
// within a few standard errors of the analytical values. Every test draws
// from a fixed stream, so it cannot flicker; the tolerances are 4 standard
// errors of the statistic, which a wrong law (a wrong parameter by more than
// a few per cent) fails.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dda/study/distribution.hpp"

namespace dda::study {
namespace {

constexpr int kDraws = 40000;

struct Moments {
  double mean = 0, std = 0, lo = 1e300, hi = -1e300;
};

Moments moments_of(const Distribution& d, std::uint64_t seed) {
  dl::Stream s(seed, "test");
  double sum = 0, sum2 = 0;
  Moments m;
  for (int i = 0; i < kDraws; ++i) {
    const double v = d.draw(s);
    sum += v;
    sum2 += v * v;
    m.lo = std::min(m.lo, v);
    m.hi = std::max(m.hi, v);
  }
  m.mean = sum / kDraws;
  m.std = std::sqrt(sum2 / kDraws - m.mean * m.mean);
  return m;
}

TEST(Distribution, NormalHasItsMeanAndStd) {
  Distribution d;
  d.mean = 30;
  d.std = 3;
  const Moments m = moments_of(d, 1);
  // Standard error of the mean: std / sqrt(n) = 0.015; of the std: std / sqrt(2n) = 0.0106.
  EXPECT_NEAR(m.mean, 30, 4 * 3 / std::sqrt(kDraws));
  EXPECT_NEAR(m.std, 3, 4 * 3 / std::sqrt(2.0 * kDraws));
}

TEST(Distribution, LognormalHasTheMeanAndStdOfTheValue) {
  Distribution d;
  d.law = Distribution::Law::lognormal;
  d.mean = 2;
  d.std = 0.5;
  const Moments m = moments_of(d, 2);
  EXPECT_GT(m.lo, 0);
  EXPECT_NEAR(m.mean, 2, 4 * 0.5 / std::sqrt(kDraws));
  // The std's standard error for a log-normal of cv 0.25 is about 1.2 x the
  // normal one (its kurtosis 3.9): 5 normal standard errors cover it.
  EXPECT_NEAR(m.std, 0.5, 5 * 0.5 / std::sqrt(2.0 * kDraws));
}

TEST(Distribution, UniformStaysWithinItsEnds) {
  Distribution d;
  d.law = Distribution::Law::uniform;
  d.from = 40;
  d.to = 60;
  const Moments m = moments_of(d, 3);
  EXPECT_GE(m.lo, 40);
  EXPECT_LT(m.hi, 60);
  // Mean 50, std 20 / sqrt(12).
  EXPECT_NEAR(m.mean, 50, 4 * (20 / std::sqrt(12.0)) / std::sqrt(kDraws));
  EXPECT_NEAR(m.std, 20 / std::sqrt(12.0), 0.05);
}

TEST(Distribution, TruncatedNormalHasTheTruncatedMean) {
  Distribution d;
  d.mean = 30;
  d.std = 5;
  d.lo = 28;
  d.hi = 45;
  const Moments m = moments_of(d, 4);
  EXPECT_GE(m.lo, 28);
  EXPECT_LE(m.hi, 45);
  // Mean of a normal truncated to [a, b]: mu + sigma (phi(A) - phi(B)) / (Phi(B) - Phi(A)),
  // A = (a - mu)/sigma = -0.4, B = 3.
  const auto pdf = [](double z) { return std::exp(-0.5 * z * z) / std::sqrt(2 * std::numbers::pi); };
  const auto cdf = [](double z) { return 0.5 * std::erfc(-z / std::numbers::sqrt2); };
  const double expected = 30 + 5 * (pdf(-0.4) - pdf(3)) / (cdf(3) - cdf(-0.4));
  EXPECT_NEAR(d.kept(), cdf(3) - cdf(-0.4), 1e-12);
  EXPECT_NEAR(m.mean, expected, 4 * 5 / std::sqrt(kDraws));
}

TEST(Distribution, FisherScatterHasTheMeanCosineOfItsKappa) {
  // For a Fisher law of concentration kappa, E[cos theta] = coth(kappa) - 1/kappa
  // (Fisher 1953); var(cos theta) = 1/kappa^2 - 1/sinh(kappa)^2.
  for (const double kappa : {20.0, 50.0}) {
    analysis::Plane mean;
    mean.dip_deg = 30;  // far enough from 90 that no drawn pole turns over
    mean.dip_direction_deg = 120;
    const analysis::Vec3 pole = mean.normal();
    dl::Stream s(5, "fisher");
    double sum = 0;
    analysis::Vec3 resultant = analysis::Vec3::Zero();
    for (int i = 0; i < kDraws; ++i) {
      const analysis::Plane p = fisher_draw(mean, kappa, s);
      ASSERT_GE(p.dip_deg, 0);
      ASSERT_LE(p.dip_deg, 90);
      sum += p.normal().dot(pole);
      resultant += p.normal();
    }
    const double expected = 1 / std::tanh(kappa) - 1 / kappa;
    const double sd = std::sqrt(1 / (kappa * kappa) - 1 / std::pow(std::sinh(kappa), 2));
    EXPECT_NEAR(sum / kDraws, expected, 4 * sd / std::sqrt(kDraws)) << "kappa " << kappa;
    // The poles scatter about the mean pole with no preferred side: their
    // resultant points along it (within 0.5 degree).
    EXPECT_GT(resultant.normalized().dot(pole), std::cos(0.5 * std::numbers::pi / 180)) << "kappa " << kappa;
  }
}

}  // namespace
}  // namespace dda::study
