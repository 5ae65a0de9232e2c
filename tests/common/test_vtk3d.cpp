// ParaView files of the 3D pipeline, read back with a real XML parser.
#include "dda/common/vtk3d.hpp"

#include <gtest/gtest.h>
#include <tinyxml2.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "dda/common/error.hpp"
#include "dda/common/vtu_writer.hpp"

namespace fs = std::filesystem;
using dda::Vec3;

namespace {

class Vtk3dTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("dda-vtk3d-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

// A parsed .vtu: the Piece, its counts and every DataArray by name.
struct Vtu {
  tinyxml2::XMLDocument doc;
  const tinyxml2::XMLElement* piece = nullptr;
  std::size_t points = 0, cells = 0;

  // Parses `xml` (a gtest failure if it is not a VTK UnstructuredGrid).
  explicit Vtu(const std::string& xml) {
    if (doc.Parse(xml.c_str()) != tinyxml2::XML_SUCCESS) {
      ADD_FAILURE() << "not XML: " << doc.ErrorStr();
      return;
    }
    const tinyxml2::XMLElement* root = doc.RootElement();
    EXPECT_STREQ(root->Name(), "VTKFile");
    EXPECT_STREQ(root->Attribute("type"), "UnstructuredGrid");
    piece = root->FirstChildElement("UnstructuredGrid")->FirstChildElement("Piece");
    points = piece->Unsigned64Attribute("NumberOfPoints");
    cells = piece->Unsigned64Attribute("NumberOfCells");
  }
  Vtu(Vtu&&) = delete;  // piece points into doc

  // The DataArray called `name` in section `section` (Points, Cells, CellData).
  const tinyxml2::XMLElement* array(const char* section, const char* name) const {
    if (!piece) return nullptr;
    const tinyxml2::XMLElement* s = piece->FirstChildElement(section);
    for (auto* a = s ? s->FirstChildElement("DataArray") : nullptr; a;
         a = a->NextSiblingElement("DataArray"))
      if (std::string(a->Attribute("Name")) == name) return a;
    return nullptr;
  }
  std::vector<double> values(const char* section, const char* name) const {
    std::vector<double> v;
    const tinyxml2::XMLElement* a = array(section, name);
    if (!a) {
      ADD_FAILURE() << "no DataArray " << name << " in " << section;
      return v;
    }
    std::istringstream in(a->GetText() ? a->GetText() : "");
    for (double x; in >> x;) v.push_back(x);
    return v;
  }
  std::string text(const char* section, const char* name) const {
    std::string out;
    for (double x : values(section, name)) {
      std::ostringstream s;
      s << x;
      if (!out.empty()) out += ' ';
      out += s.str();
    }
    return out;
  }
};

Vtu parse_file(const std::string& p) {
  std::ifstream f(p);
  std::ostringstream s;
  s << f.rdbuf();
  return Vtu(s.str());
}

dda::Polyhedron unit_cube(double x0) {
  dda::Polyhedron p;
  for (int k = 0; k < 8; ++k) p.vertices.emplace_back(x0 + (k & 1), (k >> 1) & 1, (k >> 2) & 1);
  const std::vector<std::vector<int>> faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                               {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) p.faces.push_back({f, Vec3(0, 0, 0), -1});
  p.volume = 1;
  return p;
}

constexpr const char* kCubeFaces =
    "6 4 0 2 3 1 4 4 5 7 6 4 0 1 5 4 4 2 6 7 3 4 0 4 6 2 4 1 3 7 5";

TEST_F(Vtk3dTest, UnitCubeIsOnePolyhedronWithItsFaces) {
  dda::PolyhedronModel m;
  m.blocks = {unit_cube(0)};
  m.blocks[0].body = 0;
  m.blocks[0].layer = 2;
  m.bodies = {{{0}, 1, dda::Removability::Falls, Vec3(0, 0, -1)}};
  dda::write_polyhedra_vtu(path("b.vtu"), m);
  const Vtu v = parse_file(path("b.vtu"));
  EXPECT_EQ(v.points, 8u);
  EXPECT_EQ(v.cells, 1u);
  EXPECT_EQ(v.text("Points", "Points"),
            "0 0 0 1 0 0 0 1 0 1 1 0 0 0 1 1 0 1 0 1 1 1 1 1");
  EXPECT_EQ(v.text("Cells", "types"), "42");
  EXPECT_EQ(v.text("Cells", "connectivity"), "0 1 2 3 4 5 6 7");
  EXPECT_EQ(v.text("Cells", "offsets"), "8");
  EXPECT_EQ(v.text("Cells", "faces"), kCubeFaces);
  EXPECT_EQ(v.text("Cells", "faceoffsets"), "31");  // 1 + 6 x (1 + 4)
  EXPECT_STREQ(v.array("Cells", "faces")->Attribute("type"), "Int64");
  EXPECT_EQ(v.text("CellData", "block_id"), "0");
  EXPECT_EQ(v.text("CellData", "body"), "0");
  EXPECT_EQ(v.text("CellData", "volume"), "1");
  EXPECT_EQ(v.text("CellData", "layer"), "2");
  EXPECT_EQ(v.text("CellData", "removability"), "3");
}

TEST_F(Vtk3dTest, FacesUseGlobalPointIds) {
  dda::PolyhedronModel m;
  m.blocks = {unit_cube(0), unit_cube(1)};
  m.blocks[1].volume = 0.5;
  m.blocks[1].body = 7;  // no such body: removability -1
  m.bodies = {{{0}, 1, dda::Removability::SlidesOne, Vec3(1, 0, 0)}};
  dda::write_polyhedra_vtu(path("b.vtu"), m);
  const Vtu v = parse_file(path("b.vtu"));
  EXPECT_EQ(v.points, 16u);
  EXPECT_EQ(v.cells, 2u);
  EXPECT_EQ(v.text("Cells", "types"), "42 42");
  EXPECT_EQ(v.text("Cells", "offsets"), "8 16");
  EXPECT_EQ(v.text("Cells", "faceoffsets"), "31 62");
  const std::vector<double> faces = v.values("Cells", "faces");
  ASSERT_EQ(faces.size(), 62u);
  EXPECT_EQ(faces[31], 6);
  EXPECT_EQ(faces[32], 4);
  EXPECT_EQ(std::vector<double>(faces.begin() + 33, faces.begin() + 37),
            (std::vector<double>{8, 10, 11, 9}));
  EXPECT_EQ(v.text("CellData", "volume"), "1 0.5");
  EXPECT_EQ(v.text("CellData", "removability"), "4 -1");
}

TEST_F(Vtk3dTest, MixedCellsMarkTheOnesWithoutFaces) {
  dda::VtuGrid g;
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}) g.add_point(p);
  g.add_cell(3, dda::kVtkPolygon);
  const dda::Polyhedron c = unit_cube(5);
  for (const Vec3& p : c.vertices) g.add_point(p);
  std::vector<std::vector<int>> faces;
  for (const auto& f : c.faces) faces.push_back(f.vertices);
  g.add_polyhedron(8, faces);
  g.add_point(dda::Vec2(2, 3));  // a 2D point lies at z = 0
  g.add_point(Vec3(2, 3, 4));
  g.add_cell(2, dda::kVtkLine);
  const Vtu v(g.to_xml());
  EXPECT_EQ(v.text("Cells", "types"), "7 42 3");
  EXPECT_EQ(v.text("Cells", "faceoffsets"), "-1 31 -1");
  EXPECT_EQ(v.values("Cells", "faces")[2], 3);  // the cube's first face starts at point 3
  const std::vector<double> pts = v.values("Points", "Points");
  EXPECT_EQ(std::vector<double>(pts.end() - 6, pts.end()), (std::vector<double>{2, 3, 0, 2, 3, 4}));
  EXPECT_THROW(g.add_polyhedron(2, {{0, 1, 2}}), dda::InternalError);
}

