// 3D fractures as Fracture3: discs and regular-polygon sets, P32 of polygon
// sets, deterministic planes, persistent sets, polygons from vertices.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"
#include "dda/dl/dfn3d.hpp"
#include "dda/dl/fractures3d.hpp"

namespace dda::dl {

namespace {

using V3 = Eigen::Vector3d;

Box3 box(V3 lo, V3 hi) { return {lo, hi}; }
Box3 cube(double lo, double hi) { return {V3::Constant(lo), V3::Constant(hi)}; }

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool same(const std::vector<Fracture3>& a, const std::vector<Fracture3>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].shape != b[i].shape || a[i].centre != b[i].centre || a[i].normal != b[i].normal ||
        a[i].radius != b[i].radius || a[i].vertices != b[i].vertices || a[i].set != b[i].set)
      return false;
  return true;
}

PersistentSetSpec persistent(const std::string& name, double dip, double dir, double spacing,
                             std::optional<V3> point = std::nullopt, double randomness = 0) {
  PersistentSetSpec s;
  s.name = name;
  s.dip_deg = dip;
  s.dip_direction_deg = dir;
  s.spacing = spacing;
  s.point = point;
  s.randomness = randomness;
  return s;
}

DiscSetSpec polygon_set(int sides, double p32) {
  DiscSetSpec s;
  s.name = "P";
  s.dip_deg = 50;
  s.dip_direction_deg = 210;
  s.kappa = 10;
  s.size = SizeLaw::lognormal(1, 0.3);
  s.p32 = p32;
  s.polygon_sides = sides;
  return s;
}

}  // namespace

// ---- discs and regular polygons ----------------------------------------

TEST(Fractures3dSets, DiscBecomesADiscFracture) {
  const Disc d{V3(1, 2, 3), normal_from_dip(30, 60), 1.5, 4};
  const Fracture3 f = to_fracture(d);
  EXPECT_EQ(f.shape, FractureShape::Disc);
  EXPECT_EQ(f.centre, d.centre);
  EXPECT_EQ(f.normal, d.normal);
  EXPECT_EQ(f.radius, 1.5);
  EXPECT_EQ(f.set, 4);
  EXPECT_EQ(f.kind, LineKind::Joint);
  EXPECT_EQ(f.layer, -1);
}

TEST(Fractures3dSets, RegularPolygonHasTheDiscsAreaAndCentre) {
  // Area of the n-gon = pi r^2 by construction (the P32 target counts it so);
  // all vertices at the circumradius r sqrt(2 pi / (n sin(2 pi / n))), in the
  // plane, counter-clockwise about the normal, the first one at the asked turn.
  const Disc d{V3(1, -2, 3), normal_from_dip(35, 120), 0.8, 2};
  for (const int n : {3, 4, 6, 17}) {
    const double turn = 0.7;
    const Fracture3 f = regular_polygon(d, n, turn);
    ASSERT_EQ(f.vertices.size(), static_cast<std::size_t>(n));
    EXPECT_EQ(f.shape, FractureShape::Polygon);
    EXPECT_NEAR(polygon_area(f.vertices), kPi * 0.64, 1e-12) << n;
    EXPECT_NEAR((polygon_centroid(f.vertices) - d.centre).norm(), 0, 1e-12);
    EXPECT_GT(vector_area(f.vertices).dot(f.normal), 0);  // counter-clockwise about the normal
    const double circumradius = 0.8 * std::sqrt(2 * kPi / (n * std::sin(2 * kPi / n)));
    for (const V3& p : f.vertices) {
      EXPECT_NEAR((p - d.centre).norm(), circumradius, 1e-12);
      EXPECT_NEAR(d.normal.dot(p - d.centre), 0, 1e-12);
    }
    const auto [e1, e2] = plane_basis(d.normal);
    const V3 first = f.vertices[0] - d.centre;
    EXPECT_NEAR(std::atan2(first.dot(e2), first.dot(e1)), turn, 1e-12);
  }
}

