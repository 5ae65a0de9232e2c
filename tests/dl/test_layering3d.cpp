// 3D mechanical layering: beds, bed boundaries, layer-bound joint polygons
// and their realised FSI.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "dda/common/error.hpp"
#include "dda/dl/dfn3d.hpp"
#include "dda/dl/layering3d.hpp"
#include "dda/dl/polygon3d.hpp"

namespace dda::dl {

namespace {

using V3 = Eigen::Vector3d;

ThicknessSpec lognormal(double mean, double std, double minimum) {
  ThicknessSpec t;
  t.kind = ThicknessSpec::Kind::LogNormal;
  lognormal_from_moments(mean, std, t.mu, t.sigma);
  t.minimum = minimum;
  return t;
}

LayeringSpec3 dipping_beds() {
  LayeringSpec3 s;
  s.dip_deg = 20;
  s.dip_direction_deg = 135;
  s.thickness = lognormal(1.0, 0.5, 0.4);
  s.sets = {{"J1", 80, 30, 1.5, 0.3}, {"J2", 60, 250, 1.0, 0.0}};
  return s;
}

std::pair<double, double> range_along(const V3& n, const std::vector<V3>& pts) {
  double lo = 1e300, hi = -1e300;
  for (const V3& p : pts) {
    lo = std::min(lo, n.dot(p));
    hi = std::max(hi, n.dot(p));
  }
  return {lo, hi};
}

const Box3 kBox{V3(0, 0, 0), V3(20, 15, 10)};

}  // namespace

TEST(Layering3d, BedsStackFromTheLowestToTheHighestCorner) {
  const LayeringSpec3 spec = dipping_beds();
  const auto out = generate_layering3d(spec, kBox, 5);
  const V3 nb = normal_from_dip(20, 135);
  EXPECT_LT((out.bed_normal - nb).norm(), 1e-15);
  // Along nb = (sin 20 sin 135, sin 20 cos 135, cos 20) the box spans from the
  // corner (0, 15, 0) to the corner (20, 0, 10).
  const double w_lo = nb.dot(V3(0, 15, 0)), w_hi = nb.dot(V3(20, 0, 10));
  ASSERT_GT(out.layers.size(), 5u);
  EXPECT_DOUBLE_EQ(out.layers.front().bottom, w_lo);
  EXPECT_DOUBLE_EQ(out.layers.back().top, w_hi);
  for (std::size_t i = 0; i < out.layers.size(); ++i) {
    const Layer& l = out.layers[i];
    EXPECT_GE(out.drawn_thickness[i], 0.4);  // redrawn below the minimum
    if (i + 1 < out.layers.size()) {
      EXPECT_DOUBLE_EQ(l.thickness(), out.drawn_thickness[i]);  // only the top bed is cut
      EXPECT_EQ(l.top, out.layers[i + 1].bottom);
    }
  }
  // Interior boundaries: one Plane per contact, kind Bedding, bedding set after the joint sets.
  ASSERT_EQ(out.bed_boundaries.size(), out.layers.size() - 1);
  for (std::size_t i = 0; i < out.bed_boundaries.size(); ++i) {
    const Fracture3& b = out.bed_boundaries[i];
    EXPECT_EQ(b.shape, FractureShape::Plane);
    EXPECT_EQ(b.kind, LineKind::Bedding);
    EXPECT_EQ(b.set, 2);
    EXPECT_EQ(b.layer, static_cast<int>(i));
    EXPECT_NEAR(b.offset(), out.layers[i].top, 1e-12);
    EXPECT_TRUE(kBox.contains(b.centre));
  }
}

TEST(Layering3d, EveryJointLiesWithinItsBed) {
  const auto out = generate_layering3d(dipping_beds(), kBox, 5);
  ASSERT_GT(out.joints.size(), 200u);
  for (const Fracture3& j : out.joints) {
    ASSERT_EQ(j.shape, FractureShape::Polygon);
    ASSERT_GE(j.layer, 0);
    ASSERT_GE(j.vertices.size(), 3u);
    const Layer& bed = out.layers[static_cast<std::size_t>(j.layer)];
    const auto [lo, hi] = range_along(out.bed_normal, j.vertices);
    EXPECT_GE(lo, bed.bottom - 1e-9);
    EXPECT_LE(hi, bed.top + 1e-9);
    EXPECT_TRUE(kBox.grown(1e-9).contains(j.centre));
    for (const V3& p : j.vertices) {
      EXPECT_TRUE(kBox.grown(1e-9).contains(p));
      EXPECT_NEAR(j.normal.dot(p) - j.offset(), 0, 1e-9);  // planar, through its centre
    }
    EXPECT_GT(vector_area(j.vertices).dot(j.normal), 0);  // counter-clockwise about the normal
  }
}

TEST(Layering3d, VerticalJointsInHorizontalBedsSpanTheBedExactly) {
  // A vertical plane cuts the prism bed x box in a rectangle from the bed's
  // bottom to its top: each joint's z range is the bed's.
  LayeringSpec3 spec;
  spec.thickness = lognormal(0.8, 0.3, 0.3);
  spec.sets = {{"V", 90, 70, 2.0, 0.2}};
  const auto out = generate_layering3d(spec, kBox, 8);
  ASSERT_GT(out.joints.size(), 100u);
  for (const Fracture3& j : out.joints) {
    const Layer& bed = out.layers[static_cast<std::size_t>(j.layer)];
    const auto [lo, hi] = range_along(V3(0, 0, 1), j.vertices);
    EXPECT_NEAR(lo, bed.bottom, 1e-9);
    EXPECT_NEAR(hi, bed.top, 1e-9);
  }
}

TEST(Layering3d, RealisedFsiMatchesTheTarget) {
  // Spacings are median * (1 + r X) with X uniform on [-1, 1), whose median
  // is the median, so each bed's realised FSI = drawn thickness / median of
  // its spacings estimates the target. With ~100 spacings a bed the sample
  // median's standard error is about r / sqrt(n) = 3 % of the median per bed
  // and well under 1 % over the ~60 beds. The tolerance on the mean over beds
  // is the asked 15 %, which also covers a systematic error in the scheme
  // (a spacing measured along the wrong direction would be off by the cosine
  // of the joints' angle, >= 20 % here); the tighter 3 % checks the estimate.
  LayeringSpec3 spec;
  spec.dip_deg = 15;
  spec.dip_direction_deg = 300;
  spec.thickness = lognormal(0.6, 0.2, 0.25);
  spec.sets = {{"A", 75, 40, 1.2, 0.3}, {"B", 85, 160, 2.5, 0.1}};
  const Box3 b{V3(0, 0, 0), V3(40, 40, 36)};
  const auto out = generate_layering3d(spec, b, 21);
  ASSERT_GT(out.layers.size(), 40u);
  for (std::size_t k = 0; k < spec.sets.size(); ++k) {
    double sum = 0;
    std::size_t beds = 0;
    for (std::size_t i = 0; i < out.layers.size(); ++i) {
      const BedSetStats& s = out.per_set[k][i];
      // The lowest and highest beds of dipping beds are wedges in the box's
      // corners with a few joints each; they are left out of the mean.
      if (s.spacings.size() < 20) continue;
      EXPECT_NEAR(s.target_median, out.drawn_thickness[i] / spec.sets[k].fsi, 1e-12);
      EXPECT_NEAR(s.realised_fsi, out.drawn_thickness[i] / s.median_spacing(), 1e-12);
      sum += s.realised_fsi;
      ++beds;
    }
    EXPECT_GT(beds, out.layers.size() * 3 / 4);
    const double mean = sum / static_cast<double>(beds);
    EXPECT_NEAR(mean / spec.sets[k].fsi, 1, 0.15) << spec.sets[k].name;
    EXPECT_NEAR(mean / spec.sets[k].fsi, 1, 0.03) << spec.sets[k].name;
  }
  // Layer::target_fsi / realised_fsi describe the first set, as in 2D.
  EXPECT_EQ(out.layers[3].target_fsi, 1.2);
  EXPECT_EQ(out.layers[3].realised_fsi, out.per_set[0][3].realised_fsi);
}

TEST(Layering3d, SameSeedSameLayersAndEachSetHasItsOwnStream) {
  const LayeringSpec3 spec = dipping_beds();
  const auto a = generate_layering3d(spec, kBox, 77);
  const auto b = generate_layering3d(spec, kBox, 77);
  const auto c = generate_layering3d(spec, kBox, 78);
  auto same_joints = [](const std::vector<Fracture3>& x, const std::vector<Fracture3>& y) {
    if (x.size() != y.size()) return false;
    for (std::size_t i = 0; i < x.size(); ++i)
      if (x[i].vertices != y[i].vertices || x[i].layer != y[i].layer || x[i].set != y[i].set) return false;
    return true;
  };
  EXPECT_EQ(a.drawn_thickness, b.drawn_thickness);
  EXPECT_TRUE(same_joints(a.joints, b.joints));
  EXPECT_NE(a.drawn_thickness, c.drawn_thickness);
  // Without set J2 the beds and the joints of J1 are the same.
  LayeringSpec3 one = spec;
  one.sets.pop_back();
  const auto d = generate_layering3d(one, kBox, 77);
  EXPECT_EQ(a.drawn_thickness, d.drawn_thickness);
  std::vector<Fracture3> j1;
  for (const Fracture3& j : a.joints)
    if (j.set == 0) j1.push_back(j);
  EXPECT_TRUE(same_joints(j1, d.joints));
}

TEST(Layering3d, AddLayeringAppendsSetsAndShiftsIndices) {
  FractureModel m;
  m.domain = kBox;
  m.sets.push_back({"earlier", "dfn"});
  const LayeringSpec3 spec = dipping_beds();
  const auto out = generate_layering3d(spec, kBox, 3);
  add_layering(m, spec, out);
  ASSERT_EQ(m.sets.size(), 4u);
  EXPECT_EQ(m.sets[1].name, "J1");
  EXPECT_EQ(m.sets[1].origin, "layered");
  EXPECT_EQ(m.sets[3].name, "bedding");
  EXPECT_EQ(m.sets[3].origin, "bedding");
  EXPECT_EQ(m.fractures.size(), out.bed_boundaries.size() + out.joints.size());
  for (const Fracture3& f : m.fractures) EXPECT_EQ(f.kind == LineKind::Bedding, f.set == 3);
  EXPECT_EQ(m.layers.size(), out.layers.size());
  EXPECT_EQ(m.bed_normal, out.bed_normal);
}

TEST(Layering3d, BadSpecificationsAreInputErrors) {
  auto message = [](const LayeringSpec3& s) -> std::string {
    try {
      generate_layering3d(s, kBox, 1);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  LayeringSpec3 s = dipping_beds();
  s.sets[1] = {"flat", 22, 130, 1, 0};  // 2 degrees from the bedding (20/135)
  EXPECT_NE(message(s).find("Layered joint set 'flat' must differ from the bedding"), std::string::npos);
  s = dipping_beds();
  s.sets[0].fsi = 0;
  EXPECT_NE(message(s).find("Layered joint set 'J1' has FSI 0"), std::string::npos);
  s = dipping_beds();
  s.sets[0].randomness = 1;
  EXPECT_NE(message(s).find("spacing randomness 1"), std::string::npos);
  s = dipping_beds();
  s.thickness = ThicknessSpec{};
  s.thickness.value = 1e-6;  // ~2e7 beds
  EXPECT_NE(message(s).find("more than the limit"), std::string::npos);
  s = dipping_beds();
  s.thickness = lognormal(1, 0.1, 5);  // a minimum 40 standard deviations out
  EXPECT_NE(message(s).find("minimum bed thickness"), std::string::npos);
}

}  // namespace dda::dl
