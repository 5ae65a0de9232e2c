// Mechanical layering: beds, bounded joints, FSI.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "dda/dl/clip.hpp"
#include "dda/dl/layering.hpp"
#include "dl_test_util.hpp"

namespace dda::dl {

namespace {

// The seed report's example: mean 1 m, std 0.631 m (log10 mean 0, log10 std
// -0.2), minimum 0.7 m, FSI 1.3.
LayeringSpec example_spec() {
  LayeringSpec s;
  s.thickness.kind = ThicknessSpec::Kind::LogNormal;
  lognormal_from_moments(1.0, 0.631, s.thickness.mu, s.thickness.sigma);
  s.thickness.minimum = 0.7;
  s.sets.push_back({"V", 90, 1.3, 0.5});
  return s;
}

Polygon2 box(double x0, double y0, double x1, double y1) {
  return {Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)};
}

// Moments E[T^k | T >= a] of the truncated log-normal, by Simpson's rule in
// z = ln T over [ln a, mu + 12 sigma] (independent of the closed forms).
double truncated_moment(const ThicknessSpec& t, int k) {
  const double lo = std::log(t.minimum), hi = t.mu + 12 * t.sigma;
  const int n = 20000;
  const double h = (hi - lo) / n;
  double num = 0, den = 0;
  for (int i = 0; i <= n; ++i) {
    const double z = lo + i * h;
    const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    const double pdf = std::exp(-0.5 * std::pow((z - t.mu) / t.sigma, 2));
    num += w * pdf * std::exp(k * z);
    den += w * pdf;
  }
  return num / den;
}

}  // namespace

TEST(DlLayering, LognormalParametersFromMoments) {
  // sigma^2 = ln(1 + 0.631^2) = 0.33557..., mu = -sigma^2 / 2.
  double mu = 0, sigma = 0;
  lognormal_from_moments(1.0, 0.631, mu, sigma);
  EXPECT_NEAR(sigma * sigma, std::log(1 + 0.631 * 0.631), 1e-14);
  EXPECT_NEAR(mu, -0.5 * std::log(1 + 0.631 * 0.631), 1e-14);
  // Acceptance P(T >= 0.7) = 1 - Phi((ln 0.7 - mu)/sigma) = 1 - Phi(-0.32663) = 0.62803
  // (mu = -0.167579, sigma^2 = 0.335158, by hand with erfc).
  ThicknessSpec t{ThicknessSpec::Kind::LogNormal, mu, sigma, 0.7, 0};
  EXPECT_NEAR(thickness_acceptance(t), 0.62803, 1e-5);
}

TEST(DlLayering, ThicknessesFollowTheTruncatedLognormal) {
  // ~9000 beds in a 10 km column. Expected mean/std from numerical
  // integration; tolerance 5 standard errors: SE(mean) = std / sqrt(n),
  // SE(std) = sqrt((m4 - var^2) / n) / (2 std), m4 the 4th central moment.
  const LayeringSpec spec = example_spec();
  const auto beds = stack_beds(spec, box(0, 0, 1, 10000), 11);
  ASSERT_GT(beds.size(), 5000u);
  const std::size_t n = beds.size() - 1;  // the last bed is cut by the domain
  double sum = 0, sum2 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double h = beds[i].thickness();
    ASSERT_GE(h, 0.7);
    if (i > 0) {
      ASSERT_EQ(beds[i].bottom, beds[i - 1].top);
    }
    sum += h;
    sum2 += h * h;
  }
  EXPECT_EQ(beds.front().bottom, 0.0);
  EXPECT_EQ(beds.back().top, 10000.0);
  const double mean = sum / n, var = sum2 / n - mean * mean;
  const double m1 = truncated_moment(spec.thickness, 1), m2 = truncated_moment(spec.thickness, 2);
  const double m3 = truncated_moment(spec.thickness, 3), m4raw = truncated_moment(spec.thickness, 4);
  const double evar = m2 - m1 * m1;
  const double m4 = m4raw - 4 * m1 * m3 + 6 * m1 * m1 * m2 - 3 * std::pow(m1, 4);
  EXPECT_GT(m1, 1.0);  // truncation raises the mean above the untruncated 1 m
  EXPECT_NEAR(mean, m1, 5 * std::sqrt(evar / n));
  EXPECT_NEAR(std::sqrt(var), std::sqrt(evar), 5 * std::sqrt((m4 - evar * evar) / n) / (2 * std::sqrt(evar)));
}

