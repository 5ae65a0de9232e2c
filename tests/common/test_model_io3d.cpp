// The 3D HDF5 files: every field round-trips bit for bit, and every broken
// file is an InputError that names it.
#include "dda/common/model_io3d.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "dda/common/error.hpp"
#include "dda/common/model_io.hpp"
#include "dda/common/triangle_mesh.hpp"
#include "scratch_dir_test.hpp"

namespace fs = std::filesystem;
using dda::Vec3;

namespace {

class ModelIo3dTest : public dda::testing::ScratchDirTest {
 protected:
  ModelIo3dTest() : ScratchDirTest("dda-model-io3") {}
  // Runs a Python script (argv[1] = the test folder) to make foreign files;
  // false when /usr/bin/python3 with h5py is not there.
  bool run_python(const std::string& code) {
    if (std::system("/usr/bin/python3 -c 'import h5py' >/dev/null 2>&1") != 0) return false;
    const std::string script = path("make.py");
    std::ofstream(script) << code;
    return std::system(("/usr/bin/python3 " + script + " " + dir_.string()).c_str()) == 0;
  }
};

dda::Provenance sample_provenance() {
  dda::Provenance p;
  p.program_version = "9.8.7-test";
  p.scenario_path = "examples/slope3d/scenario.yaml";
  p.scenario_text = "# Böschung — 3D\nseed: 7\n";
  p.seed = 18446744073709551557ULL;
  p.created_utc = "2024-05-06T07:08:09Z";
  return p;
}

std::vector<dda::Layer> sample_layers() { return {{0, 4, 1.5, 1.25}, {4, 10.5, 0, 2.5}}; }

std::vector<dda::ModelPoint3> sample_points() {
  return {{"fix Ω", dda::PointKind::Fixed, Vec3(0.5, 0.5, 0)},
          {"M1", dda::PointKind::Measurement, Vec3(1.0 / 3.0, 2, 1e-300)},
          {"load", dda::PointKind::Load, Vec3(-1, 9, 3)}};
}

dda::FractureModel sample_fractures() {
  dda::FractureModel m;
  m.domain = {Vec3(-1, 0, -2.5), Vec3(10, 20, 30)};
  dda::Excavation3 tunnel{"tunnel 1", {}, {}};
  tunnel.region.half_spaces = {{Vec3(1, 0, 0), 6}, {Vec3(-1, 0, 0), -4}, {Vec3(0, 0, 1), 12},
                               {Vec3(0, 0, -2), -16}, {Vec3(0.6, 0, 0.8), 11.1}};
  dda::Excavation3 air{"open air", {}, {}};
  air.region.half_spaces = {{Vec3(0, -std::sqrt(0.5), std::sqrt(0.5)), 1.0 / 7.0}};
  m.excavations = {tunnel, air};

  dda::Fracture3 plane;
  plane.shape = dda::FractureShape::Plane;
  plane.normal = Vec3(0, 0, 1);
  plane.centre = Vec3(0, 0, 4);
  plane.set = 0;
  plane.kind = dda::LineKind::Bedding;
  dda::Fracture3 disc;
  disc.shape = dda::FractureShape::Disc;
  disc.normal = Vec3(0.6, 0, 0.8);
  disc.centre = Vec3(5, 10.1, 2.0 / 3.0);
  disc.radius = 2.75;
  disc.set = 1;
  disc.layer = 1;
  dda::Fracture3 poly;
  poly.shape = dda::FractureShape::Polygon;
  poly.normal = Vec3(0, 1, 0);
  poly.centre = Vec3(1, 5, 1);
  poly.vertices = {Vec3(0, 5, 0), Vec3(2, 5, 0), Vec3(2, 5, 2), Vec3(1, 5, 2.5), Vec3(0, 5, 2)};
  poly.set = 2;
  poly.layer = 0;
  dda::Fracture3 reserved = disc;
  reserved.set = dda::kArtificialSet;
  reserved.radius = 0.1;
  m.fractures = {plane, disc, poly, reserved};
  m.sets = {{"Schichtung", "bedding"}, {"J1 節理", "statistical"}, {"user", "user"}};
  m.points = sample_points();
  m.layers = sample_layers();
  m.bed_normal = Vec3(0.1, -0.2, std::sqrt(0.95));
  m.provenance = sample_provenance();
  return m;
}

// An octahedron about c with half-diagonal r, triangles facing outward.
dda::TriangleMesh octahedron(const Vec3& c, double r) {
  dda::TriangleMesh m;
  m.vertices = {c + Vec3(r, 0, 0), c - Vec3(r, 0, 0), c + Vec3(0, r, 0),
                c - Vec3(0, r, 0), c + Vec3(0, 0, r), c - Vec3(0, 0, r)};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

// sample_fractures() with a surface domain and two surface excavations,
// one of them also a region, around a plain one.
dda::FractureModel sample_with_surfaces() {
  dda::FractureModel m = sample_fractures();
  m.domain_surface = octahedron(Vec3(4.5, 10, 13.75), 5.5);
  m.domain_surface->vertices[0].x() = 10;  // bit-exact values that are not round
  m.domain_surface->vertices[1].x() = -1.0 / 3.0;
  dda::Excavation3 cave{"cave", {}, octahedron(Vec3(2, 3, 4), 0.75)};
  m.excavations.insert(m.excavations.begin(), cave);
  m.excavations.back().surface = octahedron(Vec3(5, 5, 5), 1e-3);
  return m;
}

// The unit cube [x0, x0+1] x [0, 1] x [0, 1], faces counter-clockwise seen
// from outside, with the set of each face given.
dda::Polyhedron cube(double x0, const std::vector<int>& sets) {
  dda::Polyhedron p;
  for (int k = 0; k < 8; ++k) p.vertices.emplace_back(x0 + (k & 1), (k >> 1) & 1, (k >> 2) & 1);
  const std::vector<std::vector<int>> faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                               {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  const std::vector<Vec3> normals = {Vec3(0, 0, -1), Vec3(0, 0, 1), Vec3(0, -1, 0),
                                     Vec3(0, 1, 0),  Vec3(-1, 0, 0), Vec3(1, 0, 0)};
  for (std::size_t f = 0; f < 6; ++f) p.faces.push_back({faces[f], normals[f], sets[f]});
  p.volume = 1;
  p.centroid = Vec3(x0 + 0.5, 0.5, 0.5);
  p.second_moment = Eigen::Matrix3d::Identity() / 12.0;
  return p;
}

dda::Polyhedron tetrahedron() {
  dda::Polyhedron p;
  p.vertices = {Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1, 1), Vec3(0, 0, 2)};
  p.faces = {{{0, 2, 1}, Vec3(0, 0, -1), -1},
             {{0, 1, 3}, Vec3(0, -1, 0), 0},
             {{0, 3, 2}, Vec3(-1, 0, 0), -2},
             {{1, 2, 3}, Vec3(1, 1, 1).normalized(), -3}};
  p.volume = 1.0 / 6.0;
  p.centroid = Vec3(0.25, 0.25, 1.25);
  p.second_moment << 1, 2, 3, 4, 5, 6, 7, 8, 9.5;  // not symmetric: stored as written
  p.second_moment /= 120.0;
  return p;
}

dda::PolyhedronModel sample_polyhedra() {
  dda::PolyhedronModel m;
  dda::Polyhedron a = cube(0, {-1, 0, 1, -3, -1, 0});
  a.body = 0;
  a.layer = 0;
  dda::Polyhedron b = cube(1, {1, 1, -2, 0, 0, -1});
  b.body = 0;
  b.layer = 1;
  dda::Polyhedron c = tetrahedron();
  c.body = 1;
  c.layer = -1;
  m.blocks = {a, b, c};
  m.bodies = {{{0, 1}, 2, dda::Removability::SlidesTwo, Vec3(0.6, 0, -0.8)},
              {{2}, 1.0 / 6.0, dda::Removability::Tapered, Vec3(0, 0, 0)}};
  m.sets = {{"Schichtung", "bedding"}, {"J1", "statistical"}};
  m.points = sample_points();
  m.layers = sample_layers();
  m.bed_normal = Vec3(0, std::sqrt(0.5), std::sqrt(0.5));
  m.domain = {Vec3(0, 0, 0), Vec3(2, 1, 2)};
  m.domain_volume = 4;
  m.excavated_volume = 0.25;
  m.unfinished_cuts = 3;
  m.provenance = sample_provenance();
  return m;
}

// ---------------------------------------------------------------- comparing

void expect_same(const dda::Provenance& a, const dda::Provenance& b) {
  EXPECT_EQ(a.program_version, b.program_version);
  EXPECT_EQ(a.scenario_path, b.scenario_path);
  EXPECT_EQ(a.scenario_text, b.scenario_text);
  EXPECT_EQ(a.seed, b.seed);
  EXPECT_EQ(a.created_utc, b.created_utc);
}

template <class Model>
void expect_same_common(const Model& a, const Model& b) {
  ASSERT_EQ(a.sets.size(), b.sets.size());
  for (std::size_t i = 0; i < a.sets.size(); ++i) {
    EXPECT_EQ(a.sets[i].name, b.sets[i].name);
    EXPECT_EQ(a.sets[i].origin, b.sets[i].origin);
  }
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    EXPECT_EQ(a.points[i].name, b.points[i].name);
    EXPECT_EQ(a.points[i].kind, b.points[i].kind);
    EXPECT_EQ(a.points[i].p, b.points[i].p);
  }
  ASSERT_EQ(a.layers.size(), b.layers.size());
  for (std::size_t i = 0; i < a.layers.size(); ++i) {
    EXPECT_EQ(a.layers[i].bottom, b.layers[i].bottom);
    EXPECT_EQ(a.layers[i].top, b.layers[i].top);
    EXPECT_EQ(a.layers[i].target_fsi, b.layers[i].target_fsi);
    EXPECT_EQ(a.layers[i].realised_fsi, b.layers[i].realised_fsi);
  }
  EXPECT_EQ(a.bed_normal, b.bed_normal);
  EXPECT_EQ(a.domain.lo, b.domain.lo);
  EXPECT_EQ(a.domain.hi, b.domain.hi);
  expect_same(a.provenance, b.provenance);
}

void expect_same(const std::optional<dda::TriangleMesh>& a, const std::optional<dda::TriangleMesh>& b) {
  ASSERT_EQ(a.has_value(), b.has_value());
  if (!a) return;
  EXPECT_EQ(a->vertices, b->vertices);
  EXPECT_EQ(a->triangles, b->triangles);
}

void expect_same(const dda::FractureModel& a, const dda::FractureModel& b) {
  expect_same(a.domain_surface, b.domain_surface);
  ASSERT_EQ(a.excavations.size(), b.excavations.size());
  for (std::size_t i = 0; i < a.excavations.size(); ++i) {
    EXPECT_EQ(a.excavations[i].name, b.excavations[i].name);
    expect_same(a.excavations[i].surface, b.excavations[i].surface);
    const auto &x = a.excavations[i].region.half_spaces, &y = b.excavations[i].region.half_spaces;
    ASSERT_EQ(x.size(), y.size());
    for (std::size_t k = 0; k < x.size(); ++k) {
      EXPECT_EQ(x[k].normal, y[k].normal);
      EXPECT_EQ(x[k].offset, y[k].offset);
    }
  }
  ASSERT_EQ(a.fractures.size(), b.fractures.size());
  for (std::size_t i = 0; i < a.fractures.size(); ++i) {
    const dda::Fracture3 &x = a.fractures[i], &y = b.fractures[i];
    EXPECT_EQ(x.shape, y.shape) << i;
    EXPECT_EQ(x.normal, y.normal) << i;
    EXPECT_EQ(x.centre, y.centre) << i;
    EXPECT_EQ(x.radius, y.radius) << i;
    EXPECT_EQ(x.vertices, y.vertices) << i;
    EXPECT_EQ(x.set, y.set) << i;
    EXPECT_EQ(x.kind, y.kind) << i;
    EXPECT_EQ(x.layer, y.layer) << i;
  }
  expect_same_common(a, b);
}

void expect_same(const dda::PolyhedronModel& a, const dda::PolyhedronModel& b) {
  ASSERT_EQ(a.blocks.size(), b.blocks.size());
  for (std::size_t i = 0; i < a.blocks.size(); ++i) {
    const dda::Polyhedron &x = a.blocks[i], &y = b.blocks[i];
    EXPECT_EQ(x.vertices, y.vertices) << i;
    ASSERT_EQ(x.faces.size(), y.faces.size()) << i;
    for (std::size_t f = 0; f < x.faces.size(); ++f) {
      EXPECT_EQ(x.faces[f].vertices, y.faces[f].vertices) << i << " " << f;
      EXPECT_EQ(x.faces[f].normal, y.faces[f].normal) << i << " " << f;
      EXPECT_EQ(x.faces[f].set, y.faces[f].set) << i << " " << f;
    }
    EXPECT_EQ(x.volume, y.volume) << i;
    EXPECT_EQ(x.centroid, y.centroid) << i;
    EXPECT_EQ(x.second_moment, y.second_moment) << i;
    EXPECT_EQ(x.body, y.body) << i;
    EXPECT_EQ(x.layer, y.layer) << i;
  }
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  for (std::size_t k = 0; k < a.bodies.size(); ++k) {
    EXPECT_EQ(a.bodies[k].parts, b.bodies[k].parts);
    EXPECT_EQ(a.bodies[k].volume, b.bodies[k].volume);
    EXPECT_EQ(a.bodies[k].removability, b.bodies[k].removability);
    EXPECT_EQ(a.bodies[k].sliding_direction, b.bodies[k].sliding_direction);
  }
  EXPECT_EQ(a.domain_volume, b.domain_volume);
  EXPECT_EQ(a.excavated_volume, b.excavated_volume);
  EXPECT_EQ(a.unfinished_cuts, b.unfinished_cuts);
  expect_same_common(a, b);
}

// --------------------------------------------------------------- round trips

TEST_F(ModelIo3dTest, FracturesRoundTripAllFields) {
  const dda::FractureModel m = sample_fractures();
  dda::write_fractures_h5(path("f.h5"), m);
  expect_same(m, dda::read_fractures_h5(path("f.h5")));
  EXPECT_EQ(dda::h5_format_of(path("f.h5")), "dda-fractures");
  EXPECT_EQ(listing(), std::vector<std::string>{"f.h5"});  // no temporary left
}

TEST_F(ModelIo3dTest, SurfacesRoundTrip) {
  const dda::FractureModel m = sample_with_surfaces();
  dda::write_fractures_h5(path("f.h5"), m);
  const dda::FractureModel back = dda::read_fractures_h5(path("f.h5"));
  expect_same(m, back);
  EXPECT_FALSE(back.excavations[1].surface.has_value());
  EXPECT_TRUE(back.excavations[2].surface.has_value());
}

TEST_F(ModelIo3dTest, SurfacesAreCheckedAndTurnedOutwardOnReading) {
  dda::FractureModel m = sample_with_surfaces();
  for (auto& t : m.domain_surface->triangles) std::swap(t[0], t[1]);  // inward
  dda::write_fractures_h5(path("f.h5"), m);
  const dda::FractureModel back = dda::read_fractures_h5(path("f.h5"));
  EXPECT_GT(dda::enclosed_volume(*back.domain_surface), 0);

  m = sample_with_surfaces();
  m.excavations[0].surface->triangles.pop_back();  // a hole
  dda::write_fractures_h5(path("f.h5"), m);
  const std::string msg = error_of([&] { dda::read_fractures_h5(path("f.h5")); });
  EXPECT_EQ(msg.rfind(path("f.h5") + ": the surface of excavation 0 ('cave'): the surface is not closed", 0), 0u)
      << msg;

  m = sample_with_surfaces();
  m.domain_surface->triangles[2][1] = 6;  // six vertices: 0..5
  dda::write_fractures_h5(path("f.h5"), m);
  EXPECT_EQ(error_of([&] { dda::read_fractures_h5(path("f.h5")); }),
            path("f.h5") + ": the domain surface in /domain/surface: triangle 3 names vertex 7, which does not "
                           "exist (there are 6).");
}

TEST_F(ModelIo3dTest, EmptyFractureModelRoundTrips) {
  dda::FractureModel m;
  m.provenance.created_utc = "2000-01-01T00:00:00Z";
  m.provenance.program_version = "x";
  dda::write_fractures_h5(path("f.h5"), m);
  expect_same(m, dda::read_fractures_h5(path("f.h5")));
}

TEST_F(ModelIo3dTest, PolyhedraRoundTripAllFields) {
  const dda::PolyhedronModel m = sample_polyhedra();
  dda::write_polyhedra_h5(path("b.h5"), m);
  expect_same(m, dda::read_polyhedra_h5(path("b.h5")));
  EXPECT_EQ(dda::h5_format_of(path("b.h5")), "dda-blocks3d");
}

TEST_F(ModelIo3dTest, EmptyPolyhedronModelRoundTrips) {
  dda::PolyhedronModel m;
  m.provenance.created_utc = "2000-01-01T00:00:00Z";
  m.provenance.program_version = "x";
  dda::write_polyhedra_h5(path("b.h5"), m);
  expect_same(m, dda::read_polyhedra_h5(path("b.h5")));
}

TEST_F(ModelIo3dTest, BlocksWithoutBodiesKeepTheirBodyIndex) {
  dda::PolyhedronModel m = sample_polyhedra();
  m.bodies.clear();  // a cutter that has not grouped its blocks yet
  dda::write_polyhedra_h5(path("b.h5"), m);
  expect_same(m, dda::read_polyhedra_h5(path("b.h5")));
}

TEST_F(ModelIo3dTest, WriterFillsVersionAndCreationTime) {
  dda::write_polyhedra_h5(path("b.h5"), dda::PolyhedronModel{});
  const dda::Provenance p = dda::read_polyhedra_h5(path("b.h5")).provenance;
  EXPECT_EQ(p.program_version, dda::version_string());
  EXPECT_EQ(p.created_utc.size(), 20u) << p.created_utc;
}

// ------------------------------------------------------------------- errors

TEST_F(ModelIo3dTest, WrongFormatNamesBothFormats) {
  dda::write_polyhedra_h5(path("b.h5"), sample_polyhedra());
  dda::write_fractures_h5(path("f.h5"), sample_fractures());
  EXPECT_EQ(error_of([&] { dda::read_fractures_h5(path("b.h5")); }),
            path("b.h5") + ": is a dda-blocks3d file, expected a dda-fractures file.");
  EXPECT_EQ(error_of([&] { dda::read_polyhedra_h5(path("f.h5")); }),
            path("f.h5") + ": is a dda-fractures file, expected a dda-blocks3d file.");
  dda::write_lines_h5(path("l.h5"), dda::LineModel{});
  EXPECT_EQ(error_of([&] { dda::read_fractures_h5(path("l.h5")); }),
            path("l.h5") + ": is a dda-lines file, expected a dda-fractures file.");
  EXPECT_EQ(error_of([&] { dda::read_blocks_h5(path("b.h5")); }),
            path("b.h5") + ": is a dda-blocks3d file, expected a dda-blocks file.");
}

TEST_F(ModelIo3dTest, MissingAndGarbageFilesAreNamed) {
  EXPECT_EQ(error_of([&] { dda::read_fractures_h5(path("nope.h5")); }),
            path("nope.h5") + ": file not found.");
  EXPECT_EQ(error_of([&] { dda::read_polyhedra_h5(path("nope.h5")); }),
            path("nope.h5") + ": file not found.");
  std::ofstream(path("junk.h5"), std::ios::binary) << "not HDF5 at all";
  EXPECT_EQ(error_of([&] { dda::read_polyhedra_h5(path("junk.h5")); }),
            path("junk.h5") + ": is not an HDF5 file.");
}

TEST_F(ModelIo3dTest, WriteIntoMissingFolderIsAnInputError) {
  const std::string p = path("missing/f.h5");
  EXPECT_NE(error_of([&] { dda::write_fractures_h5(p, sample_fractures()); }).find(p),
            std::string::npos);
}

TEST_F(ModelIo3dTest, OutOfRangeIndicesAreNamed) {
  dda::FractureModel f = sample_fractures();
  f.fractures[2].layer = 5;  // two layers
  dda::write_fractures_h5(path("f.h5"), f);
  std::string msg = error_of([&] { dda::read_fractures_h5(path("f.h5")); });
  EXPECT_EQ(msg, path("f.h5") + ": dataset /fractures/layer entry 2 is 5, must be between -1 and 1.");

  dda::PolyhedronModel p = sample_polyhedra();
  p.blocks[1].faces[2].vertices[1] = 8;  // a cube has 8 vertices: 0..7
  dda::write_polyhedra_h5(path("b.h5"), p);
  msg = error_of([&] { dda::read_polyhedra_h5(path("b.h5")); });
  EXPECT_EQ(msg, path("b.h5") + ": dataset /faces/vertices entry 33 is 8, but the block of face 8 "
                                "has 8 vertices.");

  p = sample_polyhedra();
  p.blocks[2].body = 2;  // two bodies
  dda::write_polyhedra_h5(path("b.h5"), p);
  msg = error_of([&] { dda::read_polyhedra_h5(path("b.h5")); });
  EXPECT_EQ(msg, path("b.h5") + ": dataset /blocks/body entry 2 is 2, must be between -1 and 1.");

  p = sample_polyhedra();
  p.bodies[1].parts = {3};
  dda::write_polyhedra_h5(path("b.h5"), p);
  msg = error_of([&] { dda::read_polyhedra_h5(path("b.h5")); });
  EXPECT_EQ(msg, path("b.h5") + ": dataset /bodies/parts entry 2 is 3, must be between 0 and 2.");
}

TEST_F(ModelIo3dTest, ShapesMustMatchTheirOutlines) {
  dda::FractureModel f = sample_fractures();
  f.fractures[2].vertices.resize(2);  // a polygon of two vertices
  dda::write_fractures_h5(path("f.h5"), f);
  EXPECT_EQ(error_of([&] { dda::read_fractures_h5(path("f.h5")); }),
            path("f.h5") + ": fracture 2 is a polygon with 2 vertices in /fractures/offsets (a "
                           "polygon needs at least 3).");
  f = sample_fractures();
  f.fractures[1].vertices = {Vec3(0, 0, 0)};  // a disc with an outline
  dda::write_fractures_h5(path("f.h5"), f);
  EXPECT_EQ(error_of([&] { dda::read_fractures_h5(path("f.h5")); }),
            path("f.h5") + ": fracture 1 is a disc with 1 vertices in /fractures/offsets (only "
                           "polygons have vertices).");
  dda::PolyhedronModel p = sample_polyhedra();
  p.blocks[2].faces.pop_back();  // three faces cannot close a block
  dda::write_polyhedra_h5(path("b.h5"), p);
  EXPECT_EQ(error_of([&] { dda::read_polyhedra_h5(path("b.h5")); }),
            path("b.h5") + ": dataset /blocks/face_offsets gives block 2 3 entries, it needs at "
                           "least 4.");
}

// Files by another writer (h5py): absent optional groups, wrong shapes.
const char* kMakeFiles = R"PY(
import sys, h5py, numpy as np
d = sys.argv[1]
def fractures(name, normal_rows=1):
    with h5py.File(d + '/' + name, 'w') as f:
        f.attrs['format'] = 'dda-fractures'
        f.attrs['format_version'] = np.int64(1)
        g = f.create_group('fractures')
        g['shape'] = np.array([1], dtype=np.int8)
        g['normal'] = np.tile([0.0, 0.0, 1.0], (normal_rows, 1))
        g['centre'] = np.array([[1.0, 2.0, 3.0]])
        g['radius'] = np.array([0.5], dtype=np.float32)
        g['vertices'] = np.zeros((0, 3))
        g['offsets'] = np.array([0, 0], dtype=np.int64)
        g['set'] = np.array([-1], dtype=np.int16)
        g['kind'] = np.array([0])
        g['layer'] = np.array([-1])
fractures('ok.h5')
fractures('rows.h5', normal_rows=2)
with h5py.File(d + '/none.h5', 'w') as f:
    f.attrs['x'] = 1
)PY";

