// The 3D block cutter against exact geometry: brick counts and volumes of
// persistent sets, conservation of volume, finite fractures that do or do
// not reach through, excavations and the bodies they leave, the seed's
// tetrahedral wedge, and degenerate input.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <algorithm>
#include <random>

#include "dc3d_test_util.hpp"
#include "dda/common/error.hpp"
#include "dda/dc/cut3d.hpp"
#include "dda/dl/dfn3d.hpp"

namespace dda::dc {
namespace {

using namespace test3;

TEST(Cut3d, BoxWithoutFracturesIsOneBlock) {
  const auto r = cut_blocks_3d(empty_model(Vec3(0, 0, 0), Vec3(2, 3, 4)));
  ASSERT_EQ(r.model.blocks.size(), 1u);
  const auto& b = r.model.blocks[0];
  expect_valid(b);
  EXPECT_NEAR(b.volume, 24, 1e-12);
  EXPECT_TRUE(b.centroid.isApprox(Vec3(1, 1.5, 2), 1e-12));
  // Second moment of a box about its centroid: V a^2 / 12 on the diagonal.
  EXPECT_NEAR(b.second_moment(0, 0), 24 * 4 / 12.0, 1e-10);
  EXPECT_NEAR(b.second_moment(2, 2), 24 * 16 / 12.0, 1e-10);
  EXPECT_NEAR(b.second_moment(0, 1), 0, 1e-10);
  EXPECT_EQ(b.faces.size(), 6u);
  for (const auto& f : b.faces) EXPECT_EQ(f.set, kBoundarySet);
}

// Three orthogonal persistent sets: (L/s) blocks along each axis.
TEST(Cut3d, ThreeOrthogonalSetsGiveTheExactBrickCount) {
  FractureModel m = empty_model(Vec3(0, 0, 0), Vec3(10, 6, 4), 3);
  for (int i = 1; i < 5; ++i) m.fractures.push_back(plane(Vec3::UnitX(), Vec3(2.0 * i, 0, 0), 0));
  for (int i = 1; i < 4; ++i) m.fractures.push_back(plane(Vec3::UnitY(), Vec3(0, 1.5 * i, 0), 1));
  for (int i = 1; i < 4; ++i) m.fractures.push_back(plane(Vec3::UnitZ(), Vec3(0, 0, 1.0 * i), 2));
  const auto r = cut_blocks_3d(m);
  ASSERT_EQ(r.model.blocks.size(), 5u * 4u * 4u);
  for (const auto& b : r.model.blocks) {
    expect_valid(b);
    EXPECT_NEAR(b.volume, 2 * 1.5 * 1, 1e-12);
  }
  EXPECT_NEAR(total_volume(r.model), 240, 240 * 1e-12);
  EXPECT_EQ(r.model.bodies.size(), r.model.blocks.size());
}

// The same bricks turned by an arbitrary rotation: every brick away from the
// boundary has volume s1 s2 s3 and the volumes sum to the box (1e-9).
TEST(Cut3d, RotatedOrthogonalSetsConserveVolume) {
  const Vec3 a = dl::normal_from_dip(35, 40);
  const Vec3 b = a.cross(Vec3(0.3, -0.2, 1)).normalized();
  const Vec3 c = a.cross(b);
  const double s[3] = {1.3, 1.7, 2.1};
  const Vec3 axes[3] = {a, b, c};
  FractureModel m = empty_model(Vec3(0, 0, 0), Vec3(10, 8, 6), 3);
  for (int k = 0; k < 3; ++k)
    for (int i = -12; i <= 12; ++i) m.fractures.push_back(plane(axes[k], Vec3(5, 4, 3) + (i + 0.37) * s[k] * axes[k], k));
  const auto r = cut_blocks_3d(m);
  EXPECT_NEAR(total_volume(r.model), 480, 480 * 1e-9);
  int interior = 0;
  for (const auto& bl : r.model.blocks) {
    expect_valid(bl);
    bool inner = true;
    for (const auto& f : bl.faces) inner = inner && f.set >= 0;
    if (!inner) continue;
    ++interior;
    EXPECT_NEAR(bl.volume, s[0] * s[1] * s[2], 1e-9);
    EXPECT_EQ(bl.faces.size(), 6u);
  }
  EXPECT_GT(interior, 20);
}

TEST(Cut3d, PlanesThroughEdgesVerticesAndFacesAreExact) {
  FractureModel m = empty_model(Vec3(0, 0, 0), Vec3(1, 1, 1), 1);
  m.fractures.push_back(plane(Vec3(1, -1, 0), Vec3(0, 0, 0)));     // x = y: through two edges
  m.fractures.push_back(plane(Vec3(1, -1, 0), Vec3(0.5, 0.5, 0)));  // the same plane again
  m.fractures.push_back(plane(Vec3::UnitX(), Vec3(0, 0, 0)));      // on the face x = 0: cuts nothing
  m.fractures.push_back(plane(Vec3::UnitX(), Vec3(1, 0, 0)));      // on the face x = 1
  m.fractures.push_back(plane(Vec3(1, 1, 1), Vec3(1, 0, 0)));      // through three corners
  m.fractures.push_back(plane(Vec3(1, 0, 1), Vec3(1, 0, 0)));      // through the edge x = 1, z = 0 and (0, y, 1)
  const auto r = cut_blocks_3d(m);
  for (const auto& b : r.model.blocks) expect_valid(b);
  EXPECT_NEAR(total_volume(r.model), 1, 1e-12);
  // x = y halves; x + y + z = 1 cuts the corner tetrahedron (1/6) into two
  // halves by x = y; x + z = 1 (the diagonal plane of the xz faces)
  // splits each half of the rest in two: 2 + 4 = 6 blocks.
  EXPECT_EQ(r.model.blocks.size(), 6u);
}

TEST(Cut3d, ManyPlanesThroughOnePointNeverBreakTheBlocks) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g;
  FractureModel m = empty_model(Vec3(0, 0, 0), Vec3(1, 1, 1), 1);
  for (int i = 0; i < 12; ++i) m.fractures.push_back(plane(Vec3(g(rng), g(rng), g(rng)), Vec3(0.5, 0.5, 0.5)));
  // and planes through the box's corner and its centre
  m.fractures.push_back(plane(Vec3(1, -1, 0), Vec3(0.5, 0.5, 0.5)));
  m.fractures.push_back(plane(Vec3(0, 1, -1), Vec3(0.5, 0.5, 0.5)));
  const auto r = cut_blocks_3d(m);
  for (const auto& b : r.model.blocks) expect_valid(b);
  EXPECT_NEAR(total_volume(r.model), 1, 1e-12);
  // n planes in general position through one point cut space into
  // n (n - 1) + 2 cones (regions of the sphere cut by n great circles), all
  // of which reach the box's faces: 14 planes, 184 blocks. Without snapping
  // the rounded offsets would leave extra blocks 1e-16 m wide at the centre.
  EXPECT_EQ(r.model.blocks.size(), 184u);
}

TEST(Cut3d, RandomPlanesConserveVolume) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(0, 5);
  FractureModel m = empty_model(Vec3(0, 0, 0), Vec3(5, 5, 5), 1);
  for (int i = 0; i < 60; ++i) m.fractures.push_back(plane(Vec3(g(rng), g(rng), g(rng)), Vec3(u(rng), u(rng), u(rng))));
  const auto r = cut_blocks_3d(m);
  for (const auto& b : r.model.blocks) expect_valid(b);
  EXPECT_NEAR(total_volume(r.model), 125, 125 * 1e-9);
  EXPECT_GT(r.model.blocks.size(), 500u);
}