TEST_F(Vtk3dTest, GridWithoutPolyhedraHasNoFaceArrays) {
  dda::VtuGrid g;
  g.add_point(Vec3(0, 0, 0));
  g.add_cell(1, dda::kVtkVertex);
  const Vtu v(g.to_xml());
  EXPECT_EQ(v.array("Cells", "faces"), nullptr);
  EXPECT_EQ(v.array("Cells", "faceoffsets"), nullptr);
}

// Polygon i of the fractures file: its points.
std::vector<Vec3> polygon(const Vtu& v, std::size_t i) {
  const std::vector<double> pts = v.values("Points", "Points");
  const std::vector<double> conn = v.values("Cells", "connectivity");
  const std::vector<double> off = v.values("Cells", "offsets");
  std::vector<Vec3> out;
  for (auto k = static_cast<std::size_t>(i ? off[i - 1] : 0); k < static_cast<std::size_t>(off[i]); ++k) {
    const auto p = static_cast<std::size_t>(conn[k]);
    out.emplace_back(pts[3 * p], pts[3 * p + 1], pts[3 * p + 2]);
  }
  return out;
}

// Twice the vector area: its direction is the normal the vertices turn about.
Vec3 area_vector(const std::vector<Vec3>& poly) {
  Vec3 a = Vec3::Zero();
  for (std::size_t k = 0; k < poly.size(); ++k) a += poly[k].cross(poly[(k + 1) % poly.size()]);
  return a;
}

