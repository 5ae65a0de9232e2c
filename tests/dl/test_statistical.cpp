// Statistical (Shi-Goodman) joint sets.
#include <gtest/gtest.h>

#include <cmath>

#include "dda/dl/statistical.hpp"
#include "dl_test_util.hpp"

namespace dda::dl {

namespace {

const char* kTwoSets = R"(seed: 42
domain: {box: [0, 0, 40, 30]}
joint_sets:
  - {name: J1, dip: 60, mean_length: 5, mean_bridge: 1, mean_spacing: 0.9, randomness: 0.5, dip_spread: 5}
  - {name: J2, dip: 150, mean_length: 3, mean_bridge: 2, mean_spacing: 1.5, randomness: 0.3}
)";

bool same_lines(const LineModel& a, const LineModel& b) {
  if (a.lines.size() != b.lines.size()) return false;
  for (std::size_t i = 0; i < a.lines.size(); ++i)
    if (a.lines[i].a != b.lines[i].a || a.lines[i].b != b.lines[i].b || a.lines[i].set != b.lines[i].set) return false;
  return true;
}

Polygon2 box(double x0, double y0, double x1, double y1) {
  return {Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)};
}

}  // namespace

TEST(DlStatistical, SameSeedGivesIdenticalLines) {
  const auto a = test::run(kTwoSets), b = test::run(kTwoSets);
  ASSERT_GT(a.model.lines.size(), 100u);
  EXPECT_TRUE(same_lines(a.model, b.model));
  EXPECT_EQ(a.model.provenance.seed, 42u);
  EXPECT_EQ(a.model.provenance.scenario_path, "test.yaml");
  EXPECT_EQ(a.model.provenance.scenario_text, kTwoSets);
  EXPECT_FALSE(a.model.provenance.program_version.empty());
}

TEST(DlStatistical, DifferentSeedGivesDifferentLines) {
  std::string other = kTwoSets;
  other.replace(other.find("seed: 42"), 8, "seed: 43");
  EXPECT_FALSE(same_lines(test::run(kTwoSets).model, test::run(other).model));
}

TEST(DlStatistical, EachSetHasItsOwnStream) {
  // Removing J2 must not change J1's lines: J1 draws from its own stream.
  std::string one = kTwoSets;
  one.erase(one.find("  - {name: J2"));
  const auto both = test::run(kTwoSets), only = test::run(one);
  std::vector<JointLine> j1;
  for (const auto& l : both.model.lines)
    if (l.set == 0) j1.push_back(l);
  ASSERT_EQ(j1.size(), only.model.lines.size());
  for (std::size_t i = 0; i < j1.size(); ++i) {
    EXPECT_EQ(j1[i].a, only.model.lines[i].a);
    EXPECT_EQ(j1[i].b, only.model.lines[i].b);
  }
}

TEST(DlStatistical, RealisedMeansConvergeToAsked) {
  // Values are mean * (1 + r X) with X uniform on [-1, 1): standard deviation
  // mean * r / sqrt(3), so the standard error of a realised mean over n draws
  // is mean * r / sqrt(3 n). The tolerance is 5 standard errors (a correct
  // generator fails it with probability < 1e-6; a biased one, e.g. a spacing
  // of mean (1 + r/2) * asked, fails it by far).
  StatisticalSetSpec spec{"J", 35, 5.0, 1.0, 0.54, 0.5, 0.4, 0.6, 0};
  Stream rng(2024, "test");
  const auto out = generate_statistical_set(spec, box(0, 0, 200, 600), rng);
  const auto& st = out.stats;
  ASSERT_GT(st.traces, 30000u);
  ASSERT_GT(st.spacings, 1000u);
  auto tol = [](double mean, double r, std::size_t n) { return 5 * mean * r / std::sqrt(3.0 * n); };
  EXPECT_NEAR(st.mean_length(), 5.0, tol(5.0, 0.5, st.traces));
  EXPECT_NEAR(st.mean_bridge(), 1.0, tol(1.0, 0.4, st.bridges));
  EXPECT_NEAR(st.mean_spacing(), 0.54, tol(0.54, 0.6, st.spacings));
  EXPECT_DOUBLE_EQ(st.mean_dip_deg(), 35.0);  // no dip spread
  // Every drawn value lies within mean (1 +- r): check on the traces themselves.
  for (const auto& s : out.traces) {
    ASSERT_GE(s.length(), 5.0 * 0.5 - 1e-9);
    ASSERT_LE(s.length(), 5.0 * 1.5 + 1e-9);
  }
}