Cut3dOptions through_only() {
  Cut3dOptions o;
  o.finite_fractures = FiniteFractures::Through;
  return o;
}

std::vector<double> body_volumes(const PolyhedronModel& m) {
  std::vector<double> v;
  for (const auto& b : m.bodies) v.push_back(b.volume);
  std::sort(v.begin(), v.end());
  return v;
}

TEST(Cut3d, DiscThatEndsInsideABlockLeavesItOneBody) {
  FractureModel m = empty_model(Vec3(0, 0, 0), Vec3(2, 1, 1), 2);
  // A disc in z = 0.5 of radius 0.8 about (0.5, 0.5): it covers the section
  // of [0, 1] x [0, 1] (corners 0.71 from its centre) but not of the box.
  m.fractures.push_back(disc(Vec3::UnitZ(), Vec3(0.5, 0.5, 0.5), 0.8, 0));
  {
    // through: the box stays one convex block.
    const auto r = cut_blocks_3d(m, through_only());
    EXPECT_EQ(r.model.blocks.size(), 1u);
    EXPECT_EQ(r.model.unfinished_cuts, 1);
  }
  {
    // glue: two convex parts of one body.
    const auto r = cut_blocks_3d(m);
    EXPECT_EQ(r.model.blocks.size(), 2u);
    ASSERT_EQ(r.model.bodies.size(), 1u);
    EXPECT_NEAR(r.model.bodies[0].volume, 2, 1e-12);
    EXPECT_EQ(r.model.unfinished_cuts, 1);
  }
  // A disc in x = 1 of radius 1 about the section's centre covers it (corners
  // 0.71 away): it halves the box, and then the first disc reaches through
  // the left half. Either order, either way, gives the same three bodies:
  // 0.5 + 0.5 on the left, 1 on the right (where the first disc ends 0.3 m in).
  const Fracture3 splitter = disc(Vec3::UnitX(), Vec3(1, 0.5, 0.5), 1.0, 1);
  for (int mode = 0; mode < 2; ++mode)
    for (int order = 0; order < 2; ++order) {
      FractureModel mm = m;
      if (order == 0) mm.fractures.push_back(splitter);
      else mm.fractures.insert(mm.fractures.begin(), splitter);
      const auto r = cut_blocks_3d(mm, mode == 0 ? Cut3dOptions{} : through_only());
      const auto v = body_volumes(r.model);
      ASSERT_EQ(v.size(), 3u) << "mode " << mode << " order " << order;
      EXPECT_NEAR(v[0], 0.5, 1e-12);
      EXPECT_NEAR(v[1], 0.5, 1e-12);
      EXPECT_NEAR(v[2], 1.0, 1e-12);
      EXPECT_EQ(r.model.unfinished_cuts, 1);
      for (const auto& b : r.model.blocks) expect_valid(b);
    }
}

