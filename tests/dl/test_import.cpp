// CSV trace import, DDA-for-Windows .geo import, user lines and points.
#include <gtest/gtest.h>

#include <fstream>

#include "dda/dl/import.hpp"
#include "dl_test_util.hpp"

namespace dda::dl {

namespace {

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

std::string import_error(const std::string& path) {
  try {
    import_geo(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(DlImportCsv, ReadsTracesWithOptionalSetColumn) {
  // tests/data/dl_traces.csv: header, 4 traces (lines 2, 3, 5, 6), a comment.
  const auto t = read_traces_csv(test::data_path("dl_traces.csv"));
  ASSERT_EQ(t.size(), 4u);
  EXPECT_EQ(t[0].line, 2);
  EXPECT_EQ(t[0].set, "");  // empty fifth column: the scenario's set
  EXPECT_EQ(t[1].set, "F1");
  EXPECT_EQ(t[2].line, 5);  // semicolon-separated
  EXPECT_EQ(t[2].seg.b, Vec2(2, 8));
  EXPECT_EQ(t[3].set, "F2");
}

TEST(DlImportCsv, ScenarioClipsTracesAndNamesSets) {
  const auto r = test::run("domain: {box: [0, 0, 10, 10]}\ntraces:\n  - {file: dl_traces.csv, set: T}\n",
                           test::data_path("dl_scenario.yaml"));
  const auto& m = r.model;
  ASSERT_EQ(m.sets.size(), 3u);
  EXPECT_EQ(m.sets[0].name, "T");
  EXPECT_EQ(m.sets[0].origin, "csv");
  EXPECT_EQ(m.sets[1].name, "F1");
  EXPECT_EQ(m.sets[2].name, "F2");
  ASSERT_EQ(m.lines.size(), 4u);
  // -5,2 -> 15,2 clipped to the box: 0,2 -> 10,2.
  EXPECT_NEAR((m.lines[3].a - Vec2(0, 2)).norm(), 0, 1e-12);
  EXPECT_NEAR((m.lines[3].b - Vec2(10, 2)).norm(), 0, 1e-12);
  EXPECT_EQ(r.report["traces"][0]["traces"].get<int>(), 4);
}

TEST(DlImportCsv, BadFilesNameFileAndLine) {
  const auto msg = test::error_of("domain: {box: [0, 0, 10, 10]}\ntraces:\n  - {file: dl_traces_bad.csv}\n",
                                  test::data_path("dl_scenario.yaml"));
  EXPECT_NE(msg.find("dl_scenario.yaml:3:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("traces[0].file"), std::string::npos) << msg;
  EXPECT_NE(msg.find("dl_traces_bad.csv:3:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("3 columns"), std::string::npos) << msg;

  auto csv_error = [](const std::string& text) {
    try {
      read_traces_csv(write_temp("dl_bad.csv", text));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(csv_error("0,0,1,1\n0,0,x,1\n").find("dl_bad.csv:2: column 3 (x2) must be a number"), std::string::npos);
  EXPECT_NE(csv_error("0,0,1,1\n\n0,nan,1,1\n").find("dl_bad.csv:3: column 2 (y1) must be finite"), std::string::npos);
  EXPECT_NE(csv_error("1,1,1,1\n").find("dl_bad.csv:1: the trace has zero length"), std::string::npos);
  EXPECT_NE(csv_error("0,0,1,1,a,b\n").find("dl_bad.csv:1: has 6 columns"), std::string::npos);
}

// Found by fuzzing (docs/reliability.md, "Fuzzing"): a line of a lone form
// feed was not blank to trim but had no fields, and the reader took the
// first of none.
TEST(DlImportCsv, FormFeedAndVerticalTabLinesAreBlank) {
  const auto t = read_traces_csv(write_temp("dl_ff.csv", "\f\nx1,y1,x2,y2\n0,0,1,1\n\v \f\n2,2,3,3\n"));
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[1].line, 5);
}

TEST(DlImportGeo, TwoBlocks) {
  const LineModel m = import_geo(test::data_path("dl_two_blocks.geo"));
  EXPECT_TRUE(m.domain.empty());  // the outline is made by the lines
  ASSERT_EQ(m.sets.size(), 2u);
  EXPECT_EQ(m.sets[0].name, "type1");
  EXPECT_EQ(m.sets[1].name, "type2");
  EXPECT_EQ(m.sets[1].origin, "geo");
  ASSERT_EQ(m.lines.size(), 5u);
  EXPECT_EQ(m.lines[4].set, 1);
  EXPECT_EQ(m.lines[4].a, Vec2(1, 0));
  EXPECT_EQ(m.lines[4].b, Vec2(1, 1));
  ASSERT_EQ(m.points.size(), 2u);
  EXPECT_EQ(m.points[0].name, "fixed_1");
  EXPECT_EQ(m.points[0].kind, PointKind::Fixed);
  EXPECT_EQ(m.points[0].p, Vec2(1.5, 0.5));
  EXPECT_EQ(m.points[1].name, "measured_1");
  EXPECT_EQ(m.points[1].kind, PointKind::Measurement);
  EXPECT_EQ(m.points[1].p, Vec2(0.5, 0.5));
}

TEST(DlImportGeo, GridWithFixedLineAndCommentedList) {
  const LineModel m = import_geo(test::data_path("dl_grid.geo"));
  ASSERT_EQ(m.sets.size(), 2u);
  EXPECT_EQ(m.sets[1].name, "fixed");
  ASSERT_EQ(m.lines.size(), 8u);  // 7 joints + the fixed line
  EXPECT_EQ(m.lines[7].a, Vec2(0.5, 0.5));
  EXPECT_EQ(m.lines[7].b, Vec2(2.5, 0.5));
  // Fixed line: fixed points at both ends and the midpoint; then load,
  // measured (the commented-out list is ignored) and hole points.
  ASSERT_EQ(m.points.size(), 6u);
  EXPECT_EQ(m.points[0].p, Vec2(0.5, 0.5));
  EXPECT_EQ(m.points[1].p, Vec2(1.5, 0.5));
  EXPECT_EQ(m.points[2].p, Vec2(2.5, 0.5));
  EXPECT_EQ(m.points[3].kind, PointKind::Load);
  EXPECT_EQ(m.points[4].name, "measured_1");
  EXPECT_EQ(m.points[4].p, Vec2(2.5, 1.5));
  EXPECT_EQ(m.points[5].kind, PointKind::Hole);
}

TEST(DlImportGeo, ScenarioGeometryKey) {
  const auto r = test::run("seed: 4\ngeometry: {file: dl_two_blocks.geo}\npoints:\n  - {name: m2, at: [1.9, 0.9]}\n",
                           test::data_path("dl_scenario.yaml"));
  EXPECT_TRUE(r.model.domain.empty());
  EXPECT_EQ(r.model.lines.size(), 5u);
  EXPECT_EQ(r.model.points.size(), 3u);
  EXPECT_TRUE(r.report["domain"].is_null());
}

TEST(DlImportGeo, BadFilesNameFileAndLine) {
  const std::string header =
      "<?xml version=\"1.0\"?>\n<Berkeley:DDA xmlns:Berkeley=\"x\">\n<Berkeley:Geometry>\n<Jointlist>\n";
  const std::string footer = "</Jointlist>\n</Berkeley:Geometry>\n</Berkeley:DDA>\n";
  std::string msg = import_error(write_temp("dl_bad1.geo", header + "<Joint type=\"1\"> 0 0 1 1 </Joint>\n<Joint type=\"1\"> 0 0 1 </Joint>\n" + footer));
  EXPECT_NE(msg.find("dl_bad1.geo:6: <Joint> must hold 4 numbers"), std::string::npos) << msg;
  msg = import_error(write_temp("dl_bad2.geo", header + "<Joint> 0 0 1 1 </Joint>\n" + footer));
  EXPECT_NE(msg.find("dl_bad2.geo:5: <Joint> needs a type attribute"), std::string::npos) << msg;
  msg = import_error(write_temp("dl_bad3.geo", header + "<Joint type=\"1\"> 0 0 1 1 \n" + footer));
  EXPECT_NE(msg.find("dl_bad3.geo:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("not valid XML"), std::string::npos) << msg;
  msg = import_error(write_temp("dl_bad4.geo", "<?xml version=\"1.0\"?>\n<Other/>\n"));
  EXPECT_NE(msg.find("dl_bad4.geo:2: is not a DDA geometry file"), std::string::npos) << msg;
  msg = import_error(testing::TempDir() + "dl_missing.geo");
  EXPECT_NE(msg.find("dl_missing.geo: cannot open"), std::string::npos) << msg;
}

TEST(DlPoints, NamedKindsInsideTheDomain) {
  const auto r = test::run(R"(domain: {box: [0, 0, 10, 10]}
points:
  - {name: a, kind: fixed, at: [1, 1]}
  - {name: b, kind: load, at: [2, 2]}
  - {name: c, at: [3, 3]}
  - {name: d, kind: hole, at: [4, 4]}
)");
  ASSERT_EQ(r.model.points.size(), 4u);
  EXPECT_EQ(r.model.points[0].kind, PointKind::Fixed);
  EXPECT_EQ(r.model.points[1].kind, PointKind::Load);
  EXPECT_EQ(r.model.points[2].kind, PointKind::Measurement);  // the default
  EXPECT_EQ(r.model.points[3].kind, PointKind::Hole);
  EXPECT_EQ(r.report["points"]["measurement"].get<int>(), 1);
}

TEST(DlUserLines, ClippedAndGroupedBySet) {
  const auto r = test::run(R"(domain: {box: [0, 0, 10, 10]}
lines:
  - {set: fault, from: [-2, -2], to: [12, 12]}
  - {set: fault, from: [0, 5], to: [5, 5]}
  - {from: [1, 9], to: [9, 1]}
)");
  ASSERT_EQ(r.model.sets.size(), 2u);
  EXPECT_EQ(r.model.sets[0].name, "fault");
  EXPECT_EQ(r.model.sets[1].name, "user");
  ASSERT_EQ(r.model.lines.size(), 3u);
  EXPECT_NEAR((r.model.lines[0].a - Vec2(0, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((r.model.lines[0].b - Vec2(10, 10)).norm(), 0, 1e-12);
  EXPECT_NEAR(r.report["sets"][0]["total_length"].get<double>(), std::sqrt(200.0) + 5, 1e-9);
}

}  // namespace dda::dl