TEST(Fractures3dSets, DiscSetsGiveTheDiscsOfGenerateDfn) {
  DiscSetSpec a = polygon_set(0, 0.5);
  DiscSetSpec b = polygon_set(0, 0);
  b.count = 40;
  const Box3 domain = cube(0, 5);
  const auto discs = generate_dfn({a, b}, domain, 1, 9);
  const auto fr = generate_fractures({a, b}, domain, 1, 9, 3);
  ASSERT_EQ(discs.size(), fr.size());
  for (std::size_t i = 0; i < fr.size(); ++i) {
    EXPECT_EQ(fr[i].shape, FractureShape::Disc);
    EXPECT_EQ(fr[i].centre, discs[i].centre);
    EXPECT_EQ(fr[i].radius, discs[i].radius);
    EXPECT_EQ(fr[i].set, discs[i].set + 3);  // first_set shifts the indices
  }
}

TEST(Fractures3dSets, PolygonSetsAreDeterministicAndTurnedAtRandom) {
  const Box3 domain = cube(0, 5);
  DiscSetSpec p = polygon_set(5, 0.6);
  DiscSetSpec q = polygon_set(0, 0);
  q.count = 30;
  const auto both = generate_fractures({p, q}, domain, 1, 42);
  EXPECT_TRUE(same(both, generate_fractures({p, q}, domain, 1, 42)));
  EXPECT_FALSE(same(both, generate_fractures({p, q}, domain, 1, 43)));
  std::vector<Fracture3> first;
  for (const Fracture3& f : both)
    if (f.set == 0) first.push_back(f);
  EXPECT_TRUE(same(first, generate_fractures({p}, domain, 1, 42)));  // set 0 has its own stream
  // The turns: the angle of the first vertex in the plane's basis spreads
  // over the whole circle (not always the same corner first).
  double lo = 10, hi = -10;
  for (const Fracture3& f : first) {
    ASSERT_EQ(f.shape, FractureShape::Polygon);
    ASSERT_EQ(f.vertices.size(), 5u);
    const auto [e1, e2] = plane_basis(f.normal);
    const V3 r = f.vertices[0] - f.centre;
    const double a = std::atan2(r.dot(e2), r.dot(e1));
    lo = std::min(lo, a);
    hi = std::max(hi, a);
  }
  EXPECT_GT(first.size(), 20u);
  EXPECT_GT(hi - lo, 1.5 * kPi);
}

TEST(Fractures3dSets, PolygonSetP32ConvergesToTheTarget) {
  // As for discs (Dfn3dGenerate.P32TargetIsReachedInTheDomain): each hexagon
  // has the area pi r^2 of its disc, so the area over the grown box reaches
  // the target; with a margin wider than any polygon (circumradius 1.1 r,
  // r > 3.6 m has probability ~1e-8) the P32 inside the 10 m cube estimates
  // it. Area inside the box is exact (each polygon clipped to the box). About
  // 600 polygons a seed cut the domain: ~3 % scatter per seed, ~1 % over the
  // 8 seeds. Tolerance 3 %.
  const Box3 domain = cube(0, 10);
  const double target = 1.5;
  double sum = 0;
  const int seeds = 8;
  for (int seed = 1; seed <= seeds; ++seed) {
    const auto polygons = generate_fractures({polygon_set(6, target)}, domain, 4, static_cast<std::uint64_t>(seed));
    sum += p32_in_box(polygons, domain);
  }
  EXPECT_NEAR(sum / seeds / target, 1, 0.03) << "mean realised P32 " << sum / seeds;
}

TEST(Fractures3dSets, BadPolygonSidesAreInputErrors) {
  DiscSetSpec s = polygon_set(2, 1);
  EXPECT_NE(error_of([&] { generate_fractures({s}, cube(0, 1), 0, 1); }).find("Fracture set 'P' has 2 polygon sides"),
            std::string::npos);
  s.polygon_sides = -4;
  EXPECT_THROW(generate_fractures({s}, cube(0, 1), 0, 1), InputError);
  s.polygon_sides = kMaxPolygonSides + 1;
  EXPECT_THROW(generate_fractures({s}, cube(0, 1), 0, 1), InputError);
}

// ---- areas in a box ----------------------------------------------------