TEST(Cut3d, IntersectingFiniteDiscsTogetherIsolateACornerBlock) {
  // Three discs of radius 0.8 in the planes x = 1, y = 1 and z = 1 of a
  // 2 m cube, each centred on the face its plane shares with the corner cube
  // [0, 1]^3: each covers that face (corners 0.71 away) and ends inside the
  // rest of the cube. Together they cut the corner cube out: bodies of 1 and
  // 7 m^3. No single disc reaches through the cube, so `through` cuts
  // nothing.
  FractureModel m = empty_model(Vec3(0, 0, 0), Vec3(2, 2, 2), 1);
  m.fractures.push_back(disc(Vec3::UnitX(), Vec3(1, 0.5, 0.5), 0.8));
  m.fractures.push_back(disc(Vec3::UnitY(), Vec3(0.5, 1, 0.5), 0.8));
  m.fractures.push_back(disc(Vec3::UnitZ(), Vec3(0.5, 0.5, 1), 0.8));
  const auto r = cut_blocks_3d(m);
  for (const auto& b : r.model.blocks) expect_valid(b);
  const auto v = body_volumes(r.model);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_NEAR(v[0], 1, 1e-12);
  EXPECT_NEAR(v[1], 7, 1e-12);
  EXPECT_EQ(r.model.unfinished_cuts, 3);
  EXPECT_EQ(cut_blocks_3d(m, through_only()).model.blocks.size(), 1u);
}

TEST(Cut3d, DiscMissingTheBlockIsNotCounted) {
  FractureModel m = empty_model(Vec3(0, 0, 0), Vec3(1, 1, 1), 1);
  m.fractures.push_back(disc(Vec3::UnitZ(), Vec3(3, 3, 0.5), 1.0));  // plane crosses, disc is away
  const auto r = cut_blocks_3d(m);
  EXPECT_EQ(r.model.blocks.size(), 1u);
  EXPECT_EQ(r.model.unfinished_cuts, 0);
}

