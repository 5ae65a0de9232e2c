// Hoek & Bray's wedge with water (tools/analysis: wedge_body.hpp, wedge.hpp)
// against their "short solution" written out here from its published
// formula (Hoek & Bray, Rock Slope Engineering, chapter on wedge failure):
//
//   FS = 3 / (gr H) (cA X + cB Y) + (A - gw / (2 gr) X) tan phiA
//                                  + (B - gw / (2 gr) Y) tan phiB
//   X = sin t24 / (sin t45 cos t2.na),  Y = sin t13 / (sin t35 cos t1.nb)
//   A = (cos psiA - cos psiB cos tna.nb) / (sin psi5 sin^2 tna.nb)
//   B = (cos psiB - cos psiA cos tna.nb) / (sin psi5 sin^2 tna.nb)
//
// t_ij the angle between lines i and j (1: plane A with the face, 2: B with
// the face, 3: A with the upper surface, 4: B with the upper surface, 5: A
// with B), t2.na between line 2 and the pole of A, tna.nb between the poles;
// psi the dips of A and B and the plunge of line 5. The test measures these
// angles from the orientations with vectors (what the book reads off a
// stereonet), an independent route from the tool's, which builds the
// tetrahedron, its volume and face areas. The orientations are those of the
// book's worked example (A 45/105, B 70/235, face 65/185, upper surface
// 12/195), with its stereonet angles t24 65, t45 25, t2.na 50, t13 62,
// t35 31, t1.nb 60, tna.nb 101 degrees, read off a net to a degree or so:
// the vector angles must lie within a degree of them. The strengths are the
// example's in SI (cA 24 kPa, cB 48 kPa, phiA 20, phiB 30, gr 25 kN/m^3,
// gw 9.81 kN/m^3) with H = 40 m; the published factor of safety itself
// could not be checked here (docs/analytical.md says so).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <tuple>

#include "dda/analysis/wedge.hpp"
#include "dda/analysis/wedge_body.hpp"
#include "dda/common/error.hpp"

