// Import of 3D fractures: FracMan .fab files and CSV polygons.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "dda/common/error.hpp"
#include "dda/dl/import3d.hpp"
#include "dda/dl/polygon3d.hpp"
#include "dl_test_util.hpp"

namespace dda::dl {

namespace {

using V3 = Eigen::Vector3d;

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

template <class F>
std::string error_of(F&& read, const std::string& name, const std::string& text) {
  try {
    read(write_temp(name, text));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string fab_error(const std::string& text) { return error_of(read_fab, "dl3_bad.fab", text); }
std::string csv_error(const std::string& text) { return error_of(read_fracture_csv, "dl3_bad.csv", text); }

const char* kFabHead =
    "BEGIN FORMAT\nLength_Unit = M\nEND FORMAT\nBEGIN SETS\nSet1 = \"A\"\nEND SETS\nBEGIN FRACTURE\n";  // 7 lines

void expect_contains(const std::string& msg, const std::string& part) {
  EXPECT_NE(msg.find(part), std::string::npos) << "message: " << msg << "\nexpected: " << part;
}

}  // namespace

TEST(Import3dFab, ReadsFracturesAndSets) {
  // tests/data/dl3_fractures.fab: sets "Joint set A" (1) and "Faults" (2);
  // fracture 1 a horizontal 2 m square at z = 1 (line 23), fracture 2
  // a triangle in the plane x = 5 (line 29), fracture 7 a rectangle in the
  // plane x + z = 4 listed clockwise about its upper normal (line 34); a
  // TESSFRACTURE and a ROCKBLOCK section skipped.
  const ImportedFractures r = read_fab(test::data_path("dl3_fractures.fab"));
  ASSERT_EQ(r.set_names.size(), 2u);
  EXPECT_EQ(r.set_names[0], "Joint set A");
  EXPECT_EQ(r.set_names[1], "Faults");
  ASSERT_EQ(r.fractures.size(), 3u);
  EXPECT_EQ(r.lines, (std::vector<int>{23, 29, 34}));

  const Fracture3& a = r.fractures[0];
  EXPECT_EQ(a.shape, FractureShape::Polygon);
  EXPECT_EQ(a.set, 0);
  EXPECT_NEAR((a.normal - V3(0, 0, 1)).norm(), 0, 1e-15);
  EXPECT_NEAR((a.centre - V3(1, 1, 1)).norm(), 0, 1e-15);
  EXPECT_NEAR(polygon_area(a.vertices), 4, 1e-12);

  const Fracture3& b = r.fractures[1];
  EXPECT_EQ(b.set, 1);
  EXPECT_NEAR((b.normal - V3(1, 0, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR(polygon_area(b.vertices), 6, 1e-12);  // legs 3 and 4

  const Fracture3& c = r.fractures[2];
  EXPECT_EQ(c.set, 0);
  EXPECT_NEAR((c.normal - V3(1, 0, 1) / std::sqrt(2.0)).norm(), 0, 1e-15);
  EXPECT_GT(vector_area(c.vertices).dot(c.normal), 0);  // reversed to counter-clockwise
  EXPECT_NEAR(polygon_area(c.vertices), 2 * 2 * std::sqrt(2.0), 1e-12);
}

TEST(Import3dFab, FeetAreConvertedAndUnlistedSetsNamed) {
  const auto r = read_fab(write_temp("dl3_feet.fab",
                                     "BEGIN FORMAT\nLength_Unit = Ft\nEND FORMAT\nBEGIN FRACTURE\n"
                                     "1 3 4\n1 0 0 0\n2 10 0 0\n3 0 10 0\n0 0 0 1\nEND FRACTURE\n"));
  ASSERT_EQ(r.fractures.size(), 1u);
  EXPECT_EQ(r.set_names, std::vector<std::string>{"set 4"});
  EXPECT_NEAR(polygon_area(r.fractures[0].vertices), 50 * 0.3048 * 0.3048, 1e-12);
}

TEST(Import3dFab, BadFilesNameFileAndLine) {
  const std::string head = kFabHead;
  expect_contains(fab_error(head + "1 4 1\n1 0 0 0\n2 1 0 0\n3 1 1 0.3\n4 0 1 0\n0 0 0 1\nEND FRACTURE\n"),
                  "dl3_bad.fab:8: fracture 1 is not planar: vertex");
  expect_contains(fab_error(head + "1 2 1\n1 0 0 0\n2 1 0 0\n0 0 0 1\nEND FRACTURE\n"),
                  "dl3_bad.fab:8: fracture 1 has 2 vertices");
  expect_contains(fab_error(head + "1 4 1\n1 0 0 0\n2 2 0 0\n3 1 0.2 0\n4 1 2 0\n0 0 0 1\nEND FRACTURE\n"),
                  "dl3_bad.fab:8: fracture 1 is not convex");
  expect_contains(fab_error(head + "1 3 1\n1 0 0 0\n2 1 0 0\n3 2 0 0\n0 0 0 1\nEND FRACTURE\n"),
                  "dl3_bad.fab:8: fracture 1 has no area");
  expect_contains(fab_error(head + "1 3 1\n1 0 0 0\n2 1 x 0\n3 0 1 0\n0 0 0 1\nEND FRACTURE\n"),
                  "dl3_bad.fab:10: expected a vertex line 'i x y z' of fracture 1 (line 8)");
  expect_contains(fab_error(head + "1 3 1\n1 0 0 0\n2 1 0 0\nEND FRACTURE\n"),
                  "dl3_bad.fab:11: fracture 1 (line 8) ends after 2 of its 3 vertices");
  expect_contains(fab_error(head + "1 3 1\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\nEND FRACTURE\n"),
                  "dl3_bad.fab:12: expected the normal line '0 nx ny nz' of fracture 1 (line 8)");
  expect_contains(fab_error(head + "1 three 1\n"), "dl3_bad.fab:8: expected a fracture line 'id nnodes set");
  expect_contains(fab_error(head + "1 3 1\n1 0 0 0\n2 1 0 0\n3 0 1 0\n0 0 0 1\n"),
                  "dl3_bad.fab:7: 'BEGIN FRACTURE' has no matching 'END FRACTURE'");
  expect_contains(fab_error("BEGIN FORMAT\nLength_Unit = furlong\nEND FORMAT\n"),
                  "dl3_bad.fab:2: the length unit 'furlong' is not known");
  expect_contains(fab_error("BEGIN SETS\nJoints\nEND SETS\n"), "dl3_bad.fab:2: expected a set line");
  expect_contains(fab_error("\n\nNo_Fractures = 3\n"), "dl3_bad.fab:3: expected 'BEGIN <section>'");
  try {
    read_fab(testing::TempDir() + "dl3_missing/none.fab");
    ADD_FAILURE() << "no error for a missing file";
  } catch (const InputError& e) {
    expect_contains(e.what(), "dl3_missing/none.fab: cannot open");
  }
}

TEST(Import3dCsv, ReadsPolygonsAndSetNames) {
  // tests/data/dl3_polygons.csv: F1 a unit square in z = 0 (line 3, set J1),
  // F2 a triangle in x = 2 listed clockwise about +x (line 8, set J2), F3 a
  // triangle closed by repeating its first vertex (line 11, set J1).
  const ImportedFractures r = read_fracture_csv(test::data_path("dl3_polygons.csv"));
  EXPECT_EQ(r.set_names, (std::vector<std::string>{"J1", "J2"}));
  ASSERT_EQ(r.fractures.size(), 3u);
  EXPECT_EQ(r.lines, (std::vector<int>{3, 8, 11}));
  EXPECT_EQ(r.fractures[0].set, 0);
  EXPECT_NEAR(polygon_area(r.fractures[0].vertices), 1, 1e-15);
  EXPECT_EQ(r.fractures[1].set, 1);
  EXPECT_NEAR((r.fractures[1].normal - V3(1, 0, 0)).norm(), 0, 1e-15);
  EXPECT_GT(vector_area(r.fractures[1].vertices).dot(r.fractures[1].normal), 0);
  EXPECT_EQ(r.fractures[2].set, 0);
  EXPECT_EQ(r.fractures[2].vertices.size(), 3u);
  // Columns by name in any order, blanks as separators.
  const auto s = read_fracture_csv(write_temp("dl3_cols.csv", "z y x set fracture\n0 0 0 S a\n0 0 1 S a\n0 1 0 S a\n"));
  ASSERT_EQ(s.fractures.size(), 1u);
  EXPECT_NEAR((s.fractures[0].normal - V3(0, 0, 1)).norm(), 0, 1e-15);
}

TEST(Import3dCsv, BadFilesNameFileAndLine) {
  const std::string h = "fracture,set,x,y,z\n";
  expect_contains(csv_error(h + "A,J,0,0,0\nA,J,1,0,0\nA,J,1,1,0.5\nA,J,0,1,0\n"),
                  "dl3_bad.csv:2: fracture 'A' is not planar: vertex");
  expect_contains(csv_error(h + "A,J,0,0,0\nA,J,1,0,0\nB,J,0,0,0\nB,J,1,0,0\nB,J,0,1,0\n"),
                  "dl3_bad.csv:2: fracture 'A' has 2 vertices");
  expect_contains(csv_error(h + "A,J,0,0,0\nA,J,2,0,0\nA,J,1,0.2,0\nA,J,1,2,0\n"),
                  "dl3_bad.csv:2: fracture 'A' is not convex: it turns inwards at vertex 3");
  expect_contains(csv_error(h + "A,J,0,0,0\nA,J,1,1,1\nA,J,2,2,2\n"), "dl3_bad.csv:2: fracture 'A' has no area");
  expect_contains(csv_error(h + "A,J,0,0,0\nA,J,1,0,0\nA,J,0,1,0\nB,J,0,0,1\nB,J,1,0,1\nB,J,0,1,1\nA,J,5,5,5\n"),
                  "dl3_bad.csv:8: the rows of fracture 'A' are not consecutive (it started at line 2)");
  expect_contains(csv_error(h + "A,J,0,0,0\nA,K,1,0,0\n"), "dl3_bad.csv:3: fracture 'A' changes set from 'J' to 'K'");
  expect_contains(csv_error(h + "A,J,0,0,0\nA,J,1,y,0\n"), "dl3_bad.csv:3: column y must be a finite number, got 'y'");
  expect_contains(csv_error(h + "A,J,0,0,inf\n"), "dl3_bad.csv:2: column z must be a finite number");
  expect_contains(csv_error(h + "A,J,0,0\n"), "dl3_bad.csv:2: has 4 columns, the header 5");
  expect_contains(csv_error("# header next\nfracture,set,x,y\n"), "dl3_bad.csv:2: the header has no column 'z'");
  expect_contains(csv_error("# nothing\n"), "dl3_bad.csv: has no header line");
}

}  // namespace dda::dl