TEST(Cut3d, PolygonFractureCutsWhenItCoversTheSection) {
  FractureModel m = empty_model(Vec3(0, 0, 0), Vec3(1, 1, 1), 1);
  Fracture3 f = plane(Vec3::UnitZ(), Vec3(0.5, 0.5, 0.3));
  f.shape = FractureShape::Polygon;
  f.vertices = {Vec3(-0.1, -0.1, 0.3), Vec3(1.2, -0.1, 0.3), Vec3(1.2, 1.1, 0.3), Vec3(-0.1, 1.1, 0.3)};
  m.fractures.push_back(f);
  auto r = cut_blocks_3d(m);
  ASSERT_EQ(r.model.bodies.size(), 2u);
  m.fractures[0].vertices[2] = Vec3(0.9, 1.1, 0.3);  // now it misses the corner (1, 1)
  r = cut_blocks_3d(m);
  EXPECT_EQ(r.model.bodies.size(), 1u);
  EXPECT_EQ(r.model.unfinished_cuts, 1);
  EXPECT_EQ(cut_blocks_3d(m, through_only()).model.blocks.size(), 1u);
}

Excavation3 square_tunnel_along_y(double x0, double x1, double z0, double z1) {
  Excavation3 e;
  e.name = "tunnel";
  e.region.half_spaces = {{-Vec3::UnitX(), -x0}, {Vec3::UnitX(), x1}, {-Vec3::UnitZ(), -z0}, {Vec3::UnitZ(), z1}};
  return e;
}

TEST(Cut3d, TunnelThroughABlockLeavesOneGluedRing) {
  FractureModel m = empty_model(Vec3(0, 0, 0), Vec3(4, 4, 4), 1);
  m.excavations.push_back(square_tunnel_along_y(1, 3, 1, 3));
  const auto r = cut_blocks_3d(m);
  for (const auto& b : r.model.blocks) expect_valid(b);
  EXPECT_NEAR(total_volume(r.model), 64 - 16, 1e-12);
  EXPECT_NEAR(r.model.excavated_volume, 16, 1e-12);
  ASSERT_EQ(r.model.bodies.size(), 1u);  // the ring around the tunnel is one body
  EXPECT_GE(r.model.bodies[0].parts.size(), 2u);
  int artificial = 0, excavation = 0;
  for (const auto& b : r.model.blocks)
    for (const auto& f : b.faces) artificial += f.set == kArtificialSet, excavation += f.set == kExcavationSet;
  EXPECT_GT(artificial, 0);
  EXPECT_GT(excavation, 0);
}

TEST(Cut3d, JointThroughTheTunnelSplitsTheRingAndBlockTheoryReadsIt) {
  // A horizontal joint at the tunnel's mid-height: a roof body (an upturned
  // U) and a floor body (a U). With the ground surface free, the roof body
  // can only lift off (removable, held by gravity); the floor body is locked
  // (tapered). With no free boundary the roof body is locked too.
  FractureModel m = empty_model(Vec3(0, 0, 0), Vec3(4, 4, 4), 1);
  m.fractures.push_back(plane(Vec3::UnitZ(), Vec3(0, 0, 2)));
  m.excavations.push_back(square_tunnel_along_y(1, 3, 1, 3));
  auto r = cut_blocks_3d(m);
  ASSERT_EQ(r.model.bodies.size(), 2u);
  for (const auto& body : r.model.bodies) {
    EXPECT_NEAR(body.volume, 24, 1e-12);
    const bool roof = r.model.blocks[static_cast<std::size_t>(body.parts[0])].centroid.z() > 2;
    EXPECT_EQ(body.removability, roof ? Removability::Removable : Removability::Tapered);
  }
  Cut3dOptions closed;
  closed.free_boundaries.clear();
  r = cut_blocks_3d(m, closed);
  for (const auto& body : r.model.bodies) EXPECT_EQ(body.removability, Removability::Tapered);
}

