#include "dda/dc/stats.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dda/common/geometry.hpp"

using dda::Vec2;
using nlohmann::json;

namespace {

// An axis-parallel w x h rectangle with its lower left corner at (x, y).
dda::Block rect(double x, double y, double w, double h, int layer = -1) {
  dda::Block b;
  b.vertices = {Vec2(x, y), Vec2(x + w, y), Vec2(x + w, y + h), Vec2(x, y + h)};
  b.edge_set = {0, 0, 0, 0};
  const dda::PolygonMoments m = dda::polygon_moments(b.vertices);
  b.area = m.area;
  b.centroid = m.centroid;
  b.layer = layer;
  return b;
}

dda::Block polygon(const dda::Polygon2& p) {
  dda::Block b;
  b.vertices = p;
  b.edge_set.assign(p.size(), 0);
  b.area = dda::polygon_moments(p).area;
  return b;
}

// Five rectangles 1x1, 2x1, 3x1, 4x2, 10x1 (width x height), not layered.
dda::BlockModel five_rectangles() {
  dda::BlockModel m;
  m.blocks = {rect(0, 0, 1, 1), rect(1, 0, 2, 1), rect(3, 0, 3, 1), rect(6, 0, 4, 2),
              rect(0, 2, 10, 1)};
  m.domain_area = 30;
  m.excavated_area = 2;
  return m;
}

long long sum_counts(const json& dist) {
  long long s = 0;
  for (const auto& c : dist["histogram"]["counts"]) s += c.get<long long>();
  return s;
}

TEST(BlockStatistics, AreaMeanMedianPercentilesByHand) {
  // Areas 1, 2, 3, 8, 10, computed by hand:
  //  mean = 24/5 = 4.8; median = 3;
  //  population std = sqrt((3.8^2 + 2.8^2 + 1.8^2 + 3.2^2 + 5.2^2)/5) = sqrt(62.8/5);
  //  percentile p: h = (5-1) p/100, v[floor h] + frac(h) (v[floor h+1] - v[floor h]):
  //  p5: h=0.2 -> 1.2; p10: h=0.4 -> 1.4; p25: h=1 -> 2; p50: h=2 -> 3;
  //  p75: h=3 -> 8; p90: h=3.6 -> 8 + 0.6*2 = 9.2; p95: h=3.8 -> 9.6.
  const json s = dda::dc::block_statistics(five_rectangles(), 3);
  EXPECT_EQ(s["blocks"], 5);
  EXPECT_DOUBLE_EQ(s["total_area"].get<double>(), 24.0);
  EXPECT_DOUBLE_EQ(s["domain_area"].get<double>(), 30.0);
  EXPECT_DOUBLE_EQ(s["excavated_area"].get<double>(), 2.0);
  const json& a = s["area"];
  EXPECT_DOUBLE_EQ(a["min"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(a["max"].get<double>(), 10.0);
  EXPECT_DOUBLE_EQ(a["mean"].get<double>(), 4.8);
  EXPECT_DOUBLE_EQ(a["std"].get<double>(), std::sqrt(62.8 / 5));
  EXPECT_DOUBLE_EQ(a["median"].get<double>(), 3.0);
  const json& p = a["percentiles"];
  EXPECT_DOUBLE_EQ(p["p5"].get<double>(), 1.2);
  EXPECT_DOUBLE_EQ(p["p10"].get<double>(), 1.4);
  EXPECT_DOUBLE_EQ(p["p25"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(p["p50"].get<double>(), 3.0);
  EXPECT_DOUBLE_EQ(p["p75"].get<double>(), 8.0);
  EXPECT_DOUBLE_EQ(p["p90"].get<double>(), 9.2);
  EXPECT_DOUBLE_EQ(p["p95"].get<double>(), 9.6);
  // 3 bins over [1, 10]: edges 1, 4, 7, 10 -> {1, 2, 3}, {}, {8, 10}.
  const json& h = a["histogram"];
  ASSERT_EQ(h["edges"].size(), 4u);
  EXPECT_DOUBLE_EQ(h["edges"][1].get<double>(), 4.0);
  EXPECT_DOUBLE_EQ(h["edges"][3].get<double>(), 10.0);
  EXPECT_EQ(h["counts"], json({3, 0, 2}));
  for (const char* k : {"area", "width", "min_feret", "aspect"}) EXPECT_EQ(sum_counts(s[k]), 5) << k;
  EXPECT_TRUE(s["definitions"].contains("width"));
  EXPECT_TRUE(s["per_layer"].empty());
}

TEST(BlockStatistics, WidthMinFeretAndAspectOfRectangles) {
  // Horizontal beds: width = horizontal extent 1, 2, 3, 4, 10 (mean 4,
  // median 3); min Feret = the short side 1, 1, 1, 2, 1; aspect = long/short
  // side 1, 2, 3, 2, 10 (mean 18/5).
  const json s = dda::dc::block_statistics(five_rectangles(), 4);
  EXPECT_DOUBLE_EQ(s["width"]["mean"].get<double>(), 4.0);
  EXPECT_DOUBLE_EQ(s["width"]["median"].get<double>(), 3.0);
  EXPECT_DOUBLE_EQ(s["width"]["max"].get<double>(), 10.0);
  EXPECT_DOUBLE_EQ(s["min_feret"]["mean"].get<double>(), 6.0 / 5.0);
  EXPECT_DOUBLE_EQ(s["min_feret"]["max"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(s["aspect"]["mean"].get<double>(), 18.0 / 5.0);
  EXPECT_DOUBLE_EQ(s["aspect"]["median"].get<double>(), 2.0);
  EXPECT_EQ(s["width"]["histogram"]["counts"].size(), 4u);
}

TEST(BlockStatistics, WidthFollowsTheBeddingDip) {
  dda::BlockModel m;
  m.blocks = {rect(0, 0, 2, 1)};  // 2 wide, 1 tall
  m.bedding_dip_deg = 90;         // beds vertical: width is the vertical extent
  json s = dda::dc::block_statistics(m);
  EXPECT_NEAR(s["width"]["mean"].get<double>(), 1.0, 1e-12);
  m.bedding_dip_deg = 0;
  s = dda::dc::block_statistics(m);
  EXPECT_NEAR(s["width"]["mean"].get<double>(), 2.0, 1e-12);
  m.blocks = {rect(0, 0, 1, 1)};
  m.bedding_dip_deg = 45;  // a unit square measured along its diagonal
  s = dda::dc::block_statistics(m);
  EXPECT_NEAR(s["width"]["mean"].get<double>(), std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(s["min_feret"]["mean"].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(s["aspect"]["mean"].get<double>(), 1.0, 1e-12);
}

TEST(BlockStatistics, RotatedRectangleAspect) {
  // A 3 x 1 rectangle turned by 30 degrees: min Feret 1, aspect 3.
  const double c = std::cos(dda::deg2rad(30)), s = std::sin(dda::deg2rad(30));
  const Vec2 u(c, s), v(-s, c), o(5, 7);
  dda::BlockModel m;
  m.blocks = {polygon({o, o + 3 * u, o + 3 * u + v, o + v})};
  const json j = dda::dc::block_statistics(m);
  EXPECT_NEAR(j["min_feret"]["mean"].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(j["aspect"]["mean"].get<double>(), 3.0, 1e-12);
  // Horizontal extent of the turned rectangle: 3 cos 30 + sin 30.
  EXPECT_NEAR(j["width"]["mean"].get<double>(), 3 * c + s, 1e-12);
}

TEST(BlockStatistics, MinFeretAgreesWithGeometry) {
  // Random star-shaped (often non-convex) polygons: the hull-based minimum
  // width equals dda::min_feret_width.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> r(0.3, 2.0), jitter(-0.2, 0.2);
  dda::BlockModel m;
  std::vector<double> expected;
  for (int k = 0; k < 50; ++k) {
    const int n = 3 + k % 9;
    dda::Polygon2 p;
    for (int i = 0; i < n; ++i) {
      const double t = 2 * dda::kPi * (i + 0.5 + jitter(rng)) / n;
      const double radius = r(rng);
      p.emplace_back(10 + radius * std::cos(t), -4 + radius * std::sin(t));
    }
    m.blocks.push_back(polygon(p));
    expected.push_back(dda::min_feret_width(p));
  }
  const json s = dda::dc::block_statistics(m, 7);
  std::sort(expected.begin(), expected.end());
  EXPECT_NEAR(s["min_feret"]["min"].get<double>(), expected.front(), 1e-12);
  EXPECT_NEAR(s["min_feret"]["max"].get<double>(), expected.back(), 1e-12);
  double mean = 0;
  for (double e : expected) mean += e / expected.size();
  EXPECT_NEAR(s["min_feret"]["mean"].get<double>(), mean, 1e-12);
  for (const char* key : {"area", "width", "min_feret", "aspect"}) {
    EXPECT_EQ(sum_counts(s[key]), 50) << key;
    EXPECT_EQ(s[key]["histogram"]["edges"].size(), 8u) << key;
    EXPECT_GE(s[key]["min"].get<double>(), 0.0) << key;
  }
  EXPECT_GE(s["aspect"]["min"].get<double>(), 1.0 - 1e-12);
}

TEST(BlockStatistics, PerLayerCounts) {
  dda::BlockModel m;
  m.layers = {{0, 1, 2, 2.5}, {1, 3, 0, 0}, {3, 4, 0, 0}};
  m.blocks = {rect(0, 0, 2, 1, 0), rect(2, 0, 4, 1, 0), rect(0, 1, 1, 2, 1), rect(0, 5, 1, 1, -1)};
  const json s = dda::dc::block_statistics(m);
  ASSERT_EQ(s["per_layer"].size(), 3u);
  const json& l0 = s["per_layer"][0];
  EXPECT_EQ(l0["layer"], 0);
  EXPECT_EQ(l0["blocks"], 2);
  EXPECT_DOUBLE_EQ(l0["thickness"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(l0["mean_width"].get<double>(), 3.0);  // (2 + 4)/2
  EXPECT_DOUBLE_EQ(l0["mean_area"].get<double>(), 3.0);   // (2 + 4)/2
  const json& l1 = s["per_layer"][1];
  EXPECT_EQ(l1["blocks"], 1);
  EXPECT_DOUBLE_EQ(l1["bottom"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(l1["top"].get<double>(), 3.0);
  EXPECT_DOUBLE_EQ(l1["thickness"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(l1["mean_area"].get<double>(), 2.0);
  const json& l2 = s["per_layer"][2];
  EXPECT_EQ(l2["blocks"], 0);
  EXPECT_TRUE(l2["mean_width"].is_null());
  EXPECT_TRUE(l2["mean_area"].is_null());
  EXPECT_EQ(s["blocks"], 4);  // the unlayered block still counts overall
}

TEST(BlockStatistics, NoBlocksGivesNullDistributions) {
  dda::BlockModel m;
  m.domain_area = 5;
  m.layers = {{0, 1, 0, 0}};
  const json s = dda::dc::block_statistics(m, 10);
  EXPECT_EQ(s["blocks"], 0);
  EXPECT_DOUBLE_EQ(s["total_area"].get<double>(), 0.0);
  for (const char* k : {"area", "width", "min_feret", "aspect"}) EXPECT_TRUE(s[k].is_null()) << k;
  EXPECT_EQ(s["per_layer"][0]["blocks"], 0);
  EXPECT_NO_THROW((void)s.dump());
}

TEST(BlockStatistics, EqualValuesAndOneBlock) {
  dda::BlockModel m;
  m.blocks = {rect(0, 0, 1, 1), rect(1, 0, 1, 1)};
  json s = dda::dc::block_statistics(m, 2);
  EXPECT_EQ(s["area"]["histogram"]["counts"], json({0, 2}));  // range 1 +- 0.5, last bin closed
  EXPECT_DOUBLE_EQ(s["area"]["std"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(s["area"]["percentiles"]["p95"].get<double>(), 1.0);
  m.blocks.resize(1);
  s = dda::dc::block_statistics(m, 0);  // bins < 1 -> 1
  EXPECT_EQ(s["area"]["histogram"]["counts"], json({1}));
  EXPECT_DOUBLE_EQ(s["area"]["median"].get<double>(), 1.0);
}

}  // namespace
