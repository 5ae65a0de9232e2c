// 3D disc fracture networks: orientation, Fisher sampling, radius laws,
// P32-target generation and the P10/P21/P32 measures.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"
#include "dda/dl/dfn3d.hpp"
#include "dda/dl/dfn3d_measures.hpp"

namespace dda::dl {

namespace {

using V3 = Eigen::Vector3d;
constexpr double kInf = std::numeric_limits<double>::infinity();

Box3 cube(double lo, double hi) { return {V3::Constant(lo), V3::Constant(hi)}; }

double angle_deg(const V3& a, const V3& b) { return rad2deg(std::atan2(a.cross(b).norm(), a.dot(b))); }

struct Moments {
  double mean = 0, std = 0;
};
Moments sample_moments(const SizeLaw& law, std::size_t n, std::uint64_t seed) {
  Stream rng(seed, "test.size");
  double s = 0, s2 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = law.sample(rng);
    s += r;
    s2 += r * r;
  }
  const double mean = s / static_cast<double>(n);
  return {mean, std::sqrt(s2 / static_cast<double>(n) - mean * mean)};
}

bool same_discs(const std::vector<Disc>& a, const std::vector<Disc>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].centre != b[i].centre || a[i].normal != b[i].normal || a[i].radius != b[i].radius || a[i].set != b[i].set)
      return false;
  return true;
}

DiscSetSpec set_spec(double dip, double dir, double kappa, SizeLaw size, double p32) {
  DiscSetSpec s;
  s.name = std::string{"J"};  // not = "J": GCC 12 warns falsely (-Wrestrict, bug 105329) with -march=native
  s.dip_deg = dip;
  s.dip_direction_deg = dir;
  s.kappa = kappa;
  s.size = size;
  s.p32 = p32;
  return s;
}

}  // namespace

// ---- orientation -------------------------------------------------------

TEST(Dfn3dOrientation, NormalOf30Dipping090) {
  // (sin 30 sin 90, sin 30 cos 90, cos 30) = (0.5, 0, sqrt(3)/2).
  const V3 n = normal_from_dip(30, 90);
  EXPECT_NEAR(n.x(), 0.5, 1e-15);
  EXPECT_NEAR(n.y(), 0.0, 1e-15);
  EXPECT_NEAR(n.z(), std::sqrt(3.0) / 2, 1e-15);
}

TEST(Dfn3dOrientation, DipDirectionRoundTrip) {
  for (double dip = 1; dip <= 90; dip += 7.3)
    for (double dir = 0; dir < 360; dir += 11.7) {
      const DipDirection back = dip_from_normal(normal_from_dip(dip, dir));
      EXPECT_NEAR(back.dip_deg, dip, 1e-10);
      // A vertical plane is the same for dir and dir + 180 (normal folded to y > 0).
      const double want = dip == 90 && dir >= 180 ? dir - 180 : dir;
      EXPECT_NEAR(back.dip_direction_deg, want, 1e-10) << dip << "/" << dir;
    }
  // The downward normal names the same plane; a horizontal plane has dip direction 0.
  const DipDirection down = dip_from_normal(-normal_from_dip(40, 250));
  EXPECT_NEAR(down.dip_deg, 40, 1e-12);
  EXPECT_NEAR(down.dip_direction_deg, 250, 1e-12);
  EXPECT_EQ(dip_from_normal(V3(0, 0, -3)).dip_deg, 0);
  EXPECT_EQ(dip_from_normal(V3(0, 0, -3)).dip_direction_deg, 0);
}

// ---- Fisher ------------------------------------------------------------

TEST(Dfn3dFisher, MeanDirectionAndConcentrationRecovered) {
  // Fisher (1953): the resultant length R of N unit vectors gives
  // kappa_hat = (N - 1) / (N - R), with relative standard error about
  // 1/sqrt(N) = 0.7 % here; the mean direction's angular standard error is
  // about 1/sqrt(N kappa) = 0.09 deg. Tolerances: 5 % and 0.5 deg.
  const double kappa = 20;
  const std::size_t n = 20000;
  const V3 mean = normal_from_dip(60, 120);
  Stream rng(7, "test.fisher");
  V3 sum = V3::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const V3 v = sample_fisher(mean, kappa, rng);
    ASSERT_NEAR(v.norm(), 1, 1e-12);
    sum += v;
  }
  const double r = sum.norm(), nd = static_cast<double>(n);
  const double kappa_hat = (nd - 1) / (nd - r);
  EXPECT_LT(angle_deg(sum, mean), 0.5);
  EXPECT_NEAR(kappa_hat / kappa, 1, 0.05) << "kappa_hat " << kappa_hat;
}

