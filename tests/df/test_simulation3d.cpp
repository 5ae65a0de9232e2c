// The 3D DDA step (df/3d/simulation3d.hpp) on V1 in 3D: a 1 m cube on a fixed
// plane dipping alpha = 20 deg towards dip direction 90 (east).
//
// Geometry: the base [-5, 5]^2 x [-1, 0] and the cube [-0.5, 0.5]^2 x [0, 1]
// are rotated together by +alpha about the y axis, so the contact plane goes
// through the origin with upward normal n = (sin a, 0, cos a), the down-dip
// direction is (cos a, 0, -sin a) (downhill towards +x, east) and the strike
// (cross-slope) direction is y.
//
// Expected: docs/validation.md V1, s(t) = 1/2 g (sin a - cos a tan phi)
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
#include <functional>
#include <numbers>

#include "dda/common/error.hpp"
#include "dda/df/3d/simulation3d.hpp"
#include "df_test_models3d.hpp"

namespace dda::df3 {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

using testing::box;

struct SlideResult {
  double down_dip = 0, cross = 0, penetration = 0;  // from t = 0 (the settled state with initial_equilibrium)
  int unconverged = 0, max_iterations = 0;
  int contacts = 0, vertex_face = 0, sliding = 0, locked = 0;  // at the end
  df::StartUp start_up;
};

// The cube on the plane; with initial_equilibrium it is relaxed statically
// under gravity before t = 0 (Control3::initial_equilibrium).
Model3 slide_model(double alpha_deg, const df::JointProperties& joint, double dipdir_deg,
                   bool initial_equilibrium = false) {
  const Matrix3d r = testing::plane_rotation(alpha_deg, dipdir_deg);
  Model3 m;
  m.blocks = {box({-5, -5, -1}, {5, 5, 0}, r), box({-0.5, -0.5, 0}, {0.5, 0.5, 1}, r)};
  m.fixed = {true, false};
  m.materials = {{2600, 1e10, 0.25}};
  m.default_joint = joint;
  m.normal_penalty = 1e9;
  m.shear_penalty = 1e9;
  m.gravity = {0, 0, -9.81};
  m.contact_reach = 0.01;  // > 2.5 x the largest step displacement (1.7 m/s * 1 ms)
  m.control.initial_equilibrium = initial_equilibrium;
  return m;
}

SlideResult slide(double alpha_deg, const df::JointProperties& joint, double dt, double t_end,
                  double dipdir_deg = 90, bool initial_equilibrium = false) {
  const Matrix3d r = testing::plane_rotation(alpha_deg, dipdir_deg);
  Simulation3 sim(slide_model(alpha_deg, joint, dipdir_deg, initial_equilibrium));
  sim.start();  // the relaxation, if asked for: the slide is measured from where it leaves the cube
  const Vec3 c0 = sim.blocks()[1].centroid;
  const Vec3 dip = r * Vec3(1, 0, 0), strike = r * Vec3(0, 1, 0), normal = r * Vec3(0, 0, 1);
  SlideResult out;
  const int steps = static_cast<int>(std::lround(t_end / dt));
  for (int s = 0; s < steps; ++s) {
    const StepRecord3 info = sim.step(dt);
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
  out.start_up = sim.start_up();
  return out;
}

SlideResult slide(double alpha_deg, double phi_deg, double dt, double t_end, double dipdir_deg = 90,
                  bool initial_equilibrium = false) {
  df::JointProperties joint;
  joint.friction_deg = phi_deg;
  return slide(alpha_deg, joint, dt, t_end, dipdir_deg, initial_equilibrium);
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
    SCOPED_TRACE(::testing::Message() << "dt " << k.dt << " dip direction " << k.dipdir);
    const SlideResult r = slide(20, 10, k.dt, t, k.dipdir);
    print("V1-3D phi=10", r, expected);
    std::printf("  relative error %.2e\n", (r.down_dip - expected) / expected);
    EXPECT_NEAR(r.down_dip, expected, 0.01 * expected);
    EXPECT_LT(std::abs(r.cross), 1e-6);
    EXPECT_LT(r.penetration, 1e-3);
    EXPECT_EQ(r.vertex_face, 4);
    EXPECT_EQ(r.sliding, 4);
    EXPECT_EQ(r.unconverged, 0);
  }
}

// phi = 30 >= alpha = 20: the cube stays (docs/validation.md V1: a = 0); what moves is
// the elastic shear-spring stretch, W sin a / (4 ps) = 2.2e-6 m.
TEST(Simulation3, CubeHoldsWhenFrictionExceedsDip) {
  for (const double dipdir : {90.0, 210.0}) {
    SCOPED_TRACE(::testing::Message() << "dip direction " << dipdir);
    const SlideResult r = slide(20, 30, 1e-3, 1.0, dipdir);
    print("V1-3D phi=30", r, 0.0);
    EXPECT_LT(std::abs(r.down_dip), 1e-4);
    EXPECT_LT(std::abs(r.cross), 1e-6);
    EXPECT_LT(r.penetration, 1e-3);
    EXPECT_EQ(r.locked, 4);
    EXPECT_EQ(r.unconverged, 0);
  }
}

// Friction 0.1 deg above the dip: factor of safety tan 20.1 / tan 20 =
// 1.0054, so a rigid block at rest stays (docs/validation.md V1: a = 0).
// Relaxed first (the start-up), the cube is handed over in frictional
// equilibrium with its uphill corners at their strength, and it must not
// move: their friction turns only as far as their shear springs, stretched
// by strength / ps = 2.2e-6 m, are turned by the step's slip, not along
// the nanometre creep of the cube's elastic spreading (it walked 7.6 mm in
// 2 s when friction followed every slip; docs/solver3d.md, "Friction at its
// limit"). With gravity switched on at t = 0 the cube bounces on its
// contact springs: the dynamic overshoot of a suddenly applied load slides
// it 0.14 mm during the first bounce, after which it is held (the
// comparison with 2D is in docs/solver2d.md). So: relaxed, < 1e-8 m in
// 2 s; sudden, nothing more after the first second (< 1e-9 m between 1 and
// 2 s) and every contact locked at the end.
TEST(Simulation3, CubeHoldsAtItsFrictionLimit) {
  for (const double dipdir : {90.0, 210.0}) {
    SCOPED_TRACE(::testing::Message() << "dip direction " << dipdir);
    const SlideResult relaxed = slide(20, 20.1, 1e-3, 2.0, dipdir, true);
    print("V1-3D phi=20.1 settled", relaxed, 0.0);
    EXPECT_TRUE(relaxed.start_up.frictional_equilibrium);
    EXPECT_LT(std::abs(relaxed.down_dip), 1e-8);
    EXPECT_LT(std::abs(relaxed.cross), 1e-8);
    EXPECT_EQ(relaxed.locked, 4);
    EXPECT_EQ(relaxed.unconverged, 0);
    const SlideResult first = slide(20, 20.1, 1e-3, 1.0, dipdir), both = slide(20, 20.1, 1e-3, 2.0, dipdir);
    print("V1-3D phi=20.1 sudden", both, 0.0);
    std::printf("  sudden: %.3e m in the first second, %.3e m in the second\n", first.down_dip,
                both.down_dip - first.down_dip);
    EXPECT_LT(first.down_dip, 1e-3);  // the bounce's slide, measured 1.4e-4 m
    EXPECT_LT(std::abs(both.down_dip - first.down_dip), 1e-9);
    EXPECT_EQ(both.locked, 4);
  }
}

// Friction well above the dip: the relaxation hands the cube over at rest
// on loaded contacts, in frictional equilibrium. With gravity applied
// suddenly the cube first moves by its shear springs' stretch (7e-6 m,
// CubeHoldsWhenFrictionExceedsDip); settled, that stretch happened before
// t = 0 and the cube does not move.
TEST(Simulation3, SettledCubeStartsAtRest) {
  for (const double dipdir : {90.0, 210.0}) {
    SCOPED_TRACE(::testing::Message() << "dip direction " << dipdir);
    const SlideResult r = slide(20, 30, 1e-3, 1.0, dipdir, true);
    print("V1-3D phi=30 settled", r, 0.0);
    std::printf("  moved %.2e m down the dip from t = 0\n", r.down_dip);
    EXPECT_GT(r.start_up.stuck_iterations, 0);
    EXPECT_GT(r.start_up.friction_iterations, 0);
    EXPECT_TRUE(r.start_up.frictional_equilibrium);
    EXPECT_LT(std::abs(r.down_dip), 1e-8);
    EXPECT_LT(std::abs(r.cross), 1e-8);
    EXPECT_EQ(r.locked, 4);
  }
}

// Friction below the dip: the relaxation finds no frictional equilibrium
// (the cube creeps a constant 0.5 a dts^2 a solve, and phase 2 stops), and
// the cube, released at rest from the settled state, follows V1 within 1 %.
TEST(Simulation3, SettledCubeStillSlidesV1) {
  const double alpha = 20 * kDeg, phi = 10 * kDeg, g = 9.81, t = 1.0;
  const double expected = 0.5 * g * (std::sin(alpha) - std::cos(alpha) * std::tan(phi)) * t * t;
  for (const double dipdir : {90.0, 210.0}) {
    SCOPED_TRACE(::testing::Message() << "dip direction " << dipdir);
    const SlideResult r = slide(20, 10, 1e-3, t, dipdir, true);
    print("V1-3D phi=10 settled", r, expected);
    std::printf("  start-up: %d solves stuck, %d with friction, frictional equilibrium %d; relative error %.2e\n",
                r.start_up.stuck_iterations, r.start_up.friction_iterations, r.start_up.frictional_equilibrium,
                (r.down_dip - expected) / expected);
    EXPECT_GT(r.start_up.stuck_iterations, 0);
    EXPECT_GT(r.start_up.friction_iterations, 0);  // it ran, and crept without end (the flag below)
    EXPECT_FALSE(r.start_up.frictional_equilibrium);
    EXPECT_NEAR(r.down_dip, expected, 0.01 * expected);
    EXPECT_LT(std::abs(r.cross), 1e-6);
    EXPECT_EQ(r.sliding, 4);
    EXPECT_EQ(r.unconverged, 0);
  }
}

// A run restored from a checkpoint has started: it does not relax again,
// and it goes on exactly as the run it was taken from.
TEST(Simulation3, ResumedRunDoesNotRelaxAgain) {
  df::JointProperties joint;
  joint.friction_deg = 20.1;
  const Model3 m = slide_model(20, joint, 90, true);
  Simulation3 a(m);
  for (int s = 0; s < 20; ++s) a.step(1e-3);
  ASSERT_GT(a.settle_iterations(), 0);
  const SimulationState3 saved = a.state();
  EXPECT_TRUE(saved.started);
  for (int s = 0; s < 20; ++s) a.step(1e-3);

  Simulation3 b(m);
  b.restore(saved);
  b.start();
  EXPECT_EQ(b.settle_iterations(), 0);
  EXPECT_EQ(b.start_up().stuck_iterations, 0);
  for (int s = 0; s < 20; ++s) b.step(1e-3);
  EXPECT_EQ(b.settle_iterations(), 0);
  EXPECT_EQ(b.time(), a.time());
  EXPECT_EQ(b.blocks()[1].vertices, a.blocks()[1].vertices);
  EXPECT_EQ(b.log().size(), a.log().size());
}

// The friction laws of the 2D solver through the same interface
// (friction_laws.hpp). Expected: the rigid block on the plane obeys
//   s'' = g (sin a - cos a mu(s', s)),  s(0) = s'(0) = 0,
// integrated here by RK4 with 1e-5 s steps (converged to 1e-9 m).
double slide_ode(double alpha_deg, double t_end, const std::function<double(double v, double s)>& mu) {
  const double g = 9.81, a = alpha_deg * kDeg, h = 1e-5;
  auto acc = [&](double v, double s) { return g * (std::sin(a) - std::cos(a) * mu(v, s)); };
  double s = 0, v = 0;
  for (int k = 0; k < static_cast<int>(std::lround(t_end / h)); ++k) {
    const double k1v = acc(v, s), k1s = v;
    const double k2v = acc(v + 0.5 * h * k1v, s + 0.5 * h * k1s), k2s = v + 0.5 * h * k1v;
    const double k3v = acc(v + 0.5 * h * k2v, s + 0.5 * h * k2s), k3s = v + 0.5 * h * k2v;
    const double k4v = acc(v + h * k3v, s + h * k3s), k4s = v + h * k3v;
    v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    s += h / 6 * (k1s + 2 * k2s + 2 * k3s + k4s);
  }
  return s;
}

// Log-linear velocity weakening, mu = 0.2 - 0.02 ln(max(V, 1 mm/s) / 0.1 m/s):
// 0.292 at the floor speed, falling as the block speeds up. The strength
// is iterated to the slip speed of the step (FrictionInput.slip_velocity).
// Why not closer to tan 20 = 0.364 at rest: near equilibrium s(1 s) hangs
// on the first milliseconds, where the contacts close with the penalty
// springs' bounce, which the rigid-block equation does not have.
TEST(Simulation3, VelocityWeakeningBlockFollowsItsEquationOfMotion) {
  df::JointProperties joint;
  joint.friction_law = "log_linear";
  joint.friction_parameters = {{"mu_ref", 0.2}, {"s", -0.02}, {"v_ref", 0.1}, {"v_min", 1e-3}};
  const double expected = slide_ode(20, 1.0, [](double v, double) {
    return 0.2 - 0.02 * std::log(std::max(v, 1e-3) / 0.1);
  });
  const SlideResult r = slide(20, joint, 1e-3, 1.0);
  print("V1-3D log-linear", r, expected);
  EXPECT_NEAR(r.down_dip, expected, 0.01 * expected);
  EXPECT_EQ(r.sliding, 4);
  EXPECT_EQ(r.unconverged, 0);
  // Constant friction at the reference value would give a different answer:
  // the law is in effect (not Coulomb at mu_ref).
  const double coulomb = slide_ode(20, 1.0, [](double, double) { return 0.2; });
  EXPECT_GT(std::abs(expected - coulomb), 0.05 * expected);
}

// Linear slip weakening, mu = 0.25 - 0.15 min(D / 0.05 m, 1): the memory
// (FrictionState::slip) carried by each contact and advanced once a step.
TEST(Simulation3, SlipWeakeningBlockFollowsItsEquationOfMotion) {
  df::JointProperties joint;
  joint.friction_law = "slip_weakening";
  joint.friction_parameters = {{"mu_s", 0.25}, {"mu_d", 0.1}, {"dc", 0.05}};
  const double expected = slide_ode(20, 1.0, [](double, double s) { return 0.25 - 0.15 * std::min(s / 0.05, 1.0); });
  const SlideResult r = slide(20, joint, 1e-3, 1.0);
  print("V1-3D slip weakening", r, expected);
  EXPECT_NEAR(r.down_dip, expected, 0.01 * expected);
  EXPECT_EQ(r.unconverged, 0);
}

}  // namespace
}  // namespace dda::df3