TEST(DlLayering, JointsSpanTheirBedExactlyAndFsiIsMet) {
  const LayeringSpec spec = example_spec();
  const Polygon2 domain = box(0, 0, 100, 40);
  const auto out = generate_layering(spec, domain, 42);
  ASSERT_GT(out.layers.size(), 20u);
  ASSERT_GT(out.joints.size(), 1000u);
  for (const auto& j : out.joints) {
    const Layer& bed = out.layers[static_cast<std::size_t>(j.layer)];
    // Vertical joints in horizontal beds: one end on the bottom, one on the top.
    EXPECT_NEAR(std::min(j.seg.a.y(), j.seg.b.y()), bed.bottom, 1e-9);
    EXPECT_NEAR(std::max(j.seg.a.y(), j.seg.b.y()), bed.top, 1e-9);
    EXPECT_NEAR(j.seg.a.x(), j.seg.b.x(), 1e-12);
  }
  // Realised FSI per bed: the median of n spacings uniform on m(1 +- r) has a
  // relative standard error r / sqrt(n); FSI = h / median has the same. The
  // tolerance is 5 of those per bed, and the average ratio over the beds is
  // checked to 2 %.
  double ratio_sum = 0;
  std::size_t beds = 0;
  for (std::size_t i = 0; i < out.layers.size(); ++i) {
    const auto& st = out.per_set[0][i];
    if (st.spacings.size() < 10) continue;
    // The domain cuts the top bed; its spacing follows the drawn thickness
    // (checked in TopBedCutByTheDomainKeepsItsDrawnSpacing).
    if (i + 1 == out.layers.size()) continue;
    const Layer& bed = out.layers[i];
    EXPECT_EQ(bed.target_fsi, 1.3);
    const double rel_se = 0.5 / std::sqrt(static_cast<double>(st.spacings.size()));
    EXPECT_NEAR(bed.realised_fsi / 1.3, 1.0, 5 * rel_se) << "bed " << i;
    for (double s : st.spacings) {
      ASSERT_GE(s, 0.5 * bed.thickness() / 1.3 - 1e-12);
      ASSERT_LE(s, 1.5 * bed.thickness() / 1.3 + 1e-12);
    }
    ratio_sum += bed.realised_fsi / 1.3;
    ++beds;
  }
  ASSERT_GT(beds, 20u);
  EXPECT_NEAR(ratio_sum / beds, 1.0, 0.02);
  // Neighbouring joints 0.54 m apart in the thinnest possible bed (0.7/1.3).
  EXPECT_NEAR(0.7 / 1.3, 0.538, 1e-3);
}

TEST(DlLayering, TopBedCutByTheDomainKeepsItsDrawnSpacing) {
  // The bed the domain's top cuts continues beyond the model: its joints keep
  // the spacing of the whole bed (drawn thickness / FSI), not of the sliver
  // left inside the domain, which would crowd the top with tiny blocks.
  const LayeringSpec spec = example_spec();
  // Beds are stacked from the bottom with one stream, so a lower domain top
  // gives the same beds below it: cut bed 10 at 30 % of its thickness.
  const auto tall = stack_beds(spec, box(0, 0, 400, 100), 5);
  const double height = tall[10].bottom + 0.3 * tall[10].thickness();
  const Polygon2 domain = box(0, 0, 400, height);
  std::vector<double> drawn;
  const auto beds = stack_beds(spec, domain, 5, &drawn);
  ASSERT_EQ(beds.size(), 11u);
  const std::size_t top = beds.size() - 1;
  EXPECT_NEAR(drawn[top], tall[10].thickness(), 1e-12);
  const auto out = generate_layering(spec, domain, 5);
  const auto& st = out.per_set[0][top];
  ASSERT_GT(st.spacings.size(), 100u);
  // Median of n uniform spacings on m(1 +- r): relative standard error r/sqrt(n).
  const double rel_se = 0.5 / std::sqrt(static_cast<double>(st.spacings.size()));
  EXPECT_NEAR(st.median_spacing() / (drawn[top] / 1.3), 1.0, 5 * rel_se);
}