TEST_F(Vtk3dTest, FracturesAsPolygons) {
  dda::FractureModel m;
  m.domain = {Vec3(0, 0, 0), Vec3(10, 20, 30)};
  dda::Fracture3 disc;
  disc.shape = dda::FractureShape::Disc;
  disc.normal = Vec3(0.6, 0, 0.8);
  disc.centre = Vec3(5, 5, 5);
  disc.radius = 2;
  disc.set = 1;
  disc.layer = 0;
  dda::Fracture3 plane;
  plane.shape = dda::FractureShape::Plane;
  plane.centre = Vec3(3, 3, 4);  // z = 4 across the whole box
  plane.kind = dda::LineKind::Bedding;
  dda::Fracture3 miss = plane;
  miss.centre = Vec3(0, 0, 31);  // above the box: no cell
  dda::Fracture3 poly;
  poly.shape = dda::FractureShape::Polygon;
  poly.normal = Vec3(0, 1, 0);
  poly.vertices = {Vec3(0, 5, 0), Vec3(0, 5, 2), Vec3(2, 5, 2), Vec3(2, 5, 0)};
  poly.set = 2;
  m.fractures = {disc, plane, miss, poly};
  dda::write_fractures_vtu(path("f.vtu"), m);
  const Vtu v = parse_file(path("f.vtu"));
  EXPECT_EQ(v.cells, 3u);
  EXPECT_EQ(v.points, 48u + 4u + 4u);
  EXPECT_EQ(v.text("Cells", "types"), "7 7 7");
  EXPECT_EQ(v.text("CellData", "fracture_id"), "0 1 3");
  EXPECT_EQ(v.text("CellData", "set"), "1 0 2");
  EXPECT_EQ(v.text("CellData", "kind"), "0 1 0");
  EXPECT_EQ(v.text("CellData", "shape"), "1 0 2");
  EXPECT_EQ(v.text("CellData", "layer"), "0 -1 -1");

  const std::vector<Vec3> d = polygon(v, 0);
  ASSERT_EQ(d.size(), 48u);
  for (const Vec3& p : d) {
    EXPECT_NEAR((p - disc.centre).norm(), 2, 1e-12);
    EXPECT_NEAR(disc.normal.dot(p - disc.centre), 0, 1e-12);
  }
  EXPECT_GT(area_vector(d).dot(disc.normal), 0);  // counter-clockwise about the normal

  const std::vector<Vec3> p = polygon(v, 1);
  ASSERT_EQ(p.size(), 4u);
  for (const Vec3& q : p) {
    EXPECT_NEAR(q.z(), 4, 1e-9);
    EXPECT_TRUE(m.domain.grown(1e-9).contains(q)) << q.transpose();
  }
  EXPECT_NEAR(area_vector(p).z() / 2, 200, 1e-9);

  EXPECT_EQ(polygon(v, 2), poly.vertices);
}

TEST_F(Vtk3dTest, ObliquePlaneIsCutByTheBox) {
  dda::FractureModel m;
  m.domain = {Vec3(0, 0, 0), Vec3(1, 1, 1)};
  dda::Fracture3 f;
  f.shape = dda::FractureShape::Plane;
  f.normal = Vec3(1, 1, 1).normalized();
  f.centre = Vec3(0.5, 0.5, 0.5);  // the regular hexagon through the cube's middle
  m.fractures = {f};
  dda::write_fractures_vtu(path("f.vtu"), m);
  const std::vector<Vec3> h = polygon(parse_file(path("f.vtu")), 0);
  ASSERT_EQ(h.size(), 6u);
  for (std::size_t k = 0; k < 6; ++k)
    EXPECT_NEAR((h[k] - h[(k + 1) % 6]).norm(), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(area_vector(h).dot(f.normal) / 2, 3 * std::sqrt(3.0) / 2 * 0.5, 1e-12);  // 3 sqrt(3) / 2 s^2
}

TEST_F(Vtk3dTest, SurfacesFollowTheFractures) {
  dda::FractureModel m;
  m.domain = {Vec3(0, 0, 0), Vec3(1, 1, 1)};
  dda::TriangleMesh tet;
  tet.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  tet.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  m.domain_surface = tet;
  dda::Excavation3 cave{"cave", {}, tet};
  m.excavations = {cave, dda::Excavation3{"box", dda::box_region(m.domain), {}}};
  dda::Fracture3 disc;
  disc.normal = Vec3(0, 0, 1);
  disc.centre = Vec3(0.5, 0.5, 0.5);
  disc.radius = 0.25;
  m.fractures = {disc};
  dda::write_fractures_vtu(path("f.vtu"), m);
  const Vtu v = parse_file(path("f.vtu"));
  EXPECT_EQ(v.cells, 9u);
  EXPECT_EQ(v.points, 48u + 24u);
  EXPECT_EQ(v.text("Cells", "types"), "7 5 5 5 5 5 5 5 5");
  EXPECT_EQ(v.text("CellData", "set"), "0 -1 -1 -1 -1 -2 -2 -2 -2");
  EXPECT_EQ(v.text("CellData", "shape"), "1 3 3 3 3 3 3 3 3");
  EXPECT_EQ(v.text("CellData", "fracture_id"), "0 -1 -1 -1 -1 -1 -1 -1 -1");
}

TEST_F(Vtk3dTest, EmptyModelsAreValid) {
  dda::write_fractures_vtu(path("f.vtu"), dda::FractureModel{});
  dda::write_polyhedra_vtu(path("b.vtu"), dda::PolyhedronModel{});
  for (const char* f : {"f.vtu", "b.vtu"}) {
    const Vtu v = parse_file(path(f));
    EXPECT_EQ(v.points, 0u) << f;
    EXPECT_EQ(v.cells, 0u) << f;
  }
  EXPECT_THROW(dda::write_polyhedra_vtu(path("no/b.vtu"), dda::PolyhedronModel{}), dda::InputError);
}

}  // namespace
