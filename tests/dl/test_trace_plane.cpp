// Trace plane: sections of a 3D fracture model as 2D line models, against
// analytic intersections.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <optional>
#include <string>

#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"
#include "dda/dl/dfn3d.hpp"
#include "dda/dl/fractures3d.hpp"
#include "dda/dl/trace_plane.hpp"

namespace dda::dl {

namespace {

using V3 = Eigen::Vector3d;

const Box3 kBox{V3(0, 0, 0), V3(10, 20, 5)};

Fracture3 disc(const V3& c, const V3& n, double r, int set = 0) {
  Fracture3 f;
  f.shape = FractureShape::Disc;
  f.centre = c;
  f.normal = n;
  f.radius = r;
  f.set = set;
  return f;
}

FractureModel model_with(std::vector<Fracture3> fractures) {
  FractureModel m;
  m.domain = kBox;
  m.fractures = std::move(fractures);
  m.sets = {{"A", "dfn"}, {"B", "dfn"}};
  return m;
}

// The section y = 7 seen from the south: u = x, v = z (see trace_plane.hpp).
TraceFrame section_y7() { return trace_frame(V3(0, 7, 0), 90, 180); }

void expect_near(const Vec2& a, const Vec2& b, double tol = 1e-12) {
  EXPECT_NEAR((a - b).norm(), 0, tol) << "(" << a.x() << ", " << a.y() << ") vs (" << b.x() << ", " << b.y() << ")";
}

}  // namespace

TEST(TracePlane, FrameAxes) {
  // Vertical, dip direction 180: strike east, u = x; v = z.
  const TraceFrame s = section_y7();
  EXPECT_NEAR((s.u - V3(1, 0, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR((s.v - V3(0, 0, 1)).norm(), 0, 1e-15);
  // Horizontal: map view, u = east, v = north.
  const TraceFrame h = trace_frame(V3(1, 2, 3), 0, 0);
  EXPECT_EQ(h.u, V3(1, 0, 0));
  EXPECT_EQ(h.v, V3(0, 1, 0));
  // Dipping 40 towards 120: u along the strike 030 (dip direction - 90),
  // horizontal; v up the dip line, v . z = sin 40; right-handed.
  const TraceFrame d = trace_frame(V3(1, 2, 3), 40, 120);
  EXPECT_NEAR((d.u - V3(std::sin(deg2rad(30)), std::cos(deg2rad(30)), 0)).norm(), 0, 1e-15);
  EXPECT_NEAR(d.v.z(), std::sin(deg2rad(40)), 1e-15);
  EXPECT_NEAR((d.u.cross(d.v) - d.n).norm(), 0, 1e-15);
  // A normal pointing down is the same plane, and gives the same frame.
  const TraceFrame e = trace_frame(V3(1, 2, 3), -2 * normal_from_dip(40, 120));
  EXPECT_NEAR((e.u - d.u).norm() + (e.v - d.v).norm(), 0, 1e-15);
  // Round trip.
  const V3 p(3, -1, 7);
  const Vec2 q = d.to_plane(p);
  EXPECT_NEAR((d.to_space(q) - (p - d.n.dot(p - d.origin) * d.n)).norm(), 0, 1e-14);
  EXPECT_THROW(trace_frame(V3(0, 0, 0), V3::Zero()), InputError);
  EXPECT_THROW(trace_frame(V3(0, 0, 0), 91, 0), InputError);
}

TEST(TracePlane, VerticalSectionThroughTheBox) {
  // The section y = 7 of the 10 x 20 x 5 box is the rectangle u in [0, 10],
  // v in [0, 5], counter-clockwise.
  const LineModel lm = trace_section(model_with({}), section_y7());
  ASSERT_EQ(lm.domain.size(), 4u);
  EXPECT_NEAR(signed_area(lm.domain), 50, 1e-12);
  for (const Vec2& p : lm.domain) {
    EXPECT_TRUE(std::abs(p.x()) < 1e-12 || std::abs(p.x() - 10) < 1e-12);
    EXPECT_TRUE(std::abs(p.y()) < 1e-12 || std::abs(p.y() - 5) < 1e-12);
  }
  ASSERT_EQ(lm.sets.size(), 2u);
  EXPECT_EQ(lm.sets[1].name, "B");
  // A plane missing the box is an error.
  EXPECT_THROW(trace_section(model_with({}), trace_frame(V3(0, 30, 0), 90, 180)), InputError);
}

TEST(TracePlane, DiscChordsMatchTheAnalyticIntersection) {
  // A horizontal disc of radius r = 2 centred h = 1.2 north of the section
  // y = 7: its chord is 2 sqrt(r^2 - h^2) = 3.2 long, at the centre's height,
  // centred below the centre: u in [4 - 1.6, 4 + 1.6], v = 2.5.
  // A tilted disc: the section cuts its plane along a line at distance
  // h / sin(theta) from the centre (h its distance to the section, theta the
  // angle between the two planes), so its chord is 2 sqrt(r^2 - h^2 / sin^2).
  const V3 nt = normal_from_dip(50, 20);
  const V3 ct(6, 7.4, 2.0);
  const double rt = 1.5;
  const FractureModel m = model_with({disc(V3(4, 8.2, 2.5), V3(0, 0, 1), 2, 1), disc(ct, nt, rt),
                                      disc(V3(4, 9.5, 2.5), V3(0, 0, 1), 2),           // h = 2.5 > r: no trace
                                      disc(V3(4, 7.5, 2.5), V3(0, 1, 0), 2)});         // parallel: no trace
  const TraceFrame f = section_y7();
  const LineModel lm = trace_section(m, f);
  ASSERT_EQ(lm.lines.size(), 2u);
  const JointLine& a = lm.lines[0];
  EXPECT_EQ(a.set, 1);
  EXPECT_EQ(a.kind, LineKind::Joint);
  const bool forward = a.a.x() < a.b.x();
  expect_near(forward ? a.a : a.b, Vec2(2.4, 2.5));
  expect_near(forward ? a.b : a.a, Vec2(5.6, 2.5));

  const JointLine& b = lm.lines[1];
  const double h = 0.4;  // the tilted disc's centre is at y = 7.4
  const double sin_theta = nt.cross(f.n).norm();
  EXPECT_NEAR((b.b - b.a).norm(), 2 * std::sqrt(rt * rt - h * h / (sin_theta * sin_theta)), 1e-12);
  // Both ends in both planes and on the disc's rim.
  for (const Vec2& q : {b.a, b.b}) {
    const V3 p = f.to_space(q);
    EXPECT_NEAR(nt.dot(p - ct), 0, 1e-12);
    EXPECT_NEAR((p - ct).norm(), rt, 1e-12);
  }
}

TEST(TracePlane, DiscChordIsClippedToTheDomain) {
  // Horizontal disc centred on the section at the box's west face: half its
  // diameter is inside, u in [0, 2], v = 1.
  const LineModel lm = trace_section(model_with({disc(V3(0, 7, 1), V3(0, 0, 1), 2)}), section_y7());
  ASSERT_EQ(lm.lines.size(), 1u);
  EXPECT_NEAR((lm.lines[0].b - lm.lines[0].a).norm(), 2, 1e-12);
  EXPECT_NEAR(std::min(lm.lines[0].a.x(), lm.lines[0].b.x()), 0, 1e-12);
}

TEST(TracePlane, PlaneFractureCrossesTheWholeDomain) {
  // Section x = 5 (dip 90 towards 090, seen from the east): u = north (y),
  // v = z. A plane dipping 30 to the south through (5, 10, 2.5) rises to the
  // north with slope tan 30: v = 2.5 + tan 30 (u - 10), cut at v = 0 and v = 5,
  // so u = 10 -+ 2.5 / tan 30.
  const TraceFrame f = trace_frame(V3(5, 0, 0), 90, 90);
  EXPECT_NEAR((f.u - V3(0, 1, 0)).norm(), 0, 1e-15);
  Fracture3 p = make_plane({30, 180, V3(5, 10, 2.5), std::nullopt}, 1);
  const LineModel lm = trace_section(model_with({p}), f);
  ASSERT_EQ(lm.lines.size(), 1u);
  const double du = 2.5 / std::tan(deg2rad(30));
  const JointLine& l = lm.lines[0];
  const bool forward = l.a.x() < l.b.x();
  expect_near(forward ? l.a : l.b, Vec2(10 - du, 0));
  expect_near(forward ? l.b : l.a, Vec2(10 + du, 5));
}

TEST(TracePlane, PolygonFractures) {
  // A horizontal square x in [2, 6], y in [5, 9] at z = 3 crosses the section
  // y = 7 along u in [2, 6], v = 3; a square crossing the box's east face is
  // clipped at u = 10; a square in a plane parallel to the section leaves
  // nothing; a triangle touching the section at one vertex leaves nothing.
  auto poly = [](std::vector<V3> v) { return polygon_fracture(std::move(v), 0, "test polygon"); };
  const FractureModel m = model_with({
      poly({V3(2, 5, 3), V3(6, 5, 3), V3(6, 9, 3), V3(2, 9, 3)}),
      poly({V3(8, 5, 1), V3(12, 5, 1), V3(12, 9, 1), V3(8, 9, 1)}),
      poly({V3(1, 7.5, 1), V3(3, 7.5, 1), V3(3, 7.5, 3), V3(1, 7.5, 3)}),
      poly({V3(1, 7, 1), V3(3, 8, 1), V3(1, 9, 1)}),
  });
  const LineModel lm = trace_section(m, section_y7());
  ASSERT_EQ(lm.lines.size(), 2u);
  auto sorted = [](const JointLine& l) { return l.a.x() < l.b.x() ? std::pair{l.a, l.b} : std::pair{l.b, l.a}; };
  expect_near(sorted(lm.lines[0]).first, Vec2(2, 3));
  expect_near(sorted(lm.lines[0]).second, Vec2(6, 3));
  expect_near(sorted(lm.lines[1]).first, Vec2(8, 1));
  expect_near(sorted(lm.lines[1]).second, Vec2(10, 1));
}

TEST(TracePlane, ExcavationsAreCutByThePlane) {
  // A tunnel prism along y (x in [3, 6], z in [1, 3]) shows as that
  // rectangle; a shaft that stops short of the section (y <= 5) shows nothing.
  FractureModel m = model_with({});
  m.excavations.push_back({"tunnel", {{{V3(-1, 0, 0), -3}, {V3(1, 0, 0), 6}, {V3(0, 0, -1), -1}, {V3(0, 0, 1), 3}}}});
  m.excavations.push_back({"stub", {{{V3(0, 1, 0), 5}, {V3(1, 0, 0), 2}}}});
  const LineModel lm = trace_section(m, section_y7());
  ASSERT_EQ(lm.excavations.size(), 1u);
  EXPECT_NEAR(signed_area(lm.excavations[0]), 6, 1e-12);  // counter-clockwise, 3 x 2
  for (const Vec2& p : lm.excavations[0]) {
    EXPECT_TRUE(std::abs(p.x() - 3) < 1e-12 || std::abs(p.x() - 6) < 1e-12);
    EXPECT_TRUE(std::abs(p.y() - 1) < 1e-12 || std::abs(p.y() - 3) < 1e-12);
  }
}

TEST(TracePlane, BedsStayBeddingWithTheirLayers) {
  // Horizontal beds z in [0, 1.5], [1.5, 4], [4, 5] and their two contacts.
  // In a vertical section the beds are horizontal (apparent dip 0) and their
  // coordinates are z - origin.z.
  FractureModel m = model_with({});
  m.layers = {{0, 1.5, 1, 0.9}, {1.5, 4, 1, 1.1}, {4, 5, 1, 1}};
  for (int i = 0; i < 2; ++i) {
    Fracture3 b = make_plane({0, 0, V3(5, 10, m.layers[static_cast<std::size_t>(i)].top), std::nullopt}, 1);
    b.kind = LineKind::Bedding;
    b.layer = i;
    m.fractures.push_back(b);
  }
  const LineModel lm = trace_section(m, trace_frame(V3(0, 7, -1), 90, 180));
  ASSERT_EQ(lm.layers.size(), 3u);
  EXPECT_NEAR(lm.bedding_dip_deg, 0, 1e-12);
  EXPECT_NEAR(lm.layers[1].bottom, 2.5, 1e-12);
  EXPECT_NEAR(lm.layers[1].top, 5, 1e-12);
  EXPECT_EQ(lm.layers[1].realised_fsi, 1.1);
  ASSERT_EQ(lm.lines.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(lm.lines[static_cast<std::size_t>(i)].kind, LineKind::Bedding);
    EXPECT_EQ(lm.lines[static_cast<std::size_t>(i)].layer, i);
    EXPECT_NEAR(lm.lines[static_cast<std::size_t>(i)].a.y(), lm.layers[static_cast<std::size_t>(i)].top, 1e-12);
  }
}

TEST(TracePlane, BedsTurnedOverInTheSectionAreRenumbered) {
  // Vertical beds with normal +x (x in [0, 4], [4, 10]) in a section dipping
  // 60 towards 090: u = (0, 1, 0), v = (-cos 60, 0, sin 60), so going up v
  // goes west, down the bed order: x = origin.x - v cos 60, i.e. v = 2 (5 - x)
  // with origin x = 5. The section's beds, bottom to top in v: the eastern
  // one (v in [-10, 2]) then the western one (v in [2, 10]), apparent dip 0.
  FractureModel m = model_with({});
  m.bed_normal = normal_from_dip(90, 90);
  m.layers = {{0, 4}, {4, 10}};
  Fracture3 b = make_plane({90, 90, V3(4, 10, 2), std::nullopt}, 1);
  b.kind = LineKind::Bedding;
  b.layer = 0;  // the contact on top of bed 0
  m.fractures.push_back(b);
  const TraceFrame f = trace_frame(V3(5, 0, 0), 60, 90);
  EXPECT_NEAR((f.v - V3(-0.5, 0, std::sqrt(3.0) / 2)).norm(), 0, 1e-15);
  const LineModel lm = trace_section(m, f);
  ASSERT_EQ(lm.layers.size(), 2u);
  EXPECT_NEAR(lm.bedding_dip_deg, 0, 1e-9);
  EXPECT_NEAR(lm.layers[0].bottom, -10, 1e-9);
  EXPECT_NEAR(lm.layers[0].top, 2, 1e-9);
  EXPECT_NEAR(lm.layers[1].bottom, 2, 1e-9);
  EXPECT_NEAR(lm.layers[1].top, 10, 1e-9);
  ASSERT_EQ(lm.lines.size(), 1u);
  EXPECT_EQ(lm.lines[0].layer, 1);  // old bed 0 is now the upper one
  EXPECT_NEAR(lm.lines[0].a.y(), 2, 1e-9);
}

}  // namespace dda::dl