TEST(Fractures3dMeasures, AreasInABoxExactCases) {
  const Box3 b = box(V3(0, 0, 0), V3(4, 2, 3));
  // A unit square centred on the face x = 4: half inside.
  Fracture3 sq = polygon_fracture({V3(4.5, 0.5, 1), V3(4.5, 1.5, 1), V3(3.5, 1.5, 1), V3(3.5, 0.5, 1)}, 0, "sq");
  EXPECT_NEAR(fracture_area_in_box(sq, b), 0.5, 1e-12);
  // A horizontal plane cuts the 4 x 2 footprint; a plane dipping 45 degrees
  // east through the box's middle cuts 2 x (3 sqrt 2) (its section runs from
  // the bottom face to the top face over 3 m of x).
  Fracture3 h = make_plane({0, 0, V3(1, 1, 1.5), std::nullopt}, 0);
  EXPECT_NEAR(fracture_area_in_box(h, b), 8, 1e-12);
  Fracture3 d45 = make_plane({45, 90, V3(2, 1, 1.5), std::nullopt}, 0);
  EXPECT_NEAR(fracture_area_in_box(d45, b), 2 * 3 * std::sqrt(2.0), 1e-12);
  // A disc as in dfn3d: a vertical disc centred on a face it crosses is half inside.
  Fracture3 disc = make_plane({90, 0, V3(4, 1, 1.5), 0.5}, 0);
  EXPECT_NEAR(fracture_area_in_box(disc, b), kPi * 0.125, 1e-12);
  EXPECT_NEAR(p32_in_box({sq, h}, b), 8.5 / 24, 1e-12);
}

// ---- deterministic planes ----------------------------------------------

TEST(Fractures3dPlanes, DeterministicPlaneOrDisc) {
  const Fracture3 p = make_plane({60, 30, V3(1, 2, 3), std::nullopt}, 5);
  EXPECT_EQ(p.shape, FractureShape::Plane);
  EXPECT_EQ(p.centre, V3(1, 2, 3));
  EXPECT_EQ(p.normal, normal_from_dip(60, 30));
  EXPECT_EQ(p.set, 5);
  const Fracture3 d = make_plane({60, 30, V3(1, 2, 3), 2.5}, 0);
  EXPECT_EQ(d.shape, FractureShape::Disc);
  EXPECT_EQ(d.radius, 2.5);
  EXPECT_NE(error_of([] { make_plane({60, 30, V3(1, 2, 3), 0.0}, 0); }).find("radius 0"), std::string::npos);
  EXPECT_NE(error_of([] { make_plane({95, 30, V3(1, 2, 3), std::nullopt}, 0); }).find("dip 95"), std::string::npos);
  EXPECT_THROW(make_plane({10, 30, V3(std::nan(""), 2, 3), std::nullopt}, 0), InputError);
}

// ---- persistent sets ---------------------------------------------------

TEST(Fractures3dPlanes, PersistentSetCountsAndPositionsAreExact) {
  // Box 10 x 20 x 5. Expected planes: offsets point . n + k s strictly inside
  // the box's range along n (planes on its faces cut no rock).
  const Box3 b = box(V3(0, 0, 0), V3(10, 20, 5));
  Stream rng(1);
  std::vector<std::pair<PersistentSetSpec, std::vector<double>>> cases;
  // Horizontal, spacing 1.5 from the lo corner: z = 1.5, 3, 4.5 (0 is the bottom face).
  cases.emplace_back(persistent("H", 0, 0, 1.5), std::vector<double>{1.5, 3, 4.5});
  // Vertical, normal +x, through x = 1, spacing 2: x = 1, 3, 5, 7, 9.
  cases.emplace_back(persistent("V", 90, 90, 2, V3(1, 0, 0)), std::vector<double>{1, 3, 5, 7, 9});
  // Dipping 45/000: n = (0, 1, 1)/sqrt 2, the box spans [0, 25/sqrt 2 = 17.68];
  // spacing 2.5 from the lo corner: k = 1..7.
  cases.emplace_back(persistent("D", 45, 0, 2.5), std::vector<double>{2.5, 5, 7.5, 10, 12.5, 15, 17.5});
  // Through a point far below: z = -1000.25 + 0.5 k = 0.25, 0.75, ..., 4.75.
  std::vector<double> far;
  for (int k = 0; k < 10; ++k) far.push_back(0.25 + 0.5 * k);
  cases.emplace_back(persistent("F", 0, 0, 0.5, V3(3, 3, -1000.25)), far);
  for (const auto& [spec, offsets] : cases) {
    const auto planes = generate_persistent_set(spec, 7, b, rng);
    ASSERT_EQ(planes.size(), offsets.size()) << spec.name;
    const V3 n = normal_from_dip(spec.dip_deg, spec.dip_direction_deg);
    for (std::size_t i = 0; i < planes.size(); ++i) {
      EXPECT_EQ(planes[i].shape, FractureShape::Plane);
      EXPECT_EQ(planes[i].set, 7);
      EXPECT_EQ(planes[i].normal, n);
      EXPECT_NEAR(planes[i].offset(), offsets[i], 1e-12 * 1000) << spec.name << " plane " << i;
      EXPECT_TRUE(b.contains(planes[i].centre)) << spec.name << " plane " << i;
    }
  }
}