TEST(Cut3d, SeedWedgeHasTheExpectedVolumeAndNormals) {
  // Validation case V4: planes A 51.4/065.8 and B 51.4/295.2 through the
  // point T = (0, 0, 10) on the ground surface z = 10, and a vertical slope
  // face y = 10 (the open air north of it excavated). The block above both
  // planes, south of the face and below the ground is a tetrahedron whose
  // corners are T, the daylight point of the line of intersection on the
  // face, and the two points where the ground, the face and A (or B) meet.
  const Vec3 nA = dl::normal_from_dip(51.4, 65.8), nB = dl::normal_from_dip(51.4, 295.2);
  const Vec3 T(0, 0, 10);
  FractureModel m = empty_model(Vec3(-20, -5, 0), Vec3(20, 20, 10), 2);
  m.fractures.push_back(plane(nA, T, 0));
  m.fractures.push_back(plane(nB, T, 1));
  Excavation3 open_air;
  open_air.name = "slope";
  open_air.region.half_spaces = {{-Vec3::UnitY(), -10}};
  m.excavations.push_back(open_air);
  const auto r = cut_blocks_3d(m);
  for (const auto& b : r.model.blocks) expect_valid(b);
  EXPECT_NEAR(total_volume(r.model), 40 * 15 * 10, 6000 * 1e-12);

  // Corners by independent 3x3 solves of the bounding planes.
  auto meet = [](const Vec3& n1, double o1, const Vec3& n2, double o2, const Vec3& n3, double o3) {
    Eigen::Matrix3d M;
    M << n1.transpose(), n2.transpose(), n3.transpose();
    return Vec3(M.fullPivLu().solve(Vec3(o1, o2, o3)));
  };
  const double oA = nA.dot(T), oB = nB.dot(T);
  const Vec3 top = Vec3::UnitZ(), face = Vec3::UnitY();
  const Vec3 D = meet(nA, oA, nB, oB, face, 10), EA = meet(nA, oA, top, 10, face, 10), EB = meet(nB, oB, top, 10, face, 10);
  const double expected = std::abs((D - T).dot((EA - T).cross(EB - T))) / 6.0;

  const Polyhedron* wedge = nullptr;
  for (const auto& b : r.model.blocks)
    if (b.centroid.y() > 0 && b.centroid.y() < 10 && std::abs(b.centroid.x()) < 3 && b.faces.size() == 4) wedge = &b;
  ASSERT_NE(wedge, nullptr);
  EXPECT_NEAR(wedge->volume, expected, expected * 1e-12);
  EXPECT_TRUE(wedge->centroid.isApprox((T + D + EA + EB) / 4, 1e-12));
  // Face normals: -nA and -nB (the wedge rests on both planes), +y on the
  // slope face (excavation), +z on the ground (boundary).
  int matched = 0;
  for (const auto& f : wedge->faces) {
    if (f.set == 0) matched += f.normal.isApprox(-nA, 1e-12);
    if (f.set == 1) matched += f.normal.isApprox(-nB, 1e-12);
    if (f.set == kExcavationSet) matched += f.normal.isApprox(face, 1e-12);
    if (f.set == kBoundarySet) matched += f.normal.isApprox(top, 1e-12);
  }
  EXPECT_EQ(matched, 4);
  const auto& body = r.model.bodies[static_cast<std::size_t>(wedge->body)];
  EXPECT_EQ(body.removability, Removability::SlidesTwo);
  // Trend 000.5, plunge 27.63 (docs/validation.md V4).
  EXPECT_NEAR(rad2deg(std::asin(-body.sliding_direction.z())), 27.63, 0.01);
}

