// Closed surfaces in 3D scenarios: `domain: {surface}` and excavations of
// `shape: surface`, their report and their errors.
#include <gtest/gtest.h>

#include <string>

#include "dda/common/error.hpp"
#include "dda/dl/scenario3d.hpp"
#include "dl_test_util.hpp"

namespace dda::dl {
namespace {

// Relative paths in these scenarios resolve to tests/data.
DlResult3 run_in_data(const std::string& text) {
  return generate_3d_from_scenario(YamlNode::load_string(text, test::data_path("s3d_surface.yaml")));
}

std::string error_in_data(const std::string& text) {
  try {
    run_in_data(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Scenario3dSurface, DomainSurfaceSetsTheBoxToItsBounds) {
  const DlResult3 r = run_in_data(
      "dimension: 3\ndomain: {surface: mesh_lprism.obj}\n"
      "persistent_sets:\n  - {dip: 0, dip_direction: 0, spacing: 0.25}\n");
  ASSERT_TRUE(r.model.domain_surface.has_value());
  EXPECT_EQ(r.model.domain.lo, Vec3(0, 0, 0));
  EXPECT_EQ(r.model.domain.hi, Vec3(2, 2, 1));
  EXPECT_EQ(r.model.fractures.size(), 3u);  // z = 0.25, 0.5, 0.75
  const auto& d = r.report["domain"];
  EXPECT_EQ(d["surface"], "mesh_lprism.obj");
  EXPECT_EQ(d["triangles"], 20);
  EXPECT_NEAR(d["volume"].get<double>(), 3, 1e-15);
  EXPECT_NEAR(d["box_volume"].get<double>(), 4, 1e-15);
  EXPECT_FALSE(format_report3(r.report).empty());
}

TEST(Scenario3dSurface, DomainSurfaceErrorsNameTheScenarioKey) {
  std::string e = error_in_data("dimension: 3\ndomain: {surface: mesh_open.obj}\n");
  EXPECT_NE(e.find("s3d_surface.yaml:2: domain.surface names a surface file with an error"), std::string::npos) << e;
  EXPECT_NE(e.find("mesh_open.obj: the surface is not closed"), std::string::npos) << e;
  e = error_in_data("dimension: 3\ndomain: {surface: mesh_cube.stl, box: [0, 0, 0, 1, 1, 1]}\n");
  EXPECT_NE(e.find("either box or surface"), std::string::npos) << e;
  e = error_in_data(
      "dimension: 3\ndomain: {surface: mesh_cube.stl}\n"
      "trace_planes:\n  - {point: [1, 1, 1], dip: 90, dip_direction: 90}\n");
  EXPECT_NE(e.find("domain.surface cannot be sectioned by trace_planes"), std::string::npos) << e;
}

TEST(Scenario3dSurface, SurfaceExcavationReportsItsVolumeInTheDomain) {
  // The cube [0, 2]^3 against the box [1, 2] x [0.5, 2] x [0, 1.5] of it.
  const DlResult3 r = run_in_data(
      "dimension: 3\ndomain: {box: [1, 0.5, -1, 10, 10, 1.5]}\n"
      "excavations:\n  - {shape: surface, file: mesh_cube_binary.stl, name: cave}\n"
      "  - {shape: box, min: [5, 5, 0], max: [6, 6, 1]}\n");
  ASSERT_EQ(r.model.excavations.size(), 2u);
  const Excavation3& cave = r.model.excavations[0];
  EXPECT_EQ(cave.name, "cave");
  ASSERT_TRUE(cave.surface.has_value());
  EXPECT_TRUE(cave.region.half_spaces.empty());
  EXPECT_FALSE(r.model.excavations[1].surface.has_value());
  const auto& e = r.report["excavations"][0];
  EXPECT_EQ(e["shape"], "surface");
  EXPECT_EQ(e["file"], "mesh_cube_binary.stl");
  EXPECT_NEAR(e["volume"].get<double>(), 8, 1e-15);
  EXPECT_NEAR(e["volume_in_domain"].get<double>(), 2.25, 1e-12);
}

TEST(Scenario3dSurface, SurfaceExcavationErrors) {
  const std::string head = "dimension: 3\ndomain: {box: [0, 0, 0, 10, 10, 10]}\nexcavations:\n";
  std::string e = error_in_data(head + "  - {shape: surface, file: mesh_bad_index.obj}\n");
  EXPECT_NE(e.find("s3d_surface.yaml:4: excavations[0].file names a surface file with an error"), std::string::npos) << e;
  EXPECT_NE(e.find("mesh_bad_index.obj:10: vertex id 9 does not exist"), std::string::npos) << e;
  e = error_in_data("dimension: 3\ndomain: {box: [5, 5, 5, 10, 10, 10]}\nexcavations:\n"
                    "  - {shape: surface, file: mesh_cube.obj}\n");
  EXPECT_NE(e.find("does not reach into the domain"), std::string::npos) << e;
  e = error_in_data(head + "  - {shape: surface, file: mesh_cube.obj, radius: 2}\n");
  EXPECT_NE(e.find("radius"), std::string::npos) << e;
  e = error_in_data(head + "  - {shape: surface, file: mesh_cube.obj}\n"
                    "trace_planes:\n  - {point: [1, 1, 1], dip: 90, dip_direction: 90}\n");
  EXPECT_NE(e.find("cannot be sectioned by trace_planes"), std::string::npos) << e;
}

}  // namespace
}  // namespace dda::dl