TEST(Dfn3dFisher, KappaZeroIsUniformOnTheHemisphere) {
  // Uniform on the sphere, the z of a point is uniform on [-1, 1]
  // (Archimedes), so the folded |z| = cos theta from the vertical is uniform on
  // [0, 1]: mean 1/2, standard error sqrt(1/12 / N) = 0.002; tolerance 5 of
  // them.
  const std::size_t n = 20000;
  Stream rng(11, "test.fisher");
  double sum_z = 0;
  for (std::size_t i = 0; i < n; ++i) sum_z += upper_hemisphere(sample_fisher(V3(0, 1, 1), 0, rng)).z();
  EXPECT_NEAR(sum_z / static_cast<double>(n), 0.5, 5 * std::sqrt(1.0 / 12 / static_cast<double>(n)));
}

TEST(Dfn3dFisher, InfiniteKappaGivesTheMean) {
  Stream rng(3, "test.fisher");
  const V3 mean = normal_from_dip(35, 200);
  for (int i = 0; i < 10; ++i) EXPECT_LT(angle_deg(sample_fisher(mean, kInf, rng), mean), 1e-12);
}

// ---- radius laws -------------------------------------------------------

TEST(Dfn3dSize, ConstantIsConstant) {
  Stream rng(1, "test.size");
  EXPECT_EQ(SizeLaw::constant(2.5).sample(rng), 2.5);
  EXPECT_EQ(SizeLaw::constant(2.5).max_radius(), 2.5);
}

TEST(Dfn3dSize, LognormalMatchesMeanAndStd) {
  // The law is parameterised by the radius's own mean and std; 200 000
  // samples: standard errors 0.06 % of the mean and about 0.2 % of the std.
  const Moments m = sample_moments(SizeLaw::lognormal(2.0, 0.5), 200000, 1);
  EXPECT_NEAR(m.mean / 2.0, 1, 0.02);
  EXPECT_NEAR(m.std / 0.5, 1, 0.03);
  // mean_area = pi E[r^2] = pi (std^2 + mean^2) = 4.25 pi for the asked law.
  EXPECT_NEAR(SizeLaw::lognormal(2.0, 0.5).mean_area(), 4.25 * kPi, 1e-12);
}

TEST(Dfn3dSize, ExponentialMatchesMean) {
  // Exponential: std = mean; standard error of the mean 0.2 % over 200 000.
  const Moments m = sample_moments(SizeLaw::exponential(1.5), 200000, 2);
  EXPECT_NEAR(m.mean / 1.5, 1, 0.02);
  EXPECT_NEAR(m.std / 1.5, 1, 0.03);
  EXPECT_NEAR(SizeLaw::exponential(1.5).mean_area(), 2 * kPi * 1.5 * 1.5, 1e-12);  // E[r^2] = 2 mean^2
}

TEST(Dfn3dSize, TruncatedPowerLawMatchesMean) {
  // p(r) = (alpha - 1) r^-alpha / (rmin^(1-alpha) - rmax^(1-alpha)) on
  // [rmin, rmax]; integrating r p(r) gives, for alpha != 2,
  // E[r] = (alpha-1)/(alpha-2) (rmin^(2-alpha) - rmax^(2-alpha)) / (rmin^(1-alpha) - rmax^(1-alpha)).
  // mean_area() is checked against the sample's pi E[r^2] = pi (std^2 + mean^2)
  // (alpha = 3 takes the logarithmic branch).
  for (const double alpha : {1.5, 2.5, 3.0, 3.5}) {
    const double rmin = 0.5, rmax = 20;
    const double want = (alpha - 1) / (alpha - 2) * (std::pow(rmin, 2 - alpha) - std::pow(rmax, 2 - alpha)) /
                        (std::pow(rmin, 1 - alpha) - std::pow(rmax, 1 - alpha));
    const SizeLaw law = SizeLaw::power_law(alpha, rmin, rmax);
    const Moments m = sample_moments(law, 400000, 3);
    EXPECT_NEAR(m.mean / want, 1, 0.02) << "alpha " << alpha;
    EXPECT_NEAR(kPi * (m.std * m.std + m.mean * m.mean) / law.mean_area(), 1, 0.03) << "alpha " << alpha;
    Stream rng(4, "test.size");
    for (int i = 0; i < 1000; ++i) {
      const double r = law.sample(rng);
      ASSERT_GE(r, rmin);
      ASSERT_LE(r, rmax);
    }
  }
}