namespace dda::analysis {
namespace {

const Plane kA{45, 105}, kB{70, 235}, kFace{65, 185}, kUpper{12, 195};
constexpr double kH = 40, kGr = 25, kGw = 9.81, kCa = 24, kCb = 48, kPhiA = 20, kPhiB = 30;

double deg(double rad) { return rad * 180.0 / M_PI; }
double angle(const Vec3& a, const Vec3& b) { return std::acos(a.normalized().dot(b.normalized())); }
// The angle between two lines (no sense): 0..90 degrees.
double line_angle(const Vec3& a, const Vec3& b) { return std::acos(std::abs(a.normalized().dot(b.normalized()))); }

struct ShortSolution {
  double x, y, a, b;
  double t24, t45, t2na, t13, t35, t1nb, tnanb;  // rad
};

ShortSolution short_solution() {
  const Vec3 na = kA.normal(), nb = kB.normal(), nf = kFace.normal(), nu = kUpper.normal();
  const Vec3 l1 = na.cross(nf), l2 = nb.cross(nf), l3 = na.cross(nu), l4 = nb.cross(nu), l5 = na.cross(nb);
  ShortSolution s;
  s.t24 = line_angle(l2, l4);
  s.t45 = line_angle(l4, l5);
  s.t2na = line_angle(l2, na);
  s.t13 = line_angle(l1, l3);
  s.t35 = line_angle(l3, l5);
  s.t1nb = line_angle(l1, nb);
  s.tnanb = angle(na, nb);  // between the (upward) poles: signed cosine
  const double psi5 = std::asin(std::abs(l5.normalized().z()));
  const double psia = kA.dip_deg * M_PI / 180, psib = kB.dip_deg * M_PI / 180;
  s.x = std::sin(s.t24) / (std::sin(s.t45) * std::cos(s.t2na));
  s.y = std::sin(s.t13) / (std::sin(s.t35) * std::cos(s.t1nb));
  const double d = std::sin(psi5) * std::pow(std::sin(s.tnanb), 2);
  s.a = (std::cos(psia) - std::cos(psib) * std::cos(s.tnanb)) / d;
  s.b = (std::cos(psib) - std::cos(psia) * std::cos(s.tnanb)) / d;
  return s;
}

double short_fs(const ShortSolution& s, double ca, double cb, double gw) {
  const double ta = std::tan(kPhiA * M_PI / 180), tb = std::tan(kPhiB * M_PI / 180);
  return 3 / (kGr * kH) * (ca * s.x + cb * s.y) + (s.a - gw / (2 * kGr) * s.x) * ta +
         (s.b - gw / (2 * kGr) * s.y) * tb;
}

// The tool: the tetrahedron, its weight and areas, the water forces per unit weight.
double tool_fs(double ca, double cb, double gw) {
  WedgeSpec spec;
  spec.plane1 = kA;
  spec.plane2 = kB;
  spec.phi1_deg = kPhiA;
  spec.phi2_deg = kPhiB;
  const WedgeBody body = wedge_body(kA, kB, SlopeFaces{kFace, kUpper, kH});
  spec.weight_kn = kGr * body.volume_m3;
  spec.area1_m2 = body.area1_m2;
  spec.area2_m2 = body.area2_m2;
  spec.cohesion1_kpa = ca;
  spec.cohesion2_kpa = cb;
  const WedgeWaterForces u = hoek_bray_water(body, gw);
  spec.water1 = u.u1 / spec.weight_kn;
  spec.water2 = u.u2 / spec.weight_kn;
  return wedge_equilibrium(spec, Vec3(0, 0, -1)).fs;
}

TEST(WedgeWater, StereonetAnglesAreTheBooks) {
  const ShortSolution s = short_solution();
  EXPECT_NEAR(deg(s.t24), 65, 1);
  EXPECT_NEAR(deg(s.t45), 25, 1);
  EXPECT_NEAR(deg(s.t2na), 50, 1);
  EXPECT_NEAR(deg(s.t13), 62, 1);
  EXPECT_NEAR(deg(s.t35), 31, 1);
  EXPECT_NEAR(deg(s.t1nb), 60, 1);
  EXPECT_NEAR(deg(s.tnanb), 101, 1);
}

TEST(WedgeWater, DryFrictionOnlyIsV5) {
  // docs/validation.md V5 (these planes, phiA 20, phiB 30, dry, no
  // cohesion): FS = 1.1066, the vector method's; the short solution's
  // A tan phiA + B tan phiB gives the same.
  const ShortSolution s = short_solution();
  EXPECT_NEAR(short_fs(s, 0, 0, 0), 1.1066, 1e-4);
  EXPECT_NEAR(tool_fs(0, 0, 0), 1.1066, 1e-4);
}

TEST(WedgeWater, ToolAgreesWithTheShortSolution) {
  // Dry with cohesion, saturated without, saturated with: the two routes
  // agree to rounding (they are the same mechanics; the short solution's
  // X and Y are the face areas over the weight in disguise, so this checks
  // the tetrahedron, its areas and volume, and the water forces).
  const ShortSolution s = short_solution();
  for (const auto& [ca, cb, gw] : {std::tuple{kCa, kCb, 0.0}, std::tuple{0.0, 0.0, kGw}, std::tuple{kCa, kCb, kGw}}) {
    const double expected = short_fs(s, ca, cb, gw);
    std::printf("wedge c %g/%g gw %g: short solution %.4f, tool %.4f\n", ca, cb, gw, expected, tool_fs(ca, cb, gw));
    EXPECT_NEAR(tool_fs(ca, cb, gw), expected, 1e-9 * expected);
  }
  // Water takes strength off: the saturated wedge is weaker than the dry
  // one (1.214 against 1.845 with cohesion, 0.475 against 1.107 without;
  // what short_fs above gives, with X = 3.4016,
  // Y = 3.4280, A = 1.5403, B = 0.9457).
  EXPECT_NEAR(tool_fs(kCa, kCb, kGw), 1.2139, 1e-4);
  EXPECT_NEAR(tool_fs(kCa, kCb, 0), 1.8452, 1e-4);
}

TEST(WedgeWater, HeightIsTheRiseOfTheLineOfIntersection) {
  // The toe at the origin, the top of the line of intersection H above it;
  // the crest points on the face and the upper surface (their plane
  // equations hold), and the volume from the corners: 1/6 |det|.
  const WedgeBody b = wedge_body(kA, kB, SlopeFaces{kFace, kUpper, kH});
  EXPECT_NEAR(b.top.z(), kH, 1e-9);
  for (const Vec3& q : {b.crest1, b.crest2}) {
    EXPECT_NEAR(kFace.normal().dot(q), 0, 1e-9);
    EXPECT_NEAR(kUpper.normal().dot(q - b.top), 0, 1e-9);
  }
  EXPECT_NEAR(kA.normal().dot(b.crest1), 0, 1e-9);
  EXPECT_NEAR(kB.normal().dot(b.crest2), 0, 1e-9);
}

TEST(WedgeWater, ImpossibleWedgesAreRefused) {
  // A face flatter than the line of intersection (plunge 31.2): no daylight.
  EXPECT_THROW(wedge_body(kA, kB, SlopeFaces{Plane{20, 185}, kUpper, kH}), InputError);
  EXPECT_THROW(wedge_body(kA, kB, SlopeFaces{kFace, kUpper, -1}), InputError);
}

}  // namespace
}  // namespace dda::analysis
