// 3D contact geometry (df/3d/contact3d_geometry.hpp). Expected distances are the
// gaps the blocks are placed at; the linearisation is checked against the
// distance recomputed from the moved vertices (move_point), whose error must
// fall as h^2.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "dda/df/3d/contact3d_geometry.hpp"

namespace dda::df3 {
namespace {

// Newell's normal of a planar loop, unit.
Vec3 loop_normal(const std::vector<Vec3>& v, const std::vector<int>& loop) {
  Vec3 n(0, 0, 0);
  for (size_t k = 0; k < loop.size(); ++k) n += v[loop[k]].cross(v[loop[(k + 1) % loop.size()]]);
  return n.normalized();
}

// Faces' normals and the centroid (mean of vertices: exact for boxes and
// for the tetrahedron's use here, where only T's reference point matters).
Polyhedron finish(std::vector<Vec3> vertices, const std::vector<std::vector<int>>& loops) {
  Polyhedron p;
  p.vertices = std::move(vertices);
  for (const auto& loop : loops) {
    PolyFace f;
    f.vertices = loop;
    f.normal = loop_normal(p.vertices, loop);
    p.faces.push_back(f);
  }
  for (const auto& v : p.vertices) p.centroid += v / static_cast<double>(p.vertices.size());
  return p;
}

// Box [lo, hi] rotated by R about its centre, then shifted by `shift`.
Polyhedron box(const Vec3& lo, const Vec3& hi, const Matrix3d& r = Matrix3d::Identity(), const Vec3& shift = Vec3::Zero()) {
  const Vec3 c = (lo + hi) / 2;
  std::vector<Vec3> v;
  for (int i = 0; i < 8; ++i) {
    const Vec3 x(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
    v.push_back(c + r * (x - c) + shift);
  }
  return finish(v, {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}});
}

Polyhedron moved(const Polyhedron& p, const Vector12d& d) {
  std::vector<Vec3> v;
  for (const auto& x : p.vertices) v.push_back(move_point(p.centroid, d, x));
  std::vector<std::vector<int>> loops;
  for (const auto& f : p.faces) loops.push_back(f.vertices);
  Polyhedron q = finish(v, loops);
  q.centroid = move_point(p.centroid, d, p.centroid);
  return q;
}

// The contact's distance recomputed exactly in the moved blocks.
double exact_dn(const ContactCandidate3& c, const Polyhedron& i, const Polyhedron& j) {
  if (c.kind == ContactKind3::VertexFace) {
    const PolyFace& f = j.faces[c.face];
    return loop_normal(j.vertices, f.vertices).dot(i.vertices[c.vertex] - j.vertices[f.vertices[0]]);
  }
  return edge_edge_geometry(i.vertices[c.edge_i[0]], i.vertices[c.edge_i[1]], i.centroid, j.vertices[c.edge_j[0]],
                            j.vertices[c.edge_j[1]], j.centroid, c.geo.normal)
      .dn0;
}

// |exact - linearised| after moving i by h di and j by h dj.
double lin_error(const ContactCandidate3& c, const Polyhedron& i, const Polyhedron& j, const Vector12d& di,
                 const Vector12d& dj, double h) {
  const double lin = c.geo.dn0 + h * (c.geo.en.dot(di) + c.geo.gn.dot(dj));
  return std::abs(exact_dn(c, moved(i, h * di), moved(j, h * dj)) - lin);
}

// Error ratio for h and h/2 is 4 for a second-order remainder.
void expect_second_order(const ContactCandidate3& c, const Polyhedron& i, const Polyhedron& j, const Vector12d& di,
                         const Vector12d& dj) {
  const double e1 = lin_error(c, i, j, di, dj, 1e-2), e2 = lin_error(c, i, j, di, dj, 5e-3);
  EXPECT_LT(e1, 1e-3);
  EXPECT_GT(e1, 1e-9) << "motion too special: the remainder vanished";
  EXPECT_NEAR(e1 / e2, 4.0, 0.3);
}

Vector12d motion(bool strain) {
  Vector12d d;
  d << 0.3, -0.2, 0.25, 0.4, -0.3, 0.5, 0, 0, 0, 0, 0, 0;
  if (strain) d.tail<6>() << 0.1, -0.2, 0.15, 0.3, -0.1, 0.2;
  return d;
}

const Polyhedron kBase = box({-1, -1, -1}, {2, 2, 0});

TEST(Contact3Geometry, CubeOnBoxGivesFourVertexFaceContactsAtTheGap) {
  for (double gap : {0.01, -0.001}) {
    const Polyhedron cube = box({0, 0, gap}, {1, 1, 1 + gap});
    const auto cs = find_contacts3(cube, kBase, {.reach = 0.05});
    ASSERT_EQ(cs.size(), 4u) << "gap " << gap;
    for (const auto& c : cs) {
      EXPECT_EQ(c.kind, ContactKind3::VertexFace);
      EXPECT_TRUE(c.a_is_i);
      EXPECT_LT(c.vertex, 4);  // the bottom vertices (z bit clear)
      EXPECT_EQ(c.face, 1);    // the base's top face
      EXPECT_NEAR(c.geo.dn0, gap, 1e-15);
      EXPECT_NEAR((c.geo.normal - Vec3(0, 0, 1)).norm(), 0, 1e-15);
      EXPECT_NEAR(c.geo.t1.cross(c.geo.t2).dot(c.geo.normal), 1, 1e-15);
    }
  }
}

TEST(Contact3Geometry, VertexFaceLinearisationIsSecondOrder) {
  const Polyhedron cube = box({0, 0, 0.01}, {1, 1, 1.01});
  const auto cs = find_contacts3(cube, kBase, {.reach = 0.05});
  ASSERT_FALSE(cs.empty());
  const Vector12d zero = Vector12d::Zero();
  for (bool strain : {false, true}) {
    SCOPED_TRACE(strain ? "with strain" : "rigid");
    expect_second_order(cs[0], cube, kBase, motion(strain), zero);   // vertex block moves
    expect_second_order(cs[0], cube, kBase, zero, motion(strain));   // face block moves (normal turns)
    expect_second_order(cs[0], cube, kBase, motion(strain), -0.7 * motion(strain));
  }
}

TEST(Contact3Geometry, ShearRowsAreTheTangentialRelativeMotion) {
  const Polyhedron cube = box({0, 0, 0.01}, {1, 1, 1.01});
  const auto cs = find_contacts3(cube, kBase, {.reach = 0.05});
  ASSERT_FALSE(cs.empty());
  const auto& g = cs[0].geo;
  Vector12d di = Vector12d::Zero(), dj = Vector12d::Zero();
  di[0] = 0.2, di[2] = 0.5;  // i slides +x (and lifts: no shear from that)
  dj[1] = 0.1;               // j slides +y
  const Eigen::Vector2d ds = g.es * di + g.gs * dj;
  const Vec3 rel(0.2, -0.1, 0);
  EXPECT_NEAR(ds[0], rel.dot(g.t1), 1e-15);
  EXPECT_NEAR(ds[1], rel.dot(g.t2), 1e-15);
}

// A cube rotated 45 deg about x has a ridge along x at its bottom, at
// sqrt(2)/2 below its centre; one rotated 45 deg about y a ridge along y at
// its top. Stacked, the ridges cross at right angles above the origin, at
// distance `gap`, at mid-edge (s = t = 1/2), normal +z (from the lower block
// j to the upper i).
TEST(Contact3Geometry, CrossedCubesGiveOneEdgeEdgeContact) {
  const double h = std::sqrt(0.5);
  const Vec3 lo(-0.5, -0.5, -0.5), hi(0.5, 0.5, 0.5);
  const Polyhedron lower = box(lo, hi, rotation_matrix({0, std::numbers::pi / 4, 0}));
  for (double gap : {0.01, -0.001}) {
    const Polyhedron upper = box(lo, hi, rotation_matrix({std::numbers::pi / 4, 0, 0}), {0, 0, 2 * h + gap});
    const auto cs = find_contacts3(upper, lower, {.reach = 0.05});
    ASSERT_EQ(cs.size(), 1u) << "gap " << gap;
    const auto& c = cs[0];
    EXPECT_EQ(c.kind, ContactKind3::EdgeEdge);
    EXPECT_NEAR(c.geo.dn0, gap, 1e-14);
    EXPECT_NEAR((c.geo.normal - Vec3(0, 0, 1)).norm(), 0, 1e-14);
    EXPECT_NEAR(c.geo.s, 0.5, 1e-12);
    EXPECT_NEAR(c.geo.t, 0.5, 1e-12);
    const Vector12d zero = Vector12d::Zero();
    for (bool strain : {false, true}) {
      SCOPED_TRACE(strain ? "with strain" : "rigid");
      expect_second_order(c, upper, lower, motion(strain), zero);
      expect_second_order(c, upper, lower, zero, motion(strain));
    }
  }
}

TEST(Contact3Geometry, NothingBeyondReach) {
  EXPECT_TRUE(find_contacts3(box({0, 0, 0.2}, {1, 1, 1.2}), kBase, {.reach = 0.05}).empty());
  const Vec3 lo(-0.5, -0.5, -0.5), hi(0.5, 0.5, 0.5);
  const Polyhedron lower = box(lo, hi, rotation_matrix({0, std::numbers::pi / 4, 0}));
  const Polyhedron upper = box(lo, hi, rotation_matrix({std::numbers::pi / 4, 0, 0}), {0, 0, std::sqrt(2.0) + 0.2});
  EXPECT_TRUE(find_contacts3(upper, lower, {.reach = 0.05}).empty());
}

// The apex of a downward tetrahedron exactly on the base's top edge x = 2 is
// at distance 0 from both the top face (+z) and the side face (+x) and
// projects onto both: one contact, on the top face, the one the block's
// edges at the apex stay above (they dip 35 deg into the side face).
TEST(Contact3Geometry, VertexOnFaceEdgeGivesOneContact) {
  const Polyhedron tet = finish({{2, 0.5, 0}, {1.5, 0, 1}, {2.3, 0.5, 1}, {1.5, 1, 1}},
                                {{0, 2, 1}, {0, 3, 2}, {0, 1, 3}, {1, 2, 3}});
  for (const auto& f : tet.faces) ASSERT_GT(f.normal.dot(tet.vertices[f.vertices[0]] - tet.centroid), 0);
  const auto cs = find_contacts3(tet, kBase, {.reach = 0.05});
  ASSERT_EQ(cs.size(), 1u);
  EXPECT_EQ(cs[0].vertex, 0);
  EXPECT_EQ(cs[0].face, 1);
  EXPECT_NEAR(cs[0].geo.dn0, 0, 1e-15);

  // A cube flush with the base's edge: its two vertices on that edge take the
  // top face only, so face-face still gives four contacts, not six.
  const auto flush = find_contacts3(box({1, 0.5, 0}, {2, 1.5, 1}), kBase, {.reach = 0.05});
  ASSERT_EQ(flush.size(), 4u);
  for (const auto& c : flush) EXPECT_EQ(c.face, 1);
}

}  // namespace
}  // namespace dda::df3
