// The 3D DDA step (df/3d/simulation3d.hpp) on validation case V4
// (docs/validation.md): the tetrahedral wedge on planes
// A 51.4/065.8 and B 51.4/295.2.
//
// Geometry (as tests/dc/test_cut3d.cpp, SeedWedgeHasTheExpectedVolumeAndNormals,
// but a smaller box): the box x in [-8, 8], y in [-2, 10], z in [0, 10] is
// cut by A and B through T = (0, 0, 10) on the ground z = 10; the box face
// y = 10 is the excavated slope face. The block above both planes is the
// tetrahedral wedge T, D (daylight of the line of intersection on y = 10),
// EA, EB (ground, face and A or B), V = 80.2 m^3. It is free; the blocks it
// rests on are fixed. Two layouts of the fixed blocks (see Layout below):
// the blocks of the same cut, whose faces on A and B are exactly the wedge's
// faces (every wedge corner on a corner of the face it rests on), and larger
// half-space blocks whose faces reach past the wedge's. Both must give V4;
// the first is the hard one for contact identity (see the tests at the end).
//
// Expected numbers (all from docs/validation.md V4 unless said):
// * line of intersection: trend 000.5, plunge psi = 27.63 deg;
// * phi < 20.23 deg: a = g (sin psi - K tan phi cos psi), K = 1.42013;
//   phi = 10: a = 2.3731 m/s^2, so s(0.5 s) = a t^2 / 2 = 0.29664 m;
// * normal reactions N_A = N_B = 0.629 W while sliding (W = rho g V; the
//   friction acts along the line, so the normals do not depend on phi).
//   Also checked here by solving N_A nA + N_B nB + F l = W e_z.
// * phi = 30 (FS = 1.5663 > 1): the wedge holds.
//
// Penalty 1e10 N/m (not the cube test's 1e9): W = 2600 * 9.81 * 80.2 =
// 2.05 MN, the shear along the line W sin psi = 0.95 MN on 6 contact points,
// so with ps = 1e9 the elastic shear-spring stretch alone is 1.6e-4 m, more
// than the 1e-4 m allowed for "holds" (the run gives 1.1e-3 m with the
// dynamic overshoot; with pn = 1e9 the slide is also 2.3 % long, 0.3034 m).
// With 1e10 the stretch is 1.6e-5 m and the static penetration about 4e-5 m;
// the contact frequency sqrt(6 pn / m) = 540 rad/s (period 12 ms) is
// resolved by dt = 1 ms. The normal forces are compared as time averages over
// the second half of the run (0.25 to 0.5 s), as an undamped penalty contact
// oscillates about the static value after release.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "dda/common/error.hpp"
#include "dda/analysis/sliding3d.hpp"
#include "dda/dc/cut3d.hpp"
#include "dda/df/3d/simulation3d.hpp"
#include "dda/dl/dfn3d.hpp"