TEST(Fractures3dPlanes, PersistentSetWithRandomSpacing) {
  // Spacings mean * (1 + r X), X uniform on [-1, 1): consecutive planes are
  // between s (1 - r) and s (1 + r) apart; over ~200 planes the mean spacing's
  // standard error is r s / sqrt(3 * 200) = 2 % of s; tolerance 6 %.
  const Box3 b = box(V3(0, 0, 0), V3(10, 10, 100));
  const PersistentSetSpec s = persistent("R", 0, 0, 0.5, V3(0, 0, 37.3), 0.5);
  const auto planes = generate_persistent_sets({s}, b, 11);
  ASSERT_GT(planes.size(), 150u);
  for (std::size_t i = 1; i < planes.size(); ++i) {
    const double gap = planes[i].offset() - planes[i - 1].offset();
    EXPECT_GE(gap, 0.25 - 1e-12);
    EXPECT_LE(gap, 0.75 + 1e-12);
  }
  const double mean = (planes.back().offset() - planes.front().offset()) / static_cast<double>(planes.size() - 1);
  EXPECT_NEAR(mean / 0.5, 1, 0.06);
  // One plane through the point; same seed same planes; each set its own stream.
  EXPECT_TRUE(std::any_of(planes.begin(), planes.end(), [](const Fracture3& f) { return f.offset() == 37.3; }));
  const PersistentSetSpec other = persistent("O", 80, 10, 1, std::nullopt, 0.3);
  const auto two = generate_persistent_sets({s, other}, b, 11, 2);
  const auto again = generate_persistent_sets({s}, b, 11, 2);
  EXPECT_TRUE(same(again, std::vector<Fracture3>(two.begin(), two.begin() + static_cast<long>(again.size()))));
  EXPECT_FALSE(same(planes, generate_persistent_sets({s}, b, 12)));
}

TEST(Fractures3dPlanes, PersistentSetErrorsNameTheSet) {
  const Box3 b = cube(0, 10);
  Stream rng(1);
  EXPECT_NE(error_of([&] { generate_persistent_set(persistent("J1", 30, 0, 0), 0, b, rng); })
                .find("Persistent set 'J1' has spacing 0"),
            std::string::npos);
  EXPECT_NE(error_of([&] { generate_persistent_set(persistent("J1", 30, 0, 1, std::nullopt, 1), 0, b, rng); })
                .find("spacing randomness 1"),
            std::string::npos);
  EXPECT_NE(error_of([&] { generate_persistent_set(persistent("J1", 100, 0, 1), 0, b, rng); })
                .find("Persistent set 'J1' has dip 100"),
            std::string::npos);
  EXPECT_NE(error_of([&] { generate_persistent_set(persistent("J1", 0, 0, 1e-6), 0, b, rng); })
                .find("more than the limit"),
            std::string::npos);
  // Found by the fuzz target scenario3d (docs/reliability.md): a point at
  // 1.8e19 m, 1.3e17 spacings from the domain, made k of t0 + k s too large
  // for ++k to change it, and the set grew until the memory ran out. The
  // limit is 1e9 spacings (kMaxSpacingsToPoint). Horizontal planes, spacing
  // 12, through z = 2^64 = 1.8446744073709552e19 above the cube [0, 10]^3:
  // (2^64 - 10) / 12 = 1.54e18 spacings away. Spacing 1 through z = -(1e9 + 1)
  // is 1e9 + 1 spacings away: refused too; through z = -(1e9 - 1) it is
  // within, and the planes are z = 1 .. 9 (0 and 10 are the cube's faces).
  EXPECT_NE(error_of([&] { generate_persistent_set(persistent("S", 0, 0, 12, V3(0, 0, 1.8446744073709552e19)), 0, b, rng); })
                .find("Persistent set 'S' passes through a point 1.54e+18 spacings from the domain"),
            std::string::npos);
  EXPECT_NE(error_of([&] { generate_persistent_set(persistent("S", 0, 0, 1, V3(0, 0, -1e9 - 1)), 0, b, rng); })
                .find("more than the limit of 1e+09"),
            std::string::npos);
  const auto within = generate_persistent_set(persistent("S", 0, 0, 1, V3(0, 0, -1e9 + 1)), 0, b, rng);
  ASSERT_EQ(within.size(), 9u);
  for (std::size_t i = 0; i < within.size(); ++i) EXPECT_DOUBLE_EQ(within[i].offset(), 1.0 + static_cast<double>(i));
}