TEST(Cut3d, ADiscEndingInsideTheWedgeDoesNotHoldIt) {
  // The V4 wedge again, with a disc that crosses the wedge's nose and ends
  // inside it: the wedge becomes two glued parts of one body, and the faces
  // between them (a closed crack) must not count as contacts: the body
  // still slides on A and B.
  const Vec3 nA = dl::normal_from_dip(51.4, 65.8), nB = dl::normal_from_dip(51.4, 295.2);
  const Vec3 T(0, 0, 10);
  FractureModel m = empty_model(Vec3(-20, -5, 0), Vec3(20, 20, 10), 3);
  m.fractures.push_back(plane(nA, T, 0));
  m.fractures.push_back(plane(nB, T, 1));
  m.fractures.push_back(disc(Vec3(0, 1, 0.3), Vec3(0, 8, 7), 1.0, 2));
  Excavation3 open_air;
  open_air.region.half_spaces = {{-Vec3::UnitY(), -10}};
  m.excavations.push_back(open_air);
  const auto r = cut_blocks_3d(m);
  int sliding = 0;
  for (const auto& body : r.model.bodies)
    if (body.removability == Removability::SlidesTwo) {
      ++sliding;
      EXPECT_GE(body.parts.size(), 2u);  // the disc split it into glued parts
    }
  EXPECT_EQ(sliding, 1);
  EXPECT_EQ(r.model.unfinished_cuts, 1);
}

TEST(Cut3d, CoplanarAndCrossingFiniteFracturesStayValid) {
  // Degenerate finite input: two overlapping coplanar discs, a disc whose
  // rim passes through the box's corners, a polygon through an edge, and a
  // disc whose plane is a face of the box. Every part must be a valid convex
  // polyhedron and the parts must fill the box.
  FractureModel m = empty_model(Vec3(0, 0, 0), Vec3(1, 1, 1), 1);
  m.fractures.push_back(disc(Vec3::UnitZ(), Vec3(0.25, 0.5, 0.5), 0.6));
  m.fractures.push_back(disc(Vec3::UnitZ(), Vec3(0.75, 0.5, 0.5), 0.6));
  m.fractures.push_back(disc(Vec3::UnitX(), Vec3(0.5, 0.5, 0.5), std::sqrt(0.5)));  // rim through the corners
  Fracture3 p = plane(Vec3(1, 1, 0), Vec3(1, 0, 0));  // x + y = 1: through two vertical edges
  p.shape = FractureShape::Polygon;
  p.vertices = {Vec3(1.2, -0.2, -0.1), Vec3(-0.2, 1.2, -0.1), Vec3(-0.2, 1.2, 0.7), Vec3(1.2, -0.2, 0.7)};
  m.fractures.push_back(p);
  m.fractures.push_back(disc(Vec3::UnitY(), Vec3(0.5, 1, 0.5), 0.3));  // in the face y = 1
  for (int mode = 0; mode < 2; ++mode) {
    const auto r = cut_blocks_3d(m, mode == 0 ? Cut3dOptions{} : through_only());
    for (const auto& b : r.model.blocks) expect_valid(b);
    EXPECT_NEAR(total_volume(r.model), 1, 1e-12);
    double bodies = 0;
    for (const auto& b : r.model.bodies) bodies += b.volume;
    EXPECT_NEAR(bodies, 1, 1e-12);
  }
}

TEST(Cut3d, HolePointRemovesItsBody) {
  FractureModel m = empty_model(Vec3(0, 0, 0), Vec3(2, 1, 1), 1);
  m.fractures.push_back(plane(Vec3::UnitX(), Vec3(1, 0, 0)));
  m.points.push_back({"hole", PointKind::Hole, Vec3(1.5, 0.5, 0.5)});
  m.points.push_back({"mp", PointKind::Measurement, Vec3(0.5, 0.5, 0.5)});
  const auto r = cut_blocks_3d(m);
  ASSERT_EQ(r.model.blocks.size(), 1u);
  EXPECT_LT(r.model.blocks[0].centroid.x(), 1);
  EXPECT_NEAR(r.model.excavated_volume, 1, 1e-12);
  ASSERT_EQ(r.model.points.size(), 1u);
  EXPECT_EQ(r.model.points[0].name, "mp");
}

TEST(Cut3d, BadFractureIsAnInputErrorNamingIt) {
  FractureModel m = empty_model(Vec3(0, 0, 0), Vec3(1, 1, 1), 1);
  m.fractures.push_back(disc(Vec3::UnitZ(), Vec3(0.5, 0.5, 0.5), 1.0));
  m.fractures.push_back(disc(Vec3::UnitZ(), Vec3(0.5, 0.5, 0.5), 0.0));
  try {
    cut_blocks_3d(m);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("fracture 1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dda::dc