// ---- measures on single discs (geometry) -------------------------------

TEST(Dfn3dMeasures, DiscAreaInBoxExactCases) {
  const Box3 box = cube(-1, 1);
  // Horizontal disc of radius 1.2 at the centre of the cube [-1, 1]^3: the
  // square of side 2 cuts four circular segments at distance h = 1, each of
  // area r^2 acos(h/r) - h sqrt(r^2 - h^2).
  const double r = 1.2, seg = r * r * std::acos(1 / r) - std::sqrt(r * r - 1);
  EXPECT_NEAR(disc_area_in_box({V3::Zero(), V3(0, 0, 1), r, 0}, box), kPi * r * r - 4 * seg, 1e-12);
  // Radius sqrt(2): the circle circumscribes the square, area 4.
  EXPECT_NEAR(disc_area_in_box({V3::Zero(), V3(0, 0, 1), std::sqrt(2.0), 0}, box), 4, 1e-12);
  // A vertical disc centred on the face x = 1: half inside.
  EXPECT_NEAR(disc_area_in_box({V3(1, 0, 0), V3(0, 1, 0), 0.5, 0}, box), kPi * 0.125, 1e-12);
  // Fully inside (tilted), and fully outside.
  EXPECT_NEAR(disc_area_in_box({V3(0.1, 0, 0), normal_from_dip(40, 30), 0.8, 0}, box), kPi * 0.64, 1e-12);
  EXPECT_EQ(disc_area_in_box({V3(3, 0, 0), V3(0, 0, 1), 1, 0}, box), 0);
}

TEST(Dfn3dMeasures, DiscAreaInBoxMatchesMonteCarloForATiltedDiscAtACorner) {
  // Independent check of the general case: points uniform on the disc
  // (radius sqrt(U), uniform angle), the fraction inside the box times pi r^2.
  // 400 000 points: standard error below 0.2 % of the disc's area.
  const Disc d{V3(0.5, -0.4, 0.3), normal_from_dip(55, 140), 1.3, 0};
  const Box3 box = cube(-1, 1);
  const auto [e1, e2] = plane_basis(d.normal);
  Stream rng(5, "test.mc");
  const int n = 400000;
  int in = 0;
  for (int i = 0; i < n; ++i) {
    const double rho = d.radius * std::sqrt(rng.uniform01()), phi = 2 * kPi * rng.uniform01();
    const V3 p = d.centre + rho * (std::cos(phi) * e1 + std::sin(phi) * e2);
    if ((p.array() >= box.lo.array()).all() && (p.array() <= box.hi.array()).all()) ++in;
  }
  const double full = kPi * d.radius * d.radius, mc = full * in / n;
  EXPECT_NEAR(disc_area_in_box(d, box), mc, 0.01 * full);
  EXPECT_GT(mc, 0.1 * full);  // the case does cut the disc
  EXPECT_LT(mc, 0.9 * full);
}

TEST(Dfn3dMeasures, P10AndP21OfOneHorizontalDisc) {
  const std::vector<Disc> one{{V3::Zero(), V3(0, 0, 1), 1, 0}};
  // A vertical line of length 2 through the disc: 1 crossing / 2 m.
  EXPECT_DOUBLE_EQ(p10_along(one, V3(0.3, 0.3, -1), V3(0.3, 0.3, 1)), 0.5);
  EXPECT_EQ(p10_along(one, V3(1.5, 0, -1), V3(1.5, 0, 1)), 0);  // beyond the radius
  EXPECT_EQ(p10_along(one, V3(0, 0, 0.5), V3(0, 0, 1)), 0);     // segment ends above
  // The plane x = 0.6 cuts a chord 2 sqrt(1 - 0.36) = 1.6 long along y.
  // Rectangle y in [-2, 2], z in [-1, 1] (area 8): P21 = 0.2; y in [0, 2]
  // (area 4) keeps half the chord: 0.8 / 4 = 0.2.
  EXPECT_NEAR(p21_on(one, {V3(0.6, -2, -1), V3(0, 4, 0), V3(0, 0, 2)}), 0.2, 1e-12);
  EXPECT_NEAR(p21_on(one, {V3(0.6, 0, -1), V3(0, 2, 0), V3(0, 0, 2)}), 0.2, 1e-12);
  EXPECT_EQ(p21_on(one, {V3(0.6, -2, 0.5), V3(0, 4, 0), V3(0, 0, 2)}), 0);  // rectangle above the disc
  EXPECT_EQ(p21_on(one, {V3(-2, -2, 0), V3(4, 0, 0), V3(0, 4, 0)}), 0);    // parallel plane
}

