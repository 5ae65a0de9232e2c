// Closed surfaces in the 3D cutter: a mesh domain gives the blocks of the
// rock inside it (convex or not), and a mesh excavation removes what lies
// inside it, both conserving volume.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "dc3d_test_util.hpp"
#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"
#include "dda/common/triangle_mesh.hpp"
#include "dda/dc/cut3d.hpp"

namespace dda::dc {
namespace {

using namespace test3;

// A box as 12 triangles, facing outward.
TriangleMesh box_mesh(const Vec3& lo, const Vec3& hi) {
  TriangleMesh m;
  for (int k = 0; k < 8; ++k)
    m.vertices.emplace_back((k & 1) ? hi.x() : lo.x(), (k & 2) ? hi.y() : lo.y(), (k & 4) ? hi.z() : lo.z());
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  return m;
}

TriangleMesh octahedron(const Vec3& c, double r) {
  TriangleMesh m;
  m.vertices = {c + Vec3(r, 0, 0), c - Vec3(r, 0, 0), c + Vec3(0, r, 0),
                c - Vec3(0, r, 0), c + Vec3(0, 0, r), c - Vec3(0, 0, r)};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

// A prism of `sides` faces round the axis from a to b (along y), its
// vertices on the circle of radius r: a tunnel, capped at both ends.
TriangleMesh tunnel_mesh(double x, double z, double y0, double y1, double r, int sides) {
  TriangleMesh m;
  for (double y : {y0, y1})
    for (int k = 0; k < sides; ++k) {
      const double a = 2 * kPi * k / sides;
      m.vertices.emplace_back(x + r * std::cos(a), y, z + r * std::sin(a));
    }
  for (int k = 0; k < sides; ++k) {
    const int a = k, b = (k + 1) % sides;
    m.triangles.push_back({a, b, b + sides});
    m.triangles.push_back({a, b + sides, a + sides});
  }
  for (int k = 1; k + 1 < sides; ++k) {  // the caps, fanned
    m.triangles.push_back({0, k + 1, k});
    m.triangles.push_back({sides, sides + k, sides + k + 1});
  }
  orient_outward(m);
  return m;
}

// Model with the domain box set to the mesh's bounding box.
FractureModel surface_model(const TriangleMesh& mesh, int sets) {
  const Box3 b = mesh_bounds(mesh);
  FractureModel m = empty_model(b.lo, b.hi, sets);
  m.domain_surface = mesh;
  return m;
}

void add_orthogonal_sets(FractureModel& m, double spacing, const Vec3& origin) {
  for (int axis = 0; axis < 3; ++axis)
    for (int i = -12; i <= 12; ++i) {
      Vec3 n = Vec3::Zero();
      n[axis] = 1;
      Vec3 p = origin;
      p[axis] += i * spacing;
      if (p[axis] > m.domain.lo[axis] && p[axis] < m.domain.hi[axis]) m.fractures.push_back(plane(n, p, axis));
    }
}

int count_faces(const PolyhedronModel& m, int set) {
  int n = 0;
  for (const auto& b : m.blocks)
    for (const auto& f : b.faces) n += f.set == set;
  return n;
}

TEST(Cut3dSurface, CubeMeshGivesTheBlocksOfTheBox) {
  const Vec3 lo(0, 0, 0), hi(10, 6, 4);
  FractureModel box = empty_model(lo, hi, 3);
  add_orthogonal_sets(box, 1.7, Vec3(0.3, 0.2, 0.1));
  FractureModel mesh = box;
  mesh.domain_surface = box_mesh(lo, hi);
  const auto a = cut_blocks_3d(box), b = cut_blocks_3d(mesh);
  ASSERT_EQ(a.model.blocks.size(), b.model.blocks.size());
  for (std::size_t i = 0; i < a.model.blocks.size(); ++i) {
    const Polyhedron &p = a.model.blocks[i], &q = b.model.blocks[i];
    EXPECT_EQ(p.vertices, q.vertices) << i;
    ASSERT_EQ(p.faces.size(), q.faces.size()) << i;
    for (std::size_t f = 0; f < p.faces.size(); ++f) {
      EXPECT_EQ(p.faces[f].vertices, q.faces[f].vertices);
      EXPECT_EQ(p.faces[f].set, q.faces[f].set);
    }
    EXPECT_EQ(p.volume, q.volume);
    EXPECT_EQ(p.body, q.body);
  }
  EXPECT_EQ(a.model.bodies.size(), b.model.bodies.size());
  EXPECT_NEAR(b.model.domain_volume, 240, 1e-12);
  EXPECT_EQ(b.report["outside_domain_surface_volume"].get<double>(), 0);
}

// A convex surface: every cut by its planes leaves the far side outside, so
// each block stays one convex body and its faces on the surface are boundary.
void expect_convex_domain(const TriangleMesh& surface, double spacing, const Vec3& origin) {
  FractureModel m = surface_model(surface, 3);
  add_orthogonal_sets(m, spacing, origin);
  const auto r = cut_blocks_3d(m);
  const double volume = enclosed_volume(surface);
  ASSERT_GT(r.model.blocks.size(), 10u);
  for (const auto& b : r.model.blocks) {
    expect_valid(b);
    EXPECT_TRUE(mesh_contains(surface, b.centroid));
  }
  EXPECT_NEAR(total_volume(r.model), volume, volume * 1e-9);
  EXPECT_NEAR(r.model.domain_volume, volume, volume * 1e-12);
  EXPECT_EQ(r.model.excavated_volume, 0);  // the box around it was never rock
  EXPECT_NEAR(r.report["outside_domain_surface_volume"].get<double>(), m.domain.volume() - volume, volume * 1e-9);
  EXPECT_EQ(count_faces(r.model, kArtificialSet), 0);
  EXPECT_EQ(r.model.bodies.size(), r.model.blocks.size());
  // Boundary faces off the box lie on the surface: their normals are the
  // surface's own.
  std::vector<Vec3> normals;
  for (const auto& t : surface.triangles)
    normals.push_back((surface.vertices[static_cast<std::size_t>(t[1])] - surface.vertices[static_cast<std::size_t>(t[0])])
                          .cross(surface.vertices[static_cast<std::size_t>(t[2])] - surface.vertices[static_cast<std::size_t>(t[0])])
                          .normalized());
  int on_surface = 0;
  for (const auto& b : r.model.blocks)
    for (const auto& f : b.faces) {
      if (f.set != kBoundarySet) continue;
      bool matched = false;
      for (const Vec3& n : normals) matched = matched || f.normal.isApprox(n, 1e-9);
      EXPECT_TRUE(matched) << "a boundary face off the surface";
      ++on_surface;
    }
  EXPECT_GT(on_surface, 0);
}

TEST(Cut3dSurface, OctahedronDomainWithThreeSets) {
  expect_convex_domain(octahedron(Vec3(1, 2, 3), 4), 1.1, Vec3(0.37, 0.21, 0.13));
}

TEST(Cut3dSurface, TetrahedronDomainWithThreeSets) {
  TriangleMesh tet;
  tet.vertices = {Vec3(0, 0, 0), Vec3(7, 1, 0.5), Vec3(2, 6, -0.5), Vec3(2.5, 2, 5)};
  tet.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  orient_outward(tet);
  expect_convex_domain(tet, 0.9, Vec3(0.05, 0.11, 0.17));
}

TEST(Cut3dSurface, SetsThroughTheSurfaceVerticesStayValid) {
  // Planes through the octahedron's corners and edges: degenerate contacts
  // with the surface's planes.
  expect_convex_domain(octahedron(Vec3(0, 0, 0), 2), 0.5, Vec3(0, 0, 0));
}

TEST(Cut3dSurface, LShapedDomainGluesTheCornerBody) {
  // The L [0, 2]^2 without [1, 2]^2, z in [0, 1]; a bed joint at z = 0.5
  // and a joint at x = 0.5. In each bed the strip x < 0.5 is one convex
  // block; the rest wraps round the inner corner: one body of glued parts.
  const TriangleMesh l = read_triangle_mesh(std::string(DDA_TEST_DATA_DIR) + "/mesh_lprism.obj");
  FractureModel m = surface_model(l, 2);
  m.fractures.push_back(plane(Vec3::UnitZ(), Vec3(0, 0, 0.5), 0));
  m.fractures.push_back(plane(Vec3::UnitX(), Vec3(0.5, 0, 0), 1));
  const auto r = cut_blocks_3d(m);
  for (const auto& b : r.model.blocks) expect_valid(b);
  EXPECT_NEAR(total_volume(r.model), 3, 3e-9);
  EXPECT_NEAR(r.model.domain_volume, 3, 1e-12);
  ASSERT_EQ(r.model.bodies.size(), 4u);
  int wrapped = 0;
  for (const auto& body : r.model.bodies) {
    const Polyhedron& first = r.model.blocks[static_cast<std::size_t>(body.parts[0])];
    const bool strip = first.centroid.x() < 0.5;
    EXPECT_NEAR(body.volume, strip ? 0.5 : 1.0, 1e-12);
    if (strip) {
      EXPECT_EQ(body.parts.size(), 1u);
      continue;
    }
    ++wrapped;
    EXPECT_GE(body.parts.size(), 2u);
    // The notch walls x = 1 and y = 1 face out of the rock: boundary faces
    // there, and a free surface, so the lower wrapped body is exposed while
    // the lower strip, inside the model's sides, is not.
    int walls = 0;
    for (int part : body.parts) {
      const Polyhedron& b = r.model.blocks[static_cast<std::size_t>(part)];
      for (const auto& f : b.faces) {
        if (f.set != kBoundarySet) continue;
        bool x1 = f.normal.isApprox(Vec3(1, 0, 0), 1e-12), y1 = f.normal.isApprox(Vec3(0, 1, 0), 1e-12);
        for (int v : f.vertices) {
          x1 = x1 && std::abs(b.vertices[static_cast<std::size_t>(v)].x() - 1) < 1e-12;
          y1 = y1 && std::abs(b.vertices[static_cast<std::size_t>(v)].y() - 1) < 1e-12;
        }
        walls += x1 || y1;
      }
    }
    EXPECT_GT(walls, 0);
    EXPECT_NE(body.removability, Removability::NotExposed);
  }
  EXPECT_EQ(wrapped, 2);
  EXPECT_GT(count_faces(r.model, kArtificialSet), 0);
  for (const auto& body : r.model.bodies) {
    const Polyhedron& first = r.model.blocks[static_cast<std::size_t>(body.parts[0])];
    if (first.centroid.x() < 0.5 && first.centroid.z() < 0.5) {
      EXPECT_EQ(body.removability, Removability::NotExposed);
    }
  }
}

TEST(Cut3dSurface, JointsOnTheSurfaceBecomeItsBoundary) {
  // Joints x = 1 and y = 1 run along the notch walls of the L: there they
  // are where the rock ends, so boundary (and free) faces, not joints.
  const TriangleMesh l = read_triangle_mesh(std::string(DDA_TEST_DATA_DIR) + "/mesh_lprism.obj");
  FractureModel m = surface_model(l, 2);
  m.fractures.push_back(plane(Vec3::UnitX(), Vec3(1, 0, 0), 0));
  m.fractures.push_back(plane(Vec3::UnitY(), Vec3(0, 1, 0), 1));
  m.fractures.push_back(plane(Vec3::UnitZ(), Vec3(0, 0, 0.5), 0));
  const auto r = cut_blocks_3d(m);
  EXPECT_NEAR(total_volume(r.model), 3, 3e-9);
  ASSERT_EQ(r.model.blocks.size(), 6u);
  int walls = 0, joints = 0;
  for (const auto& b : r.model.blocks) {
    expect_valid(b);
    for (const auto& f : b.faces) {
      Vec3 mid = Vec3::Zero();
      for (int v : f.vertices) mid += b.vertices[static_cast<std::size_t>(v)];
      mid /= static_cast<double>(f.vertices.size());
      const bool wall = (std::abs(mid.x() - 1) < 1e-12 && mid.y() > 1) || (std::abs(mid.y() - 1) < 1e-12 && mid.x() > 1);
      if (wall) {
        ++walls;
        EXPECT_EQ(f.set, kBoundarySet);
      }
      joints += f.set >= 0;
    }
  }
  EXPECT_EQ(walls, 4);
  EXPECT_GT(joints, 0);
  // In the lower bed, the blocks beside the notch face it (a free surface);
  // the corner block away from it does not.
  for (const auto& body : r.model.bodies) {
    const Vec3 c = r.model.blocks[static_cast<std::size_t>(body.parts[0])].centroid;
    if (c.z() > 0.5) continue;
    const bool beside_notch = c.x() > 1 || c.y() > 1;
    EXPECT_EQ(body.removability == Removability::NotExposed, !beside_notch) << c.transpose();
  }
}

TEST(Cut3dSurface, TunnelMeshThroughABoxWithAJointSet) {
  // A 24-sided tunnel along y, longer than the box, through a box with an
  // inclined joint set: the blocks and the opening make up the box, the
  // opening is the prism's section times the box's length, and the cut
  // agrees with the same tunnel given as a convex region.
  const Vec3 lo(0, 0, 0), hi(10, 8, 6);
  const double radius = 1.5;
  const int sides = 24;
  FractureModel m = empty_model(lo, hi, 1);
  const Vec3 n = Vec3(1, 0.2, 1).normalized();
  for (int i = -10; i <= 10; ++i) m.fractures.push_back(plane(n, Vec3(5, 4, 3) + (i + 0.31) * 1.3 * n, 0));
  FractureModel region = m;
  Excavation3 e;
  e.name = "tunnel";
  e.surface = tunnel_mesh(5, 3, -1, 9, radius, sides);
  m.excavations.push_back(e);
  const auto r = cut_blocks_3d(m);

  const double box = 480, section = 0.5 * sides * radius * radius * std::sin(2 * kPi / sides);
  for (const auto& b : r.model.blocks) expect_valid(b);
  EXPECT_NEAR(total_volume(r.model) + r.model.excavated_volume, box, box * 1e-9);
  EXPECT_NEAR(r.model.excavated_volume, section * 8, section * 8 * 1e-9);
  EXPECT_NEAR(r.model.domain_volume, box, 1e-12);
  // Faces on the opening look into it: towards the tunnel's axis.
  int opening = 0;
  for (const auto& b : r.model.blocks)
    for (const auto& f : b.faces) {
      if (f.set != kExcavationSet) continue;
      ++opening;
      const Vec3 at = b.vertices[static_cast<std::size_t>(f.vertices[0])];
      EXPECT_GT(f.normal.dot(Vec3(5 - at.x(), 0, 3 - at.z())), 0) << "points away from the opening";
      const double from_axis = std::hypot(at.x() - 5, at.z() - 3);
      EXPECT_GE(from_axis, radius * std::cos(kPi / sides) - 1e-9);
      EXPECT_LE(from_axis, radius + 1e-9);
    }
  EXPECT_GT(opening, 0);

  // The same prism as half-spaces.
  Excavation3 convex;
  convex.name = "tunnel";
  convex.region.half_spaces = {{-Vec3::UnitY(), 1}, {Vec3::UnitY(), 9}};
  for (int k = 0; k < sides; ++k) {
    const double a = 2 * kPi * (k + 0.5) / sides;
    const Vec3 dir(std::cos(a), 0, std::sin(a));
    convex.region.half_spaces.push_back({dir, dir.dot(Vec3(5, 0, 3)) + radius * std::cos(kPi / sides)});
  }
  region.excavations.push_back(convex);
  const auto c = cut_blocks_3d(region);
  EXPECT_NEAR(c.model.excavated_volume, r.model.excavated_volume, box * 1e-9);
  ASSERT_EQ(c.model.bodies.size(), r.model.bodies.size());
  std::vector<double> va, vb;
  for (const auto& body : r.model.bodies) va.push_back(body.volume);
  for (const auto& body : c.model.bodies) vb.push_back(body.volume);
  std::sort(va.begin(), va.end());
  std::sort(vb.begin(), vb.end());
  for (std::size_t i = 0; i < va.size(); ++i) EXPECT_NEAR(va[i], vb[i], box * 1e-9);
  std::size_t exposed = 0;
  for (const auto& body : r.model.bodies) exposed += body.removability != Removability::NotExposed;
  EXPECT_GT(exposed, 0u);
}

TEST(Cut3dSurface, MeshExcavationInsideAMeshDomain) {
  // A cave (octahedron) in an octahedral rock mass: what is left is the
  // difference of the two volumes.
  const TriangleMesh rock = octahedron(Vec3(0, 0, 0), 6), cave = octahedron(Vec3(0.3, -0.2, 0.1), 1.5);
  FractureModel m = surface_model(rock, 3);
  add_orthogonal_sets(m, 1.3, Vec3(0.1, 0.2, 0.3));
  Excavation3 e;
  e.name = "cave";
  e.surface = cave;
  m.excavations.push_back(e);
  const auto r = cut_blocks_3d(m);
  for (const auto& b : r.model.blocks) expect_valid(b);
  const double vr = enclosed_volume(rock), vc = enclosed_volume(cave);
  EXPECT_NEAR(r.model.excavated_volume, vc, vc * 1e-9);
  EXPECT_NEAR(total_volume(r.model), vr - vc, vr * 1e-9);
  EXPECT_GT(count_faces(r.model, kExcavationSet), 0);
}

TEST(Cut3dSurface, BrokenSurfacesAreInputErrors) {
  FractureModel m = surface_model(octahedron(Vec3(0, 0, 0), 1), 1);
  m.domain_surface->triangles.pop_back();
  try {
    cut_blocks_3d(m);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the domain surface: the surface is not closed"), std::string::npos) << e.what();
  }
  m = surface_model(octahedron(Vec3(0, 0, 0), 1), 1);
  m.domain.hi.x() = 0.5;  // the box must hold the surface
  EXPECT_THROW(cut_blocks_3d(m), InputError);
}

}  // namespace
}  // namespace dda::dc