namespace dda::df3 {
namespace {

// Contact identity (detect_contacts3): a 1 m cube exactly on an equal fixed
// cube touches it at four points, each a corner on a corner. The search
// finds each point from both blocks (a vertex of either on a face of the
// other, and on either of the faces that meet there); that must stay four
// contacts, each keeping its state when the upper cube moves a little
// sideways and its corners overhang by less than the merge distance.
TEST(Simulation3, CornerOnCornerIsOneContactThatKeepsItsState) {
  const Matrix3d id = Matrix3d::Identity();
  std::vector<Polyhedron> blocks{box({0, 0, -1}, {1, 1, 0}, id), box({0, 0, 0}, {1, 1, 1}, id)};
  for (auto& b : blocks) refresh_geometry(b);
  const double reach = 0.01, merge = 1e-3;
  std::vector<Contact3> first = detect_contacts3(blocks, {}, reach, merge);
  ASSERT_EQ(first.size(), 4u);
  for (Contact3& c : first) {
    EXPECT_NEAR(std::abs(c.geo.normal.z()), 1.0, 1e-12);  // the contact plane z = 0, not a side face
    c.state = ContactState3::Locked;
    c.normal_force = 1000;
    c.point_now = c.geo.point_i;
  }
  // Shift the upper cube by 0.2 mm in x and y: its corners now overhang the
  // lower cube's faces on two sides, the lower cube's on the other two.
  for (auto& v : blocks[1].vertices) v += Vec3(2e-4, 2e-4, 0);
  blocks[1].centroid += Vec3(2e-4, 2e-4, 0);
  for (Contact3& c : first)
    if (c.i == 1) c.point_now += Vec3(2e-4, 2e-4, 0);
  const std::vector<Contact3> next = detect_contacts3(blocks, first, reach, merge);
  ASSERT_EQ(next.size(), 4u);
  for (const Contact3& c : next) {
    EXPECT_EQ(c.state, ContactState3::Locked);
    EXPECT_EQ(c.normal_force, 1000);
    EXPECT_NEAR(std::abs(c.geo.normal.z()), 1.0, 1e-12);
  }
}

}  // namespace
}  // namespace dda::df3