TEST(DlStatistical, NoEdgeBiasAndRightIntensity) {
  // Deterministic lengths (r = 0), dip 0: without the random phase every scan
  // line would start with a joint at x = 0 and the strip 0 < x < 1 would be
  // fully jointed (P21 = 1/S instead of (L/(L+B))/S). The expected P21 of a
  // stationary pattern is (L / (L + B)) / S = (5/6)/0.5 = 1.667 1/m in any
  // strip. Per scan line the covered fraction of a 1 m strip has a standard
  // deviation of at most 0.5; with ~2000 scan lines the standard error of the
  // strip P21 is < 1.2 %, so 5 % is > 4 standard errors.
  const double L = 5, B = 1, S = 0.5;
  StatisticalSetSpec spec{"J", 0, L, B, S, 0, 0, 0, 0};
  Stream rng(99, "edge");
  const Polygon2 domain = box(0, 0, 100, 1000);
  const auto out = generate_statistical_set(spec, domain, rng);
  const double expected = L / (L + B) / S;
  auto strip_p21 = [&](double x0, double x1) {
    const Polygon2 strip = box(x0, 0, x1, 1000);
    double len = 0;
    for (const auto& s : out.traces)
      for (const auto& piece : clip_segment(strip, s)) len += piece.length();
    return len / ((x1 - x0) * 1000);
  };
  EXPECT_NEAR(strip_p21(0, 1), expected, 0.05 * expected);
  EXPECT_NEAR(strip_p21(99, 100), expected, 0.05 * expected);
  EXPECT_NEAR(strip_p21(0, 100), expected, 0.02 * expected);
}

TEST(DlStatistical, ClippedToANonConvexDomain) {
  // An L-shaped domain: every line must lie inside it (its midpoint inside,
  // its ends inside or on the boundary), and the notch 10..20 x 10..20 empty.
  const auto r = test::run(R"(seed: 5
domain: {polygon: [[0, 0], [20, 0], [20, 10], [10, 10], [10, 20], [0, 20]]}
joint_sets:
  - {dip: 30, mean_length: 4, mean_bridge: 1, mean_spacing: 0.7, randomness: 0.5}
)");
  const auto& d = r.model.domain;
  ASSERT_GT(r.model.lines.size(), 100u);
  EXPECT_GT(signed_area(d), 0);  // made counter-clockwise
  for (const auto& l : r.model.lines) {
    ASSERT_TRUE(point_in_polygon(d, 0.5 * (l.a + l.b)));
    for (const Vec2& p : {l.a, l.b}) {
      ASSERT_TRUE(point_in_polygon(d, p) || distance_to_boundary(d, p) < 1e-9) << p.transpose();
      ASSERT_FALSE(p.x() > 10 + 1e-9 && p.y() > 10 + 1e-9) << p.transpose();
    }
  }
  // The report's in-domain length is the sum of the line lengths.
  double len = 0;
  for (const auto& l : r.model.lines) len += (l.b - l.a).norm();
  EXPECT_NEAR(r.report["statistical_sets"][0]["in_domain"]["total_length"].get<double>(), len, 1e-9 * len);
  EXPECT_NEAR(r.report["statistical_sets"][0]["in_domain"]["p21"].get<double>(), len / 300.0, 1e-12 * len);
}

TEST(DlStatistical, DipSpreadStaysWithinItsBound) {
  StatisticalSetSpec spec{"J", 170, 2, 1, 1, 0.2, 0.2, 0.2, 15};
  Stream rng(3, "spread");
  const auto out = generate_statistical_set(spec, box(0, 0, 50, 50), rng);
  double lo = 1e9, hi = -1e9;
  for (const auto& s : out.traces) {
    double a = rad2deg(std::atan2(s.b.y() - s.a.y(), s.b.x() - s.a.x()));
    if (a < 0) a += 360;
    lo = std::min(lo, a);
    hi = std::max(hi, a);
  }
  EXPECT_GE(lo, 155 - 1e-9);
  EXPECT_LE(hi, 185 + 1e-9);
  EXPECT_LT(lo, 157);  // the spread is used (thousands of traces)
  EXPECT_GT(hi, 183);
  // Realised mean dip: X uniform, SE = 15 / sqrt(3 n); 5 SE.
  EXPECT_NEAR(out.stats.mean_dip_deg(), 170, 5 * 15 / std::sqrt(3.0 * out.stats.traces));
}

}  // namespace dda::dl
