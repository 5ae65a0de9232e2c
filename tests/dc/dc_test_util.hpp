#pragma once
// Helpers for the block-cutter tests: LineModels built by hand (not through
// DL) and the validity checks every cut must pass.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "dda/common/block_model.hpp"
#include "dda/common/line_model.hpp"
#include "dda/dc/cut.hpp"

namespace dda::dc::test {

inline Polygon2 box(double x0, double y0, double x1, double y1) {
  return {Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)};
}

// Regular n-gon approximating a circle, CCW.
inline Polygon2 circle(Vec2 c, double r, int n) {
  Polygon2 p;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * kPi * i / n;
    p.emplace_back(c.x() + r * std::cos(t), c.y() + r * std::sin(t));
  }
  return p;
}

inline JointLine line(double x0, double y0, double x1, double y1, int set = 0) {
  JointLine l;
  l.a = Vec2(x0, y0);
  l.b = Vec2(x1, y1);
  l.set = set;
  return l;
}

inline ModelPoint point(const std::string& name, PointKind kind, double x, double y) {
  ModelPoint p;
  p.name = name;
  p.kind = kind;
  p.p = Vec2(x, y);
  return p;
}

// Random lines: centres uniform in `b`, angle uniform, length uniform in
// [lmin, lmax], set = index % nsets.
inline std::vector<JointLine> random_lines(unsigned seed, int n, const Box2& b, double lmin, double lmax,
                                           int nsets = 2) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(b.lo.x(), b.hi.x()), uy(b.lo.y(), b.hi.y());
  std::uniform_real_distribution<double> ua(0, kPi), ul(lmin, lmax);
  std::vector<JointLine> out;
  for (int i = 0; i < n; ++i) {
    const Vec2 c(ux(rng), uy(rng));
    const double a = ua(rng), l = ul(rng);
    const Vec2 d(std::cos(a) * l / 2, std::sin(a) * l / 2);
    JointLine j;
    j.a = c - d;
    j.b = c + d;
    j.set = i % nsets;
    out.push_back(j);
  }
  return out;
}

// Segment–segment test on doubles (touching counts).
inline bool segments_touch(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  auto orient = [](const Vec2& p, const Vec2& q, const Vec2& r) { return cross(q - p, r - p); };
  auto on = [](const Vec2& p, const Vec2& q, const Vec2& r) {
    return std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) &&
           std::min(p.y(), q.y()) <= r.y() && r.y() <= std::max(p.y(), q.y());
  };
  const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return true;
  return (o1 == 0 && on(a, b, c)) || (o2 == 0 && on(a, b, d)) || (o3 == 0 && on(c, d, a)) ||
         (o4 == 0 && on(c, d, b));
}

// Every block: >= 3 vertices, one set per edge, CCW with positive area equal
// to the stored area, no repeated vertex, simple (brute force), moments
// consistent with polygon_moments.
inline void expect_valid_blocks(const BlockModel& m) {
  for (std::size_t bi = 0; bi < m.blocks.size(); ++bi) {
    const Block& b = m.blocks[bi];
    SCOPED_TRACE("block " + std::to_string(bi));
    const std::size_t n = b.vertices.size();
    ASSERT_GE(n, 3u);
    ASSERT_EQ(b.edge_set.size(), n);
    EXPECT_GT(signed_area(b.vertices), 0.0);
    // signed_area sums cross products about the origin: its rounding error
    // scales with the squared coordinates, not with the block's area.
    double big = 0;
    for (const Vec2& v : b.vertices) big = std::max(big, v.cwiseAbs().maxCoeff());
    EXPECT_NEAR(b.area, signed_area(b.vertices), 1e-9 * std::abs(b.area) + 1e-13 * big * big);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) ASSERT_NE(b.vertices[i], b.vertices[j]) << i << " " << j;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 2; j < n; ++j) {
        if (i == 0 && j == n - 1) continue;
        ASSERT_FALSE(segments_touch(b.vertices[i], b.vertices[(i + 1) % n], b.vertices[j],
                                    b.vertices[(j + 1) % n]))
            << "edges " << i << " and " << j << " meet";
      }
    const PolygonMoments pm = polygon_moments(b.vertices);
    EXPECT_NEAR(b.centroid.x(), pm.centroid.x(), 1e-9);
    EXPECT_NEAR(b.centroid.y(), pm.centroid.y(), 1e-9);
    for (int s : b.edge_set) EXPECT_TRUE(s >= 0 || s == kBoundarySet || s == kExcavationSet || s == kArtificialSet);
  }
}

inline double total_area(const BlockModel& m) {
  double a = 0;
  for (const Block& b : m.blocks) a += b.area;
  return a;
}

inline double dist_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

inline double dist_to_outline(const Vec2& p, const Polygon2& poly) {
  double d = 1e300;
  for (std::size_t i = 0; i < poly.size(); ++i) d = std::min(d, dist_to_segment(p, poly[i], poly[(i + 1) % poly.size()]));
  return d;
}

}  // namespace dda::dc::test