TEST(DlLayering, DippingBedsInAPolygonKeepJointsInsideTheirBed) {
  // Bedding dip 20 deg, joints at 60 deg, a pentagon domain: each joint's ends
  // lie on its bed's bottom or top (coordinate along the bedding normal), or
  // on the domain boundary where the domain cuts the joint.
  LayeringSpec spec = example_spec();
  spec.dip_deg = 20;
  spec.sets = {{"A", 60, 1.0, 0.3}, {"B", 135, 0.8, 0.2}};
  const Polygon2 domain{Vec2(0, 0), Vec2(60, -5), Vec2(70, 30), Vec2(30, 45), Vec2(-5, 25)};
  const auto out = generate_layering(spec, domain, 8);
  ASSERT_GT(out.joints.size(), 300u);
  const Vec2 m(-std::sin(deg2rad(20)), std::cos(deg2rad(20)));
  EXPECT_NEAR((out.normal - m).norm(), 0, 1e-15);
  std::size_t on_both_beds = 0;
  for (const auto& j : out.joints) {
    const Layer& bed = out.layers[static_cast<std::size_t>(j.layer)];
    bool on_bed[2];
    int k = 0;
    for (const Vec2& p : {j.seg.a, j.seg.b}) {
      const double w = p.dot(m);
      ASSERT_GE(w, bed.bottom - 1e-9);
      ASSERT_LE(w, bed.top + 1e-9);
      const bool on = std::abs(w - bed.bottom) < 1e-9 || std::abs(w - bed.top) < 1e-9;
      ASSERT_TRUE(on || distance_to_boundary(domain, p) < 1e-9) << p.transpose();
      on_bed[k++] = on;
    }
    on_both_beds += on_bed[0] && on_bed[1];
  }
  EXPECT_GT(on_both_beds, out.joints.size() * 8 / 10);
  // Bed boundaries run along the bedding direction.
  for (const auto& s : out.bed_boundaries) EXPECT_NEAR(std::abs(cross((s.b - s.a).normalized(), out.along)), 0, 1e-12);
}

TEST(DlLayering, ScenarioMakesBeddingAndLayeredSets) {
  const auto r = test::run(R"(seed: 3
domain: {box: [0, 0, 30, 12]}
layering:
  thickness: {distribution: lognormal, mean: 1.0, std: 0.631, minimum: 0.7}
  sets:
    - {name: V, dip: 90, fsi: 1.3, randomness: 0.5}
)");
  const auto& m = r.model;
  ASSERT_EQ(m.sets.size(), 2u);
  EXPECT_EQ(m.sets[0].name, "bedding");
  EXPECT_EQ(m.sets[0].origin, "bedding");
  EXPECT_EQ(m.sets[1].name, "V");
  EXPECT_EQ(m.sets[1].origin, "layered");
  std::size_t bedding = 0;
  for (const auto& l : m.lines) {
    if (l.kind == LineKind::Bedding) {
      ++bedding;
      EXPECT_EQ(l.set, 0);
      EXPECT_NEAR(l.a.y(), l.b.y(), 1e-12);
      EXPECT_NEAR((l.b - l.a).norm(), 30, 1e-9);  // spans the box
    } else {
      EXPECT_EQ(l.set, 1);
      EXPECT_GE(l.layer, 0);
    }
  }
  EXPECT_EQ(bedding, m.layers.size() - 1);
  EXPECT_EQ(r.report["layering"]["beds"].get<std::size_t>(), m.layers.size());
  EXPECT_EQ(r.report["layering"]["layers"].size(), m.layers.size());
}

TEST(DlLayering, ConstantThickness) {
  LayeringSpec spec;
  spec.thickness = {ThicknessSpec::Kind::Constant, 0, 0, 0, 2.5};
  const auto beds = stack_beds(spec, box(0, 0, 5, 11), 1);
  ASSERT_EQ(beds.size(), 5u);  // 4 full beds of 2.5 m and a cut one of 1 m
  EXPECT_DOUBLE_EQ(beds[3].top, 10.0);
  EXPECT_DOUBLE_EQ(beds[4].thickness(), 1.0);
}

}  // namespace dda::dl