namespace dda::df3 {
namespace {

constexpr double kDeg = std::numbers::pi / 180;
constexpr double kG = 9.81;
constexpr double kRho = 2600;
constexpr double kPenalty = 1e10;  // N/m, normal and shear (see the header)

Fracture3 persistent_plane(const Vec3& normal, const Vec3& point, int set) {
  Fracture3 f;
  f.shape = FractureShape::Plane;
  f.normal = normal.normalized();
  f.centre = point;
  f.set = set;
  return f;
}

struct WedgeModel {
  Model3 model;
  int wedge = -1;
  Vec3 nA, nB, line;  // upper normals of A, B; unit line of intersection, pointing down
  double weight = 0;  // N
};

// Layout::SharedCorners: every block of the one cut. Layout::LargerFaces: the wedge from that cut, the fixed
// blocks the half-spaces below A and below B of a larger box (x in [-8, 8],
// y in [-2, 12], z in [0, 12]), cut by A alone and by B alone; they overlap
// each other (fixed-fixed pairs carry nothing) and their faces on A and B
// reach past the wedge's, so no wedge corner sits on a corner or edge of
// the face it rests on.
enum class Layout { SharedCorners, LargerFaces };

WedgeModel build(double phi_deg, double penalty, Layout layout = Layout::LargerFaces) {
  WedgeModel w;
  w.nA = dl::normal_from_dip(51.4, 65.8);
  w.nB = dl::normal_from_dip(51.4, 295.2);
  w.line = w.nA.cross(w.nB).normalized();
  if (w.line.z() > 0) w.line = -w.line;
  const Vec3 T(0, 0, 10);
  FractureModel fm;
  fm.domain = {Vec3(-8, -2, 0), Vec3(8, 10, 10)};
  fm.sets = {{"A", "user"}, {"B", "user"}};
  fm.fractures = {persistent_plane(w.nA, T, 0), persistent_plane(w.nB, T, 1)};
  const auto cut = dc::cut_blocks_3d(fm);
  Model3& m = w.model;
  // All four blocks of the cut, the one below both planes included: it
  // touches the wedge only along the line of intersection (collinear edges,
  // no edge-edge contact; the corners T and D give contacts that carry
  // nothing in V4).
  m.blocks = cut.model.blocks;
  if (layout == Layout::LargerFaces) {
    std::vector<Polyhedron> keep;
    for (const Polyhedron& p : m.blocks) {
      bool above = true;
      for (const Vec3& v : p.vertices) above = above && w.nA.dot(v - T) > -1e-9 && w.nB.dot(v - T) > -1e-9;
      if (above) keep.push_back(p);
    }
    for (int k = 0; k < 2; ++k) {
      FractureModel big;
      big.domain = {Vec3(-8, -2, 0), Vec3(8, 12, 12)};
      big.sets = {{"A", "user"}};
      big.fractures = {persistent_plane(k == 0 ? w.nA : w.nB, T, 0)};
      for (const Polyhedron& p : dc::cut_blocks_3d(big).model.blocks)
        if ((p.centroid - T).dot(k == 0 ? w.nA : w.nB) < 0) keep.push_back(p);
    }
    m.blocks = keep;
  }
  for (std::size_t b = 0; b < m.blocks.size(); ++b) {
    bool above = true;
    for (const Vec3& v : m.blocks[b].vertices)
      above = above && w.nA.dot(v - T) > -1e-9 && w.nB.dot(v - T) > -1e-9;
    if (above) {
      EXPECT_EQ(w.wedge, -1) << "two blocks above both planes";
      w.wedge = static_cast<int>(b);
    }
    m.fixed.push_back(!above);
  }
  if (w.wedge >= 0) w.weight = kRho * kG * m.blocks[static_cast<std::size_t>(w.wedge)].volume;
  m.materials = {{kRho, 1e10, 0.25}};
  m.default_joint.friction_deg = phi_deg;
  m.normal_penalty = penalty;
  m.shear_penalty = penalty;
  m.gravity = {0, 0, -kG};
  m.control.initial_equilibrium = false;  // gravity switched on at t = 0: what the expected numbers assume
  m.contact_reach = 0.01;  // > 2.5 x the largest step displacement (1.2 m/s * 1 ms)
  return w;
}

struct WedgeResult {
  double along = 0, off = 0;        // wedge centroid displacement along / across the line (m)
  double mean_na = 0, mean_nb = 0;  // time-averaged total normal force on A / B over the second half (N)
  double end_na = 0, end_nb = 0, end_other = 0;  // at the end
  int unconverged = 0, max_iterations = 0, contacts = 0, sliding = 0, locked = 0;
};

WedgeResult run(const WedgeModel& w, double dt, double t_end) {
  Simulation3 sim(w.model);
  const auto k = static_cast<std::size_t>(w.wedge);
  const Vec3 c0 = sim.blocks()[k].centroid;
  WedgeResult out;
  const int steps = static_cast<int>(std::lround(t_end / dt));
  int averaged = 0;
  for (int s = 0; s < steps; ++s) {
    const StepRecord3 info = sim.step(dt);
    if (!info.converged) ++out.unconverged;
    out.max_iterations = std::max(out.max_iterations, info.iterations);
    double na = 0, nb = 0, other = 0;
    for (const Contact3& c : sim.contacts()) {
      if (c.i != w.wedge && c.j != w.wedge) continue;
      if (std::abs(c.geo.normal.dot(w.nA)) > 0.999) na += c.normal_force;
      else if (std::abs(c.geo.normal.dot(w.nB)) > 0.999) nb += c.normal_force;
      else other += c.normal_force;
    }
    if (2 * (s + 1) > steps) {
      out.mean_na += na;
      out.mean_nb += nb;
      ++averaged;
    }
    out.end_na = na;
    out.end_nb = nb;
    out.end_other = other;
  }
  out.mean_na /= averaged;
  out.mean_nb /= averaged;
  const Vec3 u = sim.blocks()[k].centroid - c0;
  out.along = u.dot(w.line);
  out.off = (u - out.along * w.line).norm();
  for (const Contact3& c : sim.contacts()) {
    if (c.i != w.wedge && c.j != w.wedge) continue;
    ++out.contacts;
    if (c.state == ContactState3::Sliding) ++out.sliding;
    if (c.state == ContactState3::Locked) ++out.locked;
  }
  return out;
}

void print(const char* what, const WedgeModel& w, const WedgeResult& r, double expected) {
  std::printf("%s: along %.6f m (expected %.6f), off-line %.2e m, N_A/W mean %.4f end %.4f, N_B/W mean %.4f end %.4f,"
              " other contacts end %.3e W, wedge contacts %d (sliding %d, locked %d), unconverged %d, max it %d\n",
              what, r.along, expected, r.off, r.mean_na / w.weight, r.end_na / w.weight, r.mean_nb / w.weight,
              r.end_nb / w.weight, r.end_other / w.weight, r.contacts, r.sliding, r.locked, r.unconverged,
              r.max_iterations);
}

TEST(Simulation3Wedge, GeometryIsV4) {
  const WedgeModel w = build(10, kPenalty);
  ASSERT_GE(w.wedge, 0);
  EXPECT_EQ(w.model.blocks[static_cast<std::size_t>(w.wedge)].faces.size(), 4u);
  EXPECT_NEAR(w.model.blocks[static_cast<std::size_t>(w.wedge)].volume, 80.2, 0.5);  // the header's V
  // Trend 000.5, plunge 27.63 (docs/validation.md V4).
  EXPECT_NEAR(std::asin(-w.line.z()) / kDeg, 27.63, 0.01);
  EXPECT_NEAR(std::atan2(w.line.x(), w.line.y()) / kDeg, 0.5, 0.05);
  // Normal reactions from equilibrium: N_A nA + N_B nB + F l = W e_z.
  Eigen::Matrix3d M;
  M << w.nA, w.nB, w.line;
  const Vec3 x = M.fullPivLu().solve(Vec3(0, 0, 1));
  EXPECT_NEAR(x(0), 0.629, 0.001);  // docs/validation.md V4: 0.629 W on each
  EXPECT_NEAR(x(1), 0.629, 0.001);
  // Wedge factor K = (N_A + N_B) / (W cos psi) (docs/validation.md: 1.42013).
  EXPECT_NEAR((x(0) + x(1)) / std::cos(27.63 * kDeg), 1.42013, 2e-3);
}

// phi = 10 < 20.23: slides along the line with a = 2.3731 m/s^2.
TEST(Simulation3Wedge, SlidesAlongTheLineOfIntersectionV4) {
  const double psi = 27.63 * kDeg, phi = 10 * kDeg, K = 1.42013, t = 0.5;
  const double a = kG * (std::sin(psi) - K * std::tan(phi) * std::cos(psi));
  EXPECT_NEAR(a, 2.3731, 1e-4);  // the number in docs/validation.md
  const double expected = 0.5 * a * t * t;
  const WedgeModel w = build(10, kPenalty);
  ASSERT_GE(w.wedge, 0);
  const WedgeResult r = run(w, 1e-3, t);
  print("V4 phi=10", w, r, expected);
  EXPECT_NEAR(r.along, expected, 0.02 * expected);
  EXPECT_LT(r.off, 0.01 * std::abs(r.along));
  EXPECT_NEAR(r.mean_na, r.mean_nb, 0.05 * std::max(r.mean_na, r.mean_nb));
  EXPECT_NEAR(r.mean_na / w.weight, 0.629, 0.05 * 0.629);
  EXPECT_NEAR(r.mean_nb / w.weight, 0.629, 0.05 * 0.629);
  EXPECT_EQ(r.unconverged, 0);
}

// Friction per joint set: the faces on A and B carry their sets (0, 1), so
// joints given for them override the default (45 deg here, which would
// hold the wedge): with phi = 10 on both sets it slides as V4 at phi = 10;
// with phi = 10 on A only, the friction on B is the default and it holds
// (FS with 10 and 45: (N_A tan 10 + N_B tan 45) / (W sin psi) = 1.59).
TEST(Simulation3Wedge, FrictionComesFromTheJointSetOfTheFaces) {
  const double t = 0.5, expected = 0.5 * 2.3731 * t * t;  // docs/validation.md V4, phi = 10
  WedgeModel w = build(45, kPenalty, Layout::SharedCorners);
  df::JointProperties ten;
  ten.friction_deg = 10;
  w.model.joint_sets = {ten, ten};
  WedgeResult r = run(w, 1e-3, t);
  print("V4 sets A, B at phi=10, default 45", w, r, expected);
  EXPECT_NEAR(r.along, expected, 0.02 * expected);
  // Held: the contacts on A slip a quarter of a millimetre while the load
  // moves over to B (N_A rises to 0.84 W), then everything locks; sliding
  // would have gone 0.30 m.
  w.model.joint_sets = {ten};
  r = run(w, 1e-3, t);
  print("V4 set A at phi=10, B default 45", w, r, 0.0);
  EXPECT_LT(std::abs(r.along), 1e-3);
  EXPECT_EQ(r.sliding, 0);
  EXPECT_EQ(r.locked, r.contacts);
}

// phi = 30 (FS = 1.5663): the wedge holds.
TEST(Simulation3Wedge, HoldsWithThirtyDegreesV4) {
  const WedgeModel w = build(30, kPenalty);
  ASSERT_GE(w.wedge, 0);
  const WedgeResult r = run(w, 1e-3, 0.5);
  print("V4 phi=30", w, r, 0.0);
  EXPECT_LT(std::abs(r.along), 1e-4);
  EXPECT_LT(r.off, 1e-4);
  // No check of N_A, N_B here: with locked contacts the shear springs can
  // carry force across the line in each plane, so the normal forces are not
  // fixed by equilibrium (the run gives about 0.75 W each, wedged in).
  EXPECT_EQ(r.unconverged, 0);
}

// The fixed blocks of the same cut: every wedge corner sits on a corner of
// the face it rests on, and the contact search sees each such point now as
// a wedge vertex on a support face, now as a support vertex on a wedge face
// or an edge crossing (detect_contacts3, "Identity"). Before contacts kept
// their identity through those switches, phi = 30 crept 0.0104 m in 0.5 s
// (each switch restarted a contact without its shear spring) and phi = 10
// slid 8 % too far at pn = 1e9.
TEST(Simulation3Wedge, HoldsWithSharedCornersV4) {
  const WedgeModel w = build(30, kPenalty, Layout::SharedCorners);
  ASSERT_GE(w.wedge, 0);
  const WedgeResult r = run(w, 1e-3, 0.5);
  print("V4 phi=30 shared corners", w, r, 0.0);
  EXPECT_LT(std::abs(r.along), 1e-4);
  EXPECT_LT(r.off, 1e-4);
  EXPECT_EQ(r.unconverged, 0);
}

TEST(Simulation3Wedge, SlidesWithSharedCornersV4) {
  const double a = 2.3731, t = 0.5, expected = 0.5 * a * t * t;  // docs/validation.md V4, phi = 10
  const WedgeModel w = build(10, kPenalty, Layout::SharedCorners);
  ASSERT_GE(w.wedge, 0);
  const WedgeResult r = run(w, 1e-3, t);
  print("V4 phi=10 shared corners", w, r, expected);
  EXPECT_NEAR(r.along, expected, 0.02 * expected);
  EXPECT_LT(r.off, 0.01 * std::abs(r.along));
  EXPECT_NEAR(r.mean_na / w.weight, 0.629, 0.05 * 0.629);
  EXPECT_NEAR(r.mean_nb / w.weight, 0.629, 0.05 * 0.629);
  EXPECT_EQ(r.unconverged, 0);
}

// A checkpoint (Simulation3::state / restore) continues the run exactly:
// the sliding V4 wedge stopped after 150 steps and resumed in a new
// simulation ends where the uninterrupted run ends, to the last bit.
TEST(Simulation3Wedge, RestoredStateContinuesExactly) {
  const WedgeModel w = build(10, kPenalty, Layout::SharedCorners);
  Simulation3 whole(w.model), first(w.model);
  for (int s = 0; s < 300; ++s) whole.step(1e-3);
  for (int s = 0; s < 150; ++s) first.step(1e-3);
  Simulation3 resumed(w.model);
  resumed.restore(first.state());
  for (int s = 150; s < 300; ++s) resumed.step(1e-3);
  const auto k = static_cast<std::size_t>(w.wedge);
  EXPECT_EQ(resumed.blocks()[k].vertices, whole.blocks()[k].vertices);
  EXPECT_EQ(resumed.velocities()[k], whole.velocities()[k]);
  EXPECT_EQ(resumed.contacts().size(), whole.contacts().size());
  EXPECT_EQ(resumed.log().size(), 300u);
  // A state of another model is refused.
  Simulation3 other(build(10, kPenalty, Layout::LargerFaces).model);
  EXPECT_THROW(other.restore(first.state()), InputError);
}

// The shaking-table test of the seed report (chapter 2) on the V4 wedge:
// the table moves north-south at 2 Hz, ramped up over 5 s, 10 s in all.
// Amplitude 0.30 g, 45 % above the rigid yield acceleration 0.2074 g
// (docs/validation.md). Expected: the 3D analytical double-face solution
// (`dda sliding3d`, run here with dt = 1e-4), 122.65 mm along the line.
//
// The analysis is of a rigid wedge whose normal forces follow limit
// equilibrium at every instant, friction along the line. DDA's wedge rests
// on point contacts with shear springs, and while it sticks the springs
// across the line carry part of the load: when the shaking lifts the wedge
// off its planes, the normal forces fall by pn / (pn + ps) of the rigid
// analysis' fall (the planes are 90.5 deg apart), the wedge holds longer and
// each slide starts later (docs/solver3d.md, "Near the yield acceleration").
// Once sliding, DDA's wedge follows the analysis' acceleration: the run at
// ps = pn slides 11 % less, every slide starting 9 ms late. So the check is
// made with the shear springs a tenth of the normal ones, where the falls
// differ by 9 %: DDA within 5 % of the analysis in both input modes
// (measured -3.0 % loading, -3.2 % displacement). At ps = pn (loading
// mode) the wedge must slide less than that, by the late starts: measured
// -11.0 %, bounded here by 15 %.
TEST(Simulation3Wedge, ShakingTableMatchesTheAnalyticalSolutionV4) {
  const double t_end = 10, amplitude = 0.30 * kG, omega = 2 * std::numbers::pi * 2, ramp = 5;
  auto ground = [&](double t) { return Vec3(0, amplitude * std::sin(omega * t) * std::min(t / ramp, 1.0), 0); };
  analysis::SlidingModel am;
  am.planes = {analysis::Plane{51.4, 65.8}, analysis::Plane{51.4, 295.2}};
  am.friction = {analysis::FrictionLaw::constant_angle(30), analysis::FrictionLaw::constant_angle(30)};
  am.input.body = [&](double t) { return Vec3(-ground(t)); };
  am.input.duration = t_end;
  am.gravity = kG;
  const auto run = analysis::run_sliding(am, 1e-4, t_end);
  const Vec3 line(run.reference.x(), run.reference.y(), run.reference.z());
  const double expected = run.samples.back().u.dot(line);
  EXPECT_NEAR(expected, 122.65e-3, 0.1e-3);  // `dda sliding3d ... --sine 0.30 --freq 2 --axis y --ramp 5`
  std::vector<double> t;
  std::vector<Vec3> a;
  for (int k = 0; k <= 10000; ++k) t.push_back(k * 1e-3), a.push_back(ground(k * 1e-3));
  const auto motion = std::make_shared<GroundMotion3>(t, a);
  auto slide = [&](const char* mode, double shear_ratio) {
    WedgeModel w = build(30, 1e11, Layout::SharedCorners);
    w.model.shear_penalty = shear_ratio * w.model.normal_penalty;
    w.model.earthquake = {motion, &df::ground_motion_mode(mode)};
    Simulation3 sim(w.model);
    const auto k = static_cast<std::size_t>(w.wedge);
    std::size_t base = k == 0 ? 1 : 0;
    const Vec3 c0 = sim.blocks()[k].centroid, b0 = sim.blocks()[base].centroid;
    int unconverged = 0;
    const double dt = 1e-3;
    for (int s = 0; s < std::lround(t_end / dt); ++s) unconverged += sim.step(dt).converged ? 0 : 1;
    const Vec3 u = (sim.blocks()[k].centroid - c0) - (sim.blocks()[base].centroid - b0);
    std::printf("V4 shaking table, %s mode, ps = %g pn: %.4f mm along the line (analytical %.4f mm), %.2f %%, "
                "off-line %.2e m\n",
                mode, shear_ratio, 1e3 * u.dot(line), 1e3 * expected, 100 * (u.dot(line) - expected) / expected,
                (u - u.dot(line) * line).norm());
    EXPECT_LT((u - u.dot(line) * line).norm(), 0.01 * expected) << mode;
    EXPECT_EQ(unconverged, 0) << mode;
    return u.dot(line);
  };
  double loading = 0;
  for (const char* mode : {"loading", "displacement"}) {
    const double s = slide(mode, 0.1);
    EXPECT_NEAR(s, expected, 0.05 * expected) << mode;
    if (std::string(mode) == "loading") loading = s;
  }
  const double stiff_shear = slide("loading", 1.0);
  EXPECT_LT(stiff_shear, loading);
  EXPECT_NEAR(stiff_shear, expected, 0.15 * expected);
}

// Joint water (docs/formulation.md, "Joint water"): the V4 wedge below a
// water table at z = 12, above the whole model, so both of its joint faces
// are under water end to end, with the joints 30 % saturated (full
// saturation would lift the wedge off: U/W = 0.66 per face against N/W =
// 0.629). A flat face wholly under water carries U = s gamma_w A (h - z_c)
// (area times the depth of its centroid: textbook hydrostatics, A and z_c
// computed here from the face's corners; s the saturation), normal to it,
// pushing the wedge off its plane. The effective reactions per unit
// weight are then n_i = 0.629 - U_i / W (V4's dry reactions, the water
// being normal to both planes), and the wedge slides along the line with
// m s'' = W sin psi - (N_A + N_B) tan phi, the water deepening by s sin psi
// as it goes, so that U_A + U_B grows by gamma_w (A_A + A_B) sin psi per
// metre: s(t) = a0 / k (cosh(sqrt(k) t) - 1) from rest, a0 the initial
// acceleration, k = g s gamma_w (A_A + A_B) sin psi tan phi / W.
struct WetFace {
  double area = 0, centroid_z = 0;
};
WetFace face_on(const Polyhedron& p, const Vec3& plane_normal) {
  for (const PolyFace& f : p.faces) {
    std::vector<Vec3> v;
    for (const int k : f.vertices) v.push_back(p.vertices[static_cast<std::size_t>(k)]);
    const Vec3 n = (v[1] - v[0]).cross(v[2] - v[0]).normalized();
    if (n.dot(plane_normal) > -0.999) continue;  // the wedge's face on the plane looks down it
    WetFace out;
    double zsum = 0;
    for (std::size_t k = 1; k + 1 < v.size(); ++k) {
      const double a = 0.5 * (v[k] - v[0]).cross(v[k + 1] - v[0]).norm();
      out.area += a;
      zsum += a * (v[0].z() + v[k].z() + v[k + 1].z()) / 3;
    }
    out.centroid_z = zsum / out.area;
    return out;
  }
  ADD_FAILURE() << "no face on the plane";
  return {};
}

TEST(Simulation3Wedge, WaterTableReducesTheNormalForcesAndSpeedsTheSlide) {
  constexpr double kLevel = 12, kGammaW = 9810, kPhi = 10, kT = 0.5, kSaturation = 0.3;
  WedgeModel w = build(kPhi, kPenalty);
  ASSERT_GE(w.wedge, 0);
  w.model.default_joint.saturation = kSaturation;  // the faces on A and B take the default joint
  df::WaterTable<3> water;
  water.level = kLevel;
  w.model.water = water;
  const Polyhedron& wedge = w.model.blocks[static_cast<std::size_t>(w.wedge)];
  const WetFace fa = face_on(wedge, w.nA), fb = face_on(wedge, w.nB);
  const double ua = kSaturation * kGammaW * fa.area * (kLevel - fa.centroid_z);
  const double ub = kSaturation * kGammaW * fb.area * (kLevel - fb.centroid_z);
  const double psi = 27.63 * kDeg, mu = std::tan(kPhi * kDeg);
  const double na = 0.629 - ua / w.weight, nb = 0.629 - ub / w.weight;  // effective, per unit weight
  const double a0 = kG * (std::sin(psi) - (na + nb) * mu);
  const double k = kG * kSaturation * kGammaW * (fa.area + fb.area) * std::sin(psi) * mu / w.weight;
  const double expected = a0 / k * (std::cosh(std::sqrt(k) * kT) - 1);
  std::printf("wet V4: U_A/W %.4f, U_B/W %.4f, dry slide %.5f m, wet expected %.5f m\n", ua / w.weight,
              ub / w.weight, 0.5 * 2.3731 * kT * kT, expected);
  const WedgeResult r = run(w, 1e-3, kT);
  print("V4 phi=10 under water", w, r, expected);
  // V4's tolerances (SlidesAlongTheLineOfIntersectionV4): 2 % on the slide,
  // 5 % on the normal forces.
  EXPECT_NEAR(r.along, expected, 0.02 * expected);
  EXPECT_NEAR(r.mean_na / w.weight, na, 0.05 * 0.629);
  EXPECT_NEAR(r.mean_nb / w.weight, nb, 0.05 * 0.629);
  EXPECT_EQ(r.unconverged, 0);
}

}  // namespace
}  // namespace dda::df3