// ---- generation --------------------------------------------------------

TEST(Dfn3dGenerate, P32TargetIsReachedInTheDomain) {
  // With a margin of 3 m (a log-normal radius of mean 1, std 0.3 exceeds 3 m
  // with probability ~1e-6), discs centred outside the grown box do not reach
  // the domain, so the P32 inside the 10 m cube estimates the target. One
  // seed: about 600 discs cut the domain, binomial scatter ~3 %; the mean of 8
  // seeds has ~1 %. Tolerance 3 %.
  const Box3 domain = cube(0, 10);
  const double margin = 3, target = 1.5;
  const DiscSetSpec spec = set_spec(50, 210, 10, SizeLaw::lognormal(1, 0.3), target);
  double sum = 0;
  const int seeds = 8;
  for (int seed = 1; seed <= seeds; ++seed) {
    const auto discs = generate_dfn({spec}, domain, margin, static_cast<std::uint64_t>(seed));
    // The stopping rule: the full area over the grown box reaches the target
    // and overshoots by less than the last disc.
    double area = 0;
    for (const Disc& d : discs) area += kPi * d.radius * d.radius;
    const double v = domain.grown(margin).volume(), last = kPi * discs.back().radius * discs.back().radius;
    EXPECT_GE(area / v, target);
    EXPECT_LT((area - last) / v, target);
    sum += p32_in_box(discs, domain);
  }
  EXPECT_NEAR(sum / seeds / target, 1, 0.03) << "mean realised P32 " << sum / seeds;
}

TEST(Dfn3dGenerate, StereologyOfUniformlyOrientedDiscs) {
  // For uniformly oriented discs (kappa = 0) a line meets a disc with
  // probability proportional to |cos| of the angle to its normal, mean 1/2:
  // P10 = P32 / 2; a plane cuts traces with mean length factor pi/4:
  // P21 = (pi/4) P32 (e.g. Dershowitz & Herda 1992). Radius 1 m, margin 1 m
  // (no edge effect). Over 6 seeds, 3 x 49 axis-parallel lines of 10 m
  // (~7 000 crossings) and 3 x 9 section planes of 10 m x 10 m; tolerance 5 %
  // (the lines and planes share discs, so the scatter exceeds the Poisson
  // 1.2 %).
  const Box3 domain = cube(0, 10);
  const DiscSetSpec spec = set_spec(0, 0, 0, SizeLaw::constant(1), 2.0);
  double p32 = 0, p10 = 0, p21 = 0;
  const int seeds = 6;
  for (int seed = 1; seed <= seeds; ++seed) {
    const auto discs = generate_dfn({spec}, domain, 1, static_cast<std::uint64_t>(100 + seed));
    p32 += p32_in_box(discs, domain);
    double lines = 0, planes = 0;
    int nl = 0, np = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      for (int i = 0; i < 7; ++i)
        for (int j = 0; j < 7; ++j) {
          V3 a = V3::Zero();
          a[u] = 1.25 + 1.25 * i;
          a[w] = 1.25 + 1.25 * j;
          V3 b = a;
          b[axis] = 10;
          lines += p10_along(discs, a, b);
          ++nl;
        }
      for (int k = 1; k <= 9; ++k) {
        Rectangle3 rect{V3::Zero(), V3::Zero(), V3::Zero()};
        rect.origin[axis] = k;
        rect.e1[u] = 10;
        rect.e2[w] = 10;
        planes += p21_on(discs, rect);
        ++np;
      }
    }
    p10 += lines / nl;
    p21 += planes / np;
  }
  EXPECT_NEAR(p10 / p32, 0.5, 0.05 * 0.5) << "P10 " << p10 / seeds << " P32 " << p32 / seeds;
  EXPECT_NEAR(p21 / p32, kPi / 4, 0.05 * kPi / 4) << "P21 " << p21 / seeds << " P32 " << p32 / seeds;
}