TEST_F(ModelIo3dTest, ForeignFilesAreReadOrRefused) {
  if (!run_python(kMakeFiles)) GTEST_SKIP() << "/usr/bin/python3 with h5py not available";
  const dda::FractureModel ok = dda::read_fractures_h5(path("ok.h5"));
  ASSERT_EQ(ok.fractures.size(), 1u);
  EXPECT_EQ(ok.fractures[0].shape, dda::FractureShape::Disc);
  EXPECT_EQ(ok.fractures[0].centre, Vec3(1, 2, 3));
  EXPECT_EQ(ok.fractures[0].radius, 0.5);
  EXPECT_EQ(ok.bed_normal, Vec3(0, 0, 1));  // no /layers: not layered
  EXPECT_TRUE(ok.excavations.empty());
  EXPECT_EQ(ok.domain.volume(), 0);
  EXPECT_EQ(error_of([&] { dda::read_fractures_h5(path("rows.h5")); }),
            path("rows.h5") + ": dataset /fractures/normal has shape (2, 3), expected (1, 3), one "
                              "row per fracture.");
  EXPECT_EQ(error_of([&] { dda::read_polyhedra_h5(path("none.h5")); }),
            path("none.h5") + ": is an HDF5 file but not one written by dda (no format "
                              "attribute), expected a dda-blocks3d file.");
  EXPECT_EQ(dda::h5_format_of(path("none.h5")), "");
}

// ------------------------------------------------------------------- names

TEST(Names3d, ShapesAndRemovabilityReadBackTheirNames) {
  for (auto s : {dda::FractureShape::Plane, dda::FractureShape::Disc, dda::FractureShape::Polygon})
    EXPECT_EQ(dda::fracture_shape_from_string(dda::to_string(s)), s);
  EXPECT_STREQ(dda::to_string(dda::FractureShape::Polygon), "polygon");
  for (int c = 0; c <= 5; ++c) {
    const auto r = static_cast<dda::Removability>(c);
    EXPECT_EQ(dda::removability_from_string(dda::to_string(r)), r);
  }
  EXPECT_STREQ(dda::to_string(dda::Removability::SlidesOne), "slides_one_face");
  try {
    dda::fracture_shape_from_string("circle", "s.yaml:4");
    ADD_FAILURE();
  } catch (const dda::InputError& e) {
    EXPECT_STREQ(e.what(), "s.yaml:4: unknown fracture shape \"circle\", expected plane, disc or polygon.");
  }
  EXPECT_THROW(dda::removability_from_string("slides"), dda::InputError);
}

}  // namespace
