// Closed surfaces: the STL and OBJ readers agree, broken files are named
// with their line, and the inside test holds for non-convex shapes.
#include "dda/common/triangle_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "dda/common/error.hpp"
#include "input_error_of.hpp"

namespace {

using dda::TriangleMesh;
using dda::Vec3;

std::string data(const std::string& name) { return std::string(DDA_TEST_DATA_DIR) + "/" + name; }

template <class F>
std::string error_of(F&& f) {
  return dda::testing::input_error_of(std::forward<F>(f));
}

TEST(TriangleMesh, AsciiAndBinaryStlGiveTheSameMesh) {
  const TriangleMesh a = dda::read_triangle_mesh(data("mesh_cube.stl"));
  const TriangleMesh b = dda::read_triangle_mesh(data("mesh_cube_binary.stl"));
  EXPECT_EQ(a.vertices, b.vertices);  // corners shared, in the same order of first use
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.vertices.size(), 8u);
  EXPECT_EQ(a.triangles.size(), 12u);
  EXPECT_DOUBLE_EQ(dda::enclosed_volume(a), 8);
}

TEST(TriangleMesh, ObjQuadsAreFannedAndTurnedOutward) {
  // The OBJ cube has quads written inward, with v/vt/vn corners.
  const TriangleMesh obj = dda::read_triangle_mesh(data("mesh_cube.obj"));
  const TriangleMesh stl = dda::read_triangle_mesh(data("mesh_cube.stl"));
  ASSERT_EQ(obj.triangles.size(), 12u);
  EXPECT_DOUBLE_EQ(dda::enclosed_volume(obj), 8);
  // The same surface, though split along other diagonals: every triangle
  // of one lies in a face of the other with the same outward normal.
  auto normals = [](const TriangleMesh& m) {
    std::vector<std::array<double, 3>> n;
    for (const auto& t : m.triangles) {
      const Vec3 v = (m.vertices[static_cast<std::size_t>(t[1])] - m.vertices[static_cast<std::size_t>(t[0])])
                         .cross(m.vertices[static_cast<std::size_t>(t[2])] - m.vertices[static_cast<std::size_t>(t[0])])
                         .normalized();
      n.push_back({v.x(), v.y(), v.z()});
    }
    std::sort(n.begin(), n.end());
    return n;
  };
  EXPECT_EQ(normals(obj), normals(stl));
  const dda::Box3 box = dda::mesh_bounds(obj);
  EXPECT_EQ(box.lo, Vec3(0, 0, 0));
  EXPECT_EQ(box.hi, Vec3(2, 2, 2));
}

TEST(TriangleMesh, RelativeObjIdsAndANonConvexPrism) {
  const TriangleMesh m = dda::read_triangle_mesh(data("mesh_lprism.obj"));
  EXPECT_NEAR(dda::enclosed_volume(m), 3, 1e-15);
  EXPECT_TRUE(dda::mesh_contains(m, Vec3(0.5, 1.5, 0.5)));
  EXPECT_TRUE(dda::mesh_contains(m, Vec3(1.5, 0.5, 0.5)));
  EXPECT_FALSE(dda::mesh_contains(m, Vec3(1.5, 1.5, 0.5)));  // the notch
  EXPECT_FALSE(dda::mesh_contains(m, Vec3(0.5, 0.5, 1.5)));
  EXPECT_NEAR(dda::winding_number(m, Vec3(0.999, 0.999, 0.001)), 1, 1e-9);
  EXPECT_NEAR(dda::winding_number(m, Vec3(1.001, 1.001, 0.999)), 0, 1e-9);
}

TEST(TriangleMesh, OpenSurfaceIsRefusedNamingTheFileAndEdge) {
  const std::string e = error_of([] { dda::read_triangle_mesh(data("mesh_open.obj")); });
  EXPECT_NE(e.find("mesh_open.obj: the surface is not closed"), std::string::npos) << e;
  EXPECT_NE(e.find("belongs to one triangle only"), std::string::npos) << e;
}

TEST(TriangleMesh, BadObjIndexNamesTheFileAndLine) {
  const std::string e = error_of([] { dda::read_triangle_mesh(data("mesh_bad_index.obj")); });
  EXPECT_NE(e.find("mesh_bad_index.obj:10: vertex id 9 does not exist"), std::string::npos) << e;
}

TEST(TriangleMesh, OtherBrokenInputIsNamed) {
  EXPECT_NE(error_of([] { dda::read_triangle_mesh(data("no_such_mesh.stl")); }).find("no_such_mesh.stl: cannot open"),
            std::string::npos);
  EXPECT_NE(error_of([] { dda::read_triangle_mesh(data("dl_traces.csv")); }).find("(.stl or .obj)"), std::string::npos);
  // A surface with one triangle flipped runs an edge twice the same way.
  TriangleMesh tet;
  tet.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  tet.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  EXPECT_NO_THROW(dda::check_closed_surface(tet, "tet"));
  EXPECT_NEAR(dda::enclosed_volume(tet), 1.0 / 6.0, 1e-16);
  TriangleMesh flipped = tet;
  std::swap(flipped.triangles[3][1], flipped.triangles[3][2]);
  EXPECT_NE(error_of([&] { dda::check_closed_surface(flipped, "tet"); }).find("tet: the surface is not closed and oriented"),
            std::string::npos);
  TriangleMesh flat = tet;
  flat.vertices[3] = Vec3(0.2, 0.2, 0);
  EXPECT_NE(error_of([&] { dda::check_closed_surface(flat, "flat"); }).find("encloses no volume"), std::string::npos);
}

TEST(TriangleMesh, WindingNumberOfATetrahedron) {
  TriangleMesh tet;
  tet.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  tet.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  EXPECT_NEAR(dda::winding_number(tet, Vec3(0.1, 0.1, 0.1)), 1, 1e-12);
  EXPECT_NEAR(dda::winding_number(tet, Vec3(0.5, 0.5, 0.5)), 0, 1e-12);
  EXPECT_NEAR(dda::winding_number(tet, Vec3(-3, 2, 7)), 0, 1e-12);
  dda::orient_outward(tet);  // already outward: unchanged
  EXPECT_GT(dda::enclosed_volume(tet), 0);
  std::swap(tet.triangles[0][1], tet.triangles[0][2]);
  for (int k = 1; k < 4; ++k) std::swap(tet.triangles[static_cast<std::size_t>(k)][1], tet.triangles[static_cast<std::size_t>(k)][2]);
  EXPECT_NEAR(dda::winding_number(tet, Vec3(0.1, 0.1, 0.1)), -1, 1e-12);
  dda::orient_outward(tet);
  EXPECT_NEAR(dda::winding_number(tet, Vec3(0.1, 0.1, 0.1)), 1, 1e-12);
}

}  // namespace