// ---- polygons from vertices --------------------------------------------

TEST(Fractures3dPolygon, OrientsFitsAndChecks) {
  // Clockwise seen from above: the fitted normal points down, so the stored
  // one is reversed to +z and the vertices with it.
  const Fracture3 f = polygon_fracture({V3(0, 0, 2), V3(0, 1, 2), V3(1, 1, 2), V3(1, 0, 2), V3(0, 0, 2)}, 3, "w");
  EXPECT_EQ(f.shape, FractureShape::Polygon);
  EXPECT_NEAR((f.normal - V3(0, 0, 1)).norm(), 0, 1e-15);
  ASSERT_EQ(f.vertices.size(), 4u);  // the closing repeat dropped
  EXPECT_GT(vector_area(f.vertices).dot(f.normal), 0);
  EXPECT_NEAR((f.centre - V3(0.5, 0.5, 2)).norm(), 0, 1e-15);
  EXPECT_EQ(f.set, 3);
  // A vertex 1e-6 off the plane of a 1 m square is within the tolerance (and
  // projected onto the fitted plane); 0.01 m is not.
  const Fracture3 g = polygon_fracture({V3(0, 0, 0), V3(1, 0, 0), V3(1, 1, 1e-6), V3(0, 1, 0)}, 0, "w");
  for (const V3& p : g.vertices) EXPECT_NEAR(g.normal.dot(p - g.centre), 0, 1e-15);
  EXPECT_NE(error_of([] { polygon_fracture({V3(0, 0, 0), V3(1, 0, 0), V3(1, 1, 0.01), V3(0, 1, 0)}, 0, "F7"); })
                .find("F7 is not planar: vertex"),
            std::string::npos);
  EXPECT_NE(error_of([] { polygon_fracture({V3(0, 0, 0), V3(1, 0, 0)}, 0, "F7"); }).find("F7 has 2 vertices"),
            std::string::npos);
  EXPECT_NE(error_of([] { polygon_fracture({V3(0, 0, 0), V3(1, 0, 0), V3(2, 0, 0)}, 0, "F7"); }).find("no area"),
            std::string::npos);
  const std::vector<V3> notch{V3(0, 0, 0), V3(2, 0, 0), V3(1, 0.2, 0), V3(2, 2, 0), V3(0, 2, 0)};
  EXPECT_NE(error_of([&] { polygon_fracture(notch, 0, "F7"); })
                .find("F7 is not convex: it turns inwards at vertex 3"),
            std::string::npos);
  // A pentagram turns the same way at every vertex but winds twice.
  std::vector<V3> star;
  for (int k = 0; k < 5; ++k) star.emplace_back(std::cos(4 * kPi * k / 5), std::sin(4 * kPi * k / 5), 0);
  EXPECT_NE(error_of([&] { polygon_fracture(star, 0, "F7"); }).find("wind round 2"), std::string::npos);
  EXPECT_NE(error_of([] { polygon_fracture({V3(0, 0, 0), V3(1, 0, 0), V3(1, 0, 0), V3(0, 1, 0)}, 0, "F7"); })
                .find("vertices 2 and 3 at the same point"),
            std::string::npos);
}

}  // namespace dda::dl
