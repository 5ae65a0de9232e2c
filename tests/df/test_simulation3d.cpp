// The 3D DDA step (df/simulation3d.hpp) on V1 in 3D: a 1 m cube on a fixed
// plane dipping alpha = 20 deg towards dip direction 90 (east).
//
// Geometry: the base [-5, 5]^2 x [-1, 0] and the cube [-0.5, 0.5]^2 x [0, 1]
// are rotated together by +alpha about the y axis, so the contact plane goes
// through the origin with upward normal n = (sin a, 0, cos a), the down-dip
// direction is (cos a, 0, -sin a) (downhill towards +x, east) and the strike
// (cross-slope) direction is y.
//
// Expected: shared/validation/CASES.md V1, s(t) = 1/2 g (sin a - cos a tan phi)
// t^2 if tan phi < tan a, else 0. For a = 20, phi = 10, t = 1 s, g = 9.81:
// a_slide = 9.81 (0.342020 - 0.939693 * 0.176327) = 1.729768 m/s^2,
// s = 0.864884 m (computed below from the formula; the literal is a check).
// Other dip directions: the whole model is turned about z by 90 - dipdir
// (x east, y north, dip direction clockwise from north).
//
// Penalty: the cube weighs W = rho g V = 2600 * 9.81 * 1 = 25.5 kN and rests
// on its 4 bottom vertices, so with pn = 1e9 N/m each carries
// W cos a / 4 = 6.0 kN at a static penetration of 6e-6 m (the dynamic
// overshoot at most doubles it), far below the 1e-3 m allowed; the contact
// frequency sqrt(4 pn / m) = 1240 rad/s (period 5 ms) is resolved by
// dt = 1 ms. ps = pn.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "dda/df/simulation3d.hpp"

namespace dda::df3 {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

// Axis-aligned box [lo, hi] turned by r about the origin; face loops
// counter-clockwise seen from outside (normals are recomputed by Simulation3).
Polyhedron box(const Vec3& lo, const Vec3& hi, const Matrix3d& r) {
  Polyhedron p;
  for (int i = 0; i < 8; ++i)
    p.vertices.push_back(r * Vec3(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z()));
  for (const auto& loop : std::vector<std::vector<int>>{
           {0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}) {
    PolyFace f;
    f.vertices = loop;
    p.faces.push_back(f);
  }
  return p;
}

struct SlideResult {
  double down_dip = 0, cross = 0, penetration = 0;
  int unconverged = 0, max_iterations = 0;
  int contacts = 0, vertex_face = 0, sliding = 0, locked = 0;  // at the end
};

SlideResult slide(double alpha_deg, double phi_deg, double dt, double t_end, double dipdir_deg = 90) {
  const double a = alpha_deg * kDeg, b = (90 - dipdir_deg) * kDeg;
  Matrix3d ry, rz;
  ry << std::cos(a), 0, std::sin(a), 0, 1, 0, -std::sin(a), 0, std::cos(a);  // +a about y: dip towards +x
  rz << std::cos(b), -std::sin(b), 0, std::sin(b), std::cos(b), 0, 0, 0, 1;   // +x to the dip direction
  const Matrix3d r = rz * ry;
  Model3 m;
  m.blocks = {box({-5, -5, -1}, {5, 5, 0}, r), box({-0.5, -0.5, 0}, {0.5, 0.5, 1}, r)};
  m.fixed = {true, false};
  m.material = {2600, 1e10, 0.25};
  m.friction_deg = phi_deg;
  m.normal_penalty = 1e9;
  m.shear_penalty = 1e9;
  m.gravity = {0, 0, -9.81};
  m.contact_reach = 0.01;  // > 2.5 x the largest step displacement (1.7 m/s * 1 ms)
  Simulation3 sim(m);
  const Vec3 c0 = sim.blocks()[1].centroid;
  const Vec3 dip = r * Vec3(1, 0, 0), strike = r * Vec3(0, 1, 0), normal = r * Vec3(0, 0, 1);
  SlideResult out;
  const int steps = static_cast<int>(std::lround(t_end / dt));
  for (int s = 0; s < steps; ++s) {
    const StepInfo3 info = sim.step(dt);
    if (!info.converged) ++out.unconverged;
    out.max_iterations = std::max(out.max_iterations, info.iterations);
    for (const auto& v : sim.blocks()[1].vertices) out.penetration = std::max(out.penetration, -normal.dot(v));
  }
  const Vec3 u = sim.blocks()[1].centroid - c0;
  out.down_dip = u.dot(dip);
  out.cross = u.dot(strike);
  for (const Contact3& c : sim.contacts()) {
    if (c.kind == ContactKind3::VertexFace) ++out.vertex_face;
    if (c.state == ContactState3::Sliding) ++out.sliding;
    if (c.state == ContactState3::Locked) ++out.locked;
  }
  out.contacts = static_cast<int>(sim.contacts().size());
  return out;
}

void print(const char* what, const SlideResult& r, double expected) {
  std::printf("%s: s = %.6f m (expected %.6f), cross %.2e m, max penetration %.2e m, contacts %d "
              "(vertex-face %d, sliding %d, locked %d), unconverged steps %d, max iterations %d\n",
              what, r.down_dip, expected, r.cross, r.penetration, r.contacts, r.vertex_face, r.sliding, r.locked,
              r.unconverged, r.max_iterations);
}

// phi = 10 < alpha = 20: s(1 s) within 1 % of V1, no drift across the slope,
// the four bottom vertices sliding on the base's top face.
TEST(Simulation3, CubeSlidesDownPlaneV1) {
  const double alpha = 20 * kDeg, phi = 10 * kDeg, g = 9.81, t = 1.0;
  const double expected = 0.5 * g * (std::sin(alpha) - std::cos(alpha) * std::tan(phi)) * t * t;
  EXPECT_NEAR(expected, 0.864884, 1e-6);  // the number in the header
  struct Case {
    double dt, dipdir;
  };
  for (const Case k : {Case{1e-3, 90}, Case{5e-3, 90}, Case{1e-3, 210}}) {
    SCOPED_TRACE(testing::Message() << "dt " << k.dt << " dip direction " << k.dipdir);
    const SlideResult r = slide(20, 10, k.dt, t, k.dipdir);
    print("V1-3D phi=10", r, expected);
    EXPECT_NEAR(r.down_dip, expected, 0.01 * expected);
    EXPECT_LT(std::abs(r.cross), 1e-6);
    EXPECT_LT(r.penetration, 1e-3);
    EXPECT_EQ(r.vertex_face, 4);
    EXPECT_EQ(r.sliding, 4);
    EXPECT_EQ(r.unconverged, 0);
  }
}

// phi = 30 >= alpha = 20: the cube stays (CASES.md V1: a = 0); what moves is
// the elastic shear-spring stretch, W sin a / (4 ps) = 2.2e-6 m.
TEST(Simulation3, CubeHoldsWhenFrictionExceedsDip) {
  for (const double dipdir : {90.0, 210.0}) {
    SCOPED_TRACE(testing::Message() << "dip direction " << dipdir);
    const SlideResult r = slide(20, 30, 1e-3, 1.0, dipdir);
    print("V1-3D phi=30", r, 0.0);
    EXPECT_LT(std::abs(r.down_dip), 1e-4);
    EXPECT_LT(std::abs(r.cross), 1e-6);
    EXPECT_LT(r.penetration, 1e-3);
    EXPECT_EQ(r.locked, 4);
    EXPECT_EQ(r.unconverged, 0);
  }
}

}  // namespace
}  // namespace dda::df3
