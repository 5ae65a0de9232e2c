// Joint water (df/include/dda/df/core/water.hpp, docs/formulation.md "Joint
// water"): the pore pressure's integral over joint faces against hand
// integrals, and a 2D block on an incline with a water table against the
// effective-stress limit equilibrium
//   FS = (W cos a - U) tan phi / (W sin a),
// U the water force on its base (the block's free faces are not loaded:
// the model's assumption, docs/formulation.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "df_test_models.hpp"
#include "dda/df/2d/simulation.hpp"
#include "dda/df/core/water.hpp"
#include "2d/water_faces.hpp"
#include "3d/water_faces3d.hpp"

namespace dda::df {
namespace {

constexpr double kGammaW = 9810;  // N/m^3, 1000 kg/m^3 x 9.81 m/s^2

// ---- the integral of u over a face ---------------------------------------

TEST(WaterPressure, SubmergedSegmentCarriesMeanDepthTimesLength) {
  // Level 10; a segment from (0, 2) to (4, 5) (length 5): depths 8 and 5,
  // linear in between, so U = gamma_w * 5 * (8 + 5) / 2 = 318 825 N/m and
  // the centre lies at the depth-weighted point: s = L (d0 + 2 d1) / (3 (d0 + d1))
  // from the first end = 5 * 18 / 39.
  WaterTable<2> w;
  w.level = 10;
  const PressureResultant<2> r = pressure_on_segment(w, {0, 2}, {4, 5});
  EXPECT_NEAR(r.force, kGammaW * 5 * 6.5, 1e-9 * r.force);
  const double s = 5.0 * 18.0 / 39.0;
  EXPECT_NEAR((r.centre - Eigen::Vector2d(0, 2)).norm(), s, 1e-12);
}

TEST(WaterPressure, SegmentCrossingTheTableIsLoadedBelowItOnly) {
  // A vertical face from z = 0 to z = 1, level 0.5: the triangle of
  // pressure gamma_w d over d in [0, 0.5] gives gamma_w 0.5^2 / 2 =
  // 1226.25 N/m, acting a third of the wet height above its foot (z = 1/6).
  WaterTable<2> w;
  w.level = 0.5;
  const PressureResultant<2> r = pressure_on_segment(w, {3, 0}, {3, 1});
  EXPECT_NEAR(r.force, 1226.25, 1e-9);
  EXPECT_NEAR(r.centre.y(), 1.0 / 6.0, 1e-12);
  EXPECT_NEAR(r.centre.x(), 3.0, 1e-12);
  // Dry: a face above the table carries nothing.
  EXPECT_EQ(pressure_on_segment(w, {0, 0.6}, {1, 2}).force, 0.0);
}

TEST(WaterPressure, PolylineSurfaceIsIntegratedPieceByPiece) {
  // Surface through (0, 1), (1, 3), (2, 1): over the horizontal face z = 0,
  // x in [0, 2], the head is a tent of height 1..3, so U = gamma_w * (area
  // under the tent) = gamma_w * 4 (two trapezoids of mean 2 and width 1),
  // centred at x = 1 by symmetry. A midpoint rule written here agrees.
  WaterTable<2> w;
  w.knots = {{0, 1}, {1, 3}, {2, 1}};
  const PressureResultant<2> r = pressure_on_segment(w, {0, 0}, {2, 0});
  EXPECT_NEAR(r.force, kGammaW * 4, 1e-9 * r.force);
  EXPECT_NEAR(r.centre.x(), 1.0, 1e-12);
  // Outside the knots the head holds the end value (1): 1 m to the left.
  EXPECT_NEAR(pressure_on_segment(w, {-1, 0}, {0, 0}).force, kGammaW * 1, 1e-6);
}

TEST(WaterPressure, PolygonAgreesWithAMidpointRule) {
  // A 2 x 2 square tilted 30 degrees about the x axis, its lowest edge at
  // z = 0, under a plane surface h = 1 + 0.1 x: part of it lies above the
  // water. Independent integral: the midpoint rule on a 400 x 400 grid of
  // the square's own coordinates (its error is far below 1e-4).
  WaterTable<3> w;
  w.knots = {{0, 0, 1.0}, {1, 0, 1.1}, {0, 1, 1.0}};
  const double a = M_PI / 6;
  auto at = [&](double s, double t) { return Eigen::Vector3d(s, t * std::cos(a), t * std::sin(a)); };
  const std::vector<Eigen::Vector3d> face{at(0, 0), at(2, 0), at(2, 2), at(0, 2)};
  const PressureResultant<3> r = pressure_on_polygon(w, face);
  const int n = 400;
  double force = 0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Eigen::Vector3d p = at(2.0 * (i + 0.5) / n, 2.0 * (j + 0.5) / n);
      const double u = w.pressure(p) * (2.0 / n) * (2.0 / n);
      force += u;
      moment += u * p;
    }
  EXPECT_NEAR(r.force, force, 1e-4 * force);
  EXPECT_LT((r.centre - moment / force).norm(), 1e-3);
  EXPECT_GT(r.force, 0.0);
}

// ---- a 2D block on an incline with a water table --------------------------

constexpr double kAlpha = 30.0;  // degrees
constexpr double kG = 9.81, kRho = 2000;

// V1's plane (docs/validation.md): an 8 x 1 m slab dipping at alpha, held by
// three fixed points, and a 1 x 1 m block on it at local x = 6..7 (uphill is
// local +x), its base at z = 3 .. 3.5. The water table at `level` loads the
// joint between them.
ModelInput incline(double phi_deg, double level) {
  const double a = deg2rad(kAlpha);
  ModelInput in;
  in.geometry.blocks.push_back(test::make_block(test::rotated(test::rectangle(0, -1, 8, 1), a)));
  in.geometry.blocks.push_back(test::make_block(test::rotated(test::rectangle(6, 0, 1, 1), a)));
  in.materials = {test::rock(kRho, 5e10)};
  JointProperties j;
  j.friction_deg = phi_deg;
  in.joint_sets = {j};
  in.control.dt = 1e-3;
  WaterTable<2> w;
  w.level = level;
  in.water = w;
  for (const double x : {0.5, 4.0, 7.5}) in.fixed_points.push_back({"base", test::rotated(Vec2(x, -0.5), a), 0, {}});
  in.measurements.push_back({"slider", test::rotated(Vec2(6.5, 0.5), a), 1});
  return in;
}

// The water table 0.4 m above the middle of the block's base (z = 3.25):
// the base is under water from end to end (its top end is at z = 3.5), so
// U = gamma_w * 1 m * 0.4 m = 3924 N/m (mean depth times length).
constexpr double kLevel = 3.65;
constexpr double kU = kGammaW * 1.0 * 0.4;

double weight() { return kRho * kG * 1.0; }  // N/m, the 1 m^2 block
// The friction angle at which FS = 1: tan phi = W sin a / (W cos a - U).
double critical_phi() {
  const double a = deg2rad(kAlpha);
  return rad2deg(std::atan(weight() * std::sin(a) / (weight() * std::cos(a) - kU)));
}

TEST(WaterIncline, LimitEquilibriumOfTheHandNumbers) {
  // The analytical side on its own: 36.90 degrees wet against 30 dry, and
  // FS from the formula at phi = 40: (16991 - 3924) tan 40 / 9810 = 1.1177.
  EXPECT_NEAR(critical_phi(), 36.896, 0.001);
  const double a = deg2rad(kAlpha);
  const double fs = (weight() * std::cos(a) - kU) * std::tan(deg2rad(40.0)) / (weight() * std::sin(a));
  EXPECT_NEAR(fs, 1.1177, 1e-4);
}

TEST(WaterIncline, BlockHoldsJustAboveTheCriticalAngleWithEffectiveNormalForce) {
  // phi_c + 0.5 degree: FS = 1.02, the block must stay (the bound is the
  // friction-limit test's, tests/df/test_friction_limit.cpp), and its
  // contacts carry the effective normal force W cos a - U = 13 067 N/m:
  // the water's push took U off the springs.
  Simulation sim(build_model(incline(critical_phi() + 0.5, kLevel)));
  sim.run_until(1.0);
  const auto& h = sim.histories()[0];
  const double slip = (h.back().displacement - h.front().displacement).norm();
  double normal = 0;
  for (const Contact& c : sim.contacts()) normal += c.normal_force;
  const double expected = weight() * std::cos(deg2rad(kAlpha)) - kU;
  std::printf("water incline, phi_c + 0.5: slip %.2e m, sum N %.1f N/m (expected %.1f)\n", slip, normal, expected);
  EXPECT_LT(slip, 1e-4);
  EXPECT_NEAR(normal, expected, 1e-3 * expected);
}

TEST(WaterIncline, BlockSlidesJustBelowTheCriticalAngle) {
  // phi_c - 0.5 degree: FS = 0.98, it must slide. Well below, at phi_c - 5,
  // with the effective-stress balance along the way: sliding s down the
  // slope lowers the (fully submerged) base by s sin a, so U grows by
  // gamma_w L s sin a, and
  //   m s'' = W sin a - (W cos a - U0 - gamma_w L s sin a) tan phi = m (a0 + k s),
  //   k = gamma_w L sin a tan phi / m,
  // from rest: s(t) = a0 / k (cosh(sqrt(k) t) - 1). At 1 s that is 0.4755 m,
  // 13 % more than a0 / 2 with U held at U0. Within 0.2 %.
  Simulation near(build_model(incline(critical_phi() - 0.5, kLevel)));
  near.run_until(1.0);
  EXPECT_GT(near.histories()[0].back().displacement.norm(), 1e-3);

  const double phi = critical_phi() - 5;
  Simulation sim(build_model(incline(phi, kLevel)));
  sim.run_until(1.0);
  const double s = sim.histories()[0].back().displacement.norm();
  const double a = deg2rad(kAlpha), mu = std::tan(deg2rad(phi));
  const double a0 = (weight() * std::sin(a) - (weight() * std::cos(a) - kU) * mu) / kRho;
  const double k = kGammaW * 1.0 * std::sin(a) * mu / kRho;
  const double expected = a0 / k * (std::cosh(std::sqrt(k) * 1.0) - 1);
  std::printf("water incline, phi_c - 5: s %.5f m, expected %.5f m\n", s, expected);
  EXPECT_NEAR(s, expected, 0.002 * expected);  // measured within 0.03 %
}

TEST(WaterIncline, TableBelowTheJointChangesNothing) {
  // A water table under the whole model loads no face: the run is the dry
  // run bit for bit (so is one without `water`).
  ModelInput dry = incline(critical_phi() - 5, -100);
  ModelInput none = dry;
  none.water.reset();
  Simulation a(build_model(dry)), b(build_model(none));
  a.run_until(0.2);
  b.run_until(0.2);
  EXPECT_EQ(a.histories()[0].back().displacement, b.histories()[0].back().displacement);
}

TEST(WaterIncline, SaturationScalesThePressure) {
  // saturation 0.5 halves U: the critical angle becomes that of U / 2,
  // tan phi = W sin a / (W cos a - U / 2) (33.13 degrees); 0.5 degree below
  // it the block slides, 0.5 above it holds.
  const double a = deg2rad(kAlpha);
  const double phi_half = rad2deg(std::atan(weight() * std::sin(a) / (weight() * std::cos(a) - kU / 2)));
  for (const double dphi : {-0.5, 0.5}) {
    ModelInput in = incline(phi_half + dphi, kLevel);
    in.joint_sets[0].saturation = 0.5;
    Simulation sim(build_model(in));
    sim.run_until(1.0);
    const double s = sim.histories()[0].back().displacement.norm();
    if (dphi < 0)
      EXPECT_GT(s, 1e-3);
    else
      EXPECT_LT(s, 1e-4);
  }
}

TEST(WaterBond, TensileBondSeesTheEffectiveStress) {
  // A 1 x 1 m block (W = 19 620 N/m) bonded to a fixed base by a joint of
  // tensile strength 10 kPa over its 1 m base (T l = 10 000 N/m, 5000 on
  // each of its two corner contacts), the joint at depth d below a water
  // table: the water pushes the block up with U = gamma_w d (1 m), so the
  // bond's springs carry N = W - U in all (tension when negative) and break
  // once U - W > T l, at d = (W + T l) / gamma_w = 3.019 m. At d = 3.0 m the
  // block stays bonded with N = (W - U) / 2 = -4905 N/m a contact; at
  // d = 3.05 m (1 % deeper) the bond breaks and the water lifts the block.
  // The cohesion (100 kPa) keeps the bond from failing in shear first: with
  // none, the little shear the blocks' elastic strains put on the stiff
  // contacts exceeds mu N once the water has taken most of N away (the
  // same effective stress, acting on the shear strength).
  for (const double depth : {3.0, 3.05}) {
    ModelInput in;
    in.geometry.blocks.push_back(test::make_block(test::rectangle(-2, -1, 5, 1)));
    in.geometry.blocks.push_back(test::make_block(test::rectangle(0, 0, 1, 1)));
    in.materials = {test::rock(kRho, 5e10)};
    JointProperties j;
    j.tensile_strength = 1e4;
    j.cohesion = 1e5;
    in.joint_sets = {j};
    in.control.dt = 1e-3;
    WaterTable<2> w;
    w.level = depth;
    in.water = w;
    for (const double x : {-1.5, 0.5, 2.5}) in.fixed_points.push_back({"base", Vec2(x, -0.5), 0, {}});
    in.measurements.push_back({"block", Vec2(0.5, 0.5), 1});
    Simulation sim(build_model(in));
    sim.run_until(0.2);
    const double rise = sim.histories()[0].back().displacement.y();
    int bonded = 0;
    double normal = 0;
    for (const Contact& c : sim.contacts()) {
      bonded += c.bonded;
      normal += c.normal_force;
    }
    std::printf("bonded block under %.2f m of water: rise %.3e m, %d bonds, sum N %.1f N/m\n", depth, rise, bonded,
                normal);
    if (depth < 3.019) {
      EXPECT_EQ(bonded, 2);
      EXPECT_NEAR(normal, weight() - kGammaW * depth, 1e-6 * weight());
      EXPECT_LT(std::abs(rise), 1e-5);
    } else {
      EXPECT_EQ(bonded, 0);
      EXPECT_GT(rise, 1e-3);
    }
  }
}

TEST(WaterFaces, FacingEdgesAreLoadedOnceAndGluedCutsNotAtAll) {
  // Two unit squares side by side (the right one's left edge on the left
  // one's right edge, x = 1), under a level of 2: the shared face, depths
  // 1 .. 2 from top to bottom, carries U = gamma_w * 1.5 (mean depth times
  // 1 m), centred s = L (d0 + 2 d1) / (3 (d0 + d1)) = 5/9 below its top
  // (y = 4/9), pushing the right block to +x and the left one to -x. Both of
  // the right block's left corners touch the edge: one pair, found twice,
  // loaded once. Glued (an artificial cut), nothing.
  const Polygon2 left = test::rectangle(0, 0, 1, 1), right = test::rectangle(1, 0, 1, 1);
  std::vector<Contact> contacts(2);
  for (int k = 0; k < 2; ++k) {
    contacts[k].vblock = 1;
    contacts[k].vertex = k == 0 ? 0 : 3;  // (1, 0) and (1, 1)
    contacts[k].eblock = 0;
    contacts[k].edge = 1;  // (1, 0) -> (1, 1)
  }
  WaterTable<2> w;
  w.level = 2;
  const std::vector<const Polygon2*> blocks{&left, &right};
  const auto loads = water_loads_2d(w, {1.0}, blocks, contacts, 0.01);
  ASSERT_EQ(loads.size(), 2u);
  EXPECT_EQ(loads[0].block, 1);
  EXPECT_NEAR(loads[0].force.x(), kGammaW * 1.5, 1e-9 * kGammaW);
  EXPECT_NEAR(loads[0].force.y(), 0, 1e-9);
  EXPECT_NEAR(loads[1].force.x(), -kGammaW * 1.5, 1e-9 * kGammaW);
  EXPECT_NEAR(loads[0].at.y(), 4.0 / 9.0, 1e-12);
  for (Contact& c : contacts) c.glued = true;
  EXPECT_TRUE(water_loads_2d(w, {1.0}, blocks, contacts, 0.01).empty());
}

}  // namespace
}  // namespace dda::df