TEST(Dfn3dGenerate, SameSeedSameDiscsAndEachSetHasItsOwnStream) {
  const Box3 domain = cube(0, 5);
  DiscSetSpec a = set_spec(30, 90, 15, SizeLaw::power_law(2.5, 0.2, 3), 0.8);
  DiscSetSpec b = set_spec(80, 340, kInf, SizeLaw::exponential(0.5), 0);
  b.count = 200;
  const auto both = generate_dfn({a, b}, domain, 1, 42);
  ASSERT_GT(both.size(), 300u);
  EXPECT_TRUE(same_discs(both, generate_dfn({a, b}, domain, 1, 42)));
  EXPECT_FALSE(same_discs(both, generate_dfn({a, b}, domain, 1, 43)));
  // Set 0 alone gives the same discs as set 0 of the pair.
  std::vector<Disc> first;
  for (const Disc& d : both)
    if (d.set == 0) first.push_back(d);
  EXPECT_TRUE(same_discs(first, generate_dfn({a}, domain, 1, 42)));
  // Count honoured, normals all at the mean for kappa = infinity, centres in
  // the grown box.
  std::size_t n1 = 0;
  for (const Disc& d : both) {
    EXPECT_TRUE((d.centre.array() >= -1).all() && (d.centre.array() <= 6).all());
    EXPECT_GE(d.normal.z(), 0);
    if (d.set == 1) {
      ++n1;
      EXPECT_LT(angle_deg(d.normal, normal_from_dip(80, 340)), 1e-12);
    }
  }
  EXPECT_EQ(n1, 200u);
}

TEST(Dfn3dErrors, BadParametersAreInputErrors) {
  auto message = [](auto&& f) -> std::string {
    try {
      f();
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(message([] { SizeLaw::constant(0); }).find("constant size law's radius"), std::string::npos);
  EXPECT_NE(message([] { SizeLaw::lognormal(1, -1); }).find("log-normal size law's std"), std::string::npos);
  EXPECT_NE(message([] { SizeLaw::lognormal(-1, 1); }).find("log-normal size law's mean"), std::string::npos);
  EXPECT_NE(message([] { SizeLaw::exponential(kInf); }).find("exponential size law's mean"), std::string::npos);
  EXPECT_NE(message([] { SizeLaw::power_law(1, 1, 2); }).find("power-law size law's exponent"), std::string::npos);
  EXPECT_NE(message([] { SizeLaw::power_law(2, 0, 2); }).find("power-law size law's rmin"), std::string::npos);
  EXPECT_NE(message([] { SizeLaw::power_law(2, 2, 2); }).find("power-law size law's rmax"), std::string::npos);
  EXPECT_THROW(normal_from_dip(95, 0), InputError);
  EXPECT_THROW(normal_from_dip(30, std::nan("")), InputError);
  EXPECT_THROW(dip_from_normal(V3::Zero()), InputError);
  Stream rng(1);
  EXPECT_THROW(sample_fisher(V3(0, 0, 1), -1, rng), InputError);

  const Box3 domain = cube(0, 1);
  DiscSetSpec s = set_spec(30, 90, 10, SizeLaw::constant(1), 0);
  EXPECT_THROW(generate_dfn({s}, domain, 0, 1), InputError);  // no intensity
  s.count = 5;
  s.p32 = 1;
  EXPECT_THROW(generate_dfn({s}, domain, 0, 1), InputError);  // both
  s.count = 0;
  s.p32 = -1;
  EXPECT_THROW(generate_dfn({s}, domain, 0, 1), InputError);
  s.p32 = 1;
  EXPECT_THROW(generate_dfn({s}, domain, -1, 1), InputError);
  EXPECT_THROW(generate_dfn({s}, {V3(0, 0, 0), V3(1, 0, 1)}, 0, 1), InputError);
  s.kappa = std::nan("");
  EXPECT_THROW(generate_dfn({s}, domain, 0, 1), InputError);
  s.kappa = 10;
  s.size = SizeLaw::constant(1e-4);
  s.p32 = 1e6;  // needs ~1e14 discs
  EXPECT_THROW(generate_dfn({s}, domain, 0, 1), InputError);
  EXPECT_THROW(p10_along({}, V3(1, 1, 1), V3(1, 1, 1)), InputError);
  EXPECT_THROW(p21_on({}, {V3::Zero(), V3(1, 0, 0), V3(1, 1, 0)}), InputError);
}

}  // namespace dda::dl
