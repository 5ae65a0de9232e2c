// 3D DL from a scenario: each section, the errors (file:line and key),
// determinism, and the report against what was asked.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"
#include "dda/common/scenario.hpp"
#include "dda/dl/dfn3d.hpp"
#include "dda/dl/fracture_measures3d.hpp"
#include "dda/dl/fractures3d.hpp"
#include "dda/dl/scenario3d.hpp"
#include "dl_test_util.hpp"

namespace dda::dl {

namespace {

using V3 = Eigen::Vector3d;

// Lines 1-3 of every scenario below.
const std::string kHead = "dimension: 3\nseed: 5\ndomain: {box: [0, 0, 0, 10, 10, 10]}\n";

DlResult3 run3(const std::string& body, const std::string& label = "test.yaml") {
  return generate_3d_from_scenario(YamlNode::load_string(kHead + body, label));
}

std::string error3(const std::string& body, const std::string& label = "test.yaml") {
  try {
    run3(body, label);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// The message must hold every part, and be one sentence.
void expect_error(const std::string& body, const std::vector<std::string>& parts) {
  const std::string msg = error3(body);
  ASSERT_FALSE(msg.empty()) << body;
  for (const std::string& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' not in: " << msg;
  EXPECT_EQ(msg.back(), '.') << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
}

std::size_t count_of_set(const FractureModel& m, int set) {
  std::size_t n = 0;
  for (const Fracture3& f : m.fractures) n += f.set == set;
  return n;
}

// load_scenario needs a file: the message it gives for `text`, or "".
std::string load_error(const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / "dda_test_scenario3d.yaml").string();
  std::ofstream(path) << text;
  std::string message;
  try {
    load_scenario(path);
  } catch (const InputError& e) {
    message = e.what();
  }
  std::filesystem::remove(path);
  return message;
}

}  // namespace

// ---- sections and dimension ---------------------------------------------

TEST(Scenario3d, DimensionSelectsTheSections) {
  EXPECT_EQ(scenario_dimension(YamlNode::load_string("seed: 1\n", "t.yaml")), 2);
  EXPECT_EQ(scenario_dimension(YamlNode::load_string("dimension: 3\n", "t.yaml")), 3);
  EXPECT_EQ(error3("", "t.yaml"), "");
  const std::string four = load_error("dimension: 4\n");
  EXPECT_NE(four.find(":1: dimension must be 2 or 3, got 4."), std::string::npos) << four;

  // 2D sections in a 3D scenario, 3D sections in a 2D one: named, with the way out.
  const std::string two = load_error(kHead + "joint_sets: []\n");
  EXPECT_NE(two.find(":4: joint_sets is a 2D section, not read with dimension: 3 (in 3D, use fracture_sets)."),
            std::string::npos)
      << two;
  const std::string three = load_error("domain: {box: [0, 0, 1, 1]}\nplanes: []\n");
  EXPECT_NE(three.find(":2: planes is a 3D section; add dimension: 3"), std::string::npos) << three;
  EXPECT_EQ(load_error(kHead + "fracture_sets: []\ncutting: {}\n"), "");
  // The 3D generator itself refuses what it does not read.
  expect_error("lines: []\n", {"test.yaml:4:", "unknown key 'lines'"});
  const std::string not3 = [] {
    try {
      generate_3d_from_scenario(YamlNode::load_string("domain: {box: [0, 0, 0, 1, 1, 1]}\n", "t.yaml"));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  }();
  EXPECT_NE(not3.find("dimension must be 3"), std::string::npos) << not3;
}

TEST(Scenario3d, DomainIsABoxOfSixNumbers) {
  const DlResult3 r = run3("");
  EXPECT_EQ(r.model.domain.lo, V3(0, 0, 0));
  EXPECT_EQ(r.model.domain.hi, V3(10, 10, 10));
  EXPECT_DOUBLE_EQ(r.report["domain"]["volume"].get<double>(), 1000);
  EXPECT_EQ(r.report["dimension"], 3);
  auto domain_error = [](const std::string& domain) {
    try {
      generate_3d_from_scenario(YamlNode::load_string("dimension: 3\ndomain: " + domain + "\n", "d.yaml"));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(domain_error("{box: [0, 0, 10, 10]}"),
            "d.yaml:2: domain.box must be [x0, y0, z0, x1, y1, z1], got 4 numbers.");
  EXPECT_EQ(domain_error("{box: [0, 0, 0, 10, 10, -1]}"),
            "d.yaml:2: domain.box must have x1 > x0, y1 > y0 and z1 > z0.");
  EXPECT_NE(domain_error("{polygon: [[0, 0], [1, 0], [1, 1]]}").find("unknown key 'domain.polygon'"),
            std::string::npos);
}

// ---- fracture_sets --------------------------------------------------------

TEST(Scenario3d, FractureSetsOfDiscsAndPolygons) {
  const DlResult3 r = run3(
      "fracture_sets:\n"
      "  - {name: A, dip: 30, dip_direction: 120, size: {law: constant, radius: 1}, count: 200}\n"
      "  - {name: B, dip: 70, dip_direction: 10, kappa: 30, size: {law: power_law, alpha: 2.5, rmin: 0.5, rmax: 3},\n"
      "     shape: polygon, sides: 5, p32: 0.5}\n");
  ASSERT_EQ(r.model.sets.size(), 2u);
  EXPECT_EQ(r.model.sets[0].name, "A");
  EXPECT_EQ(r.model.sets[1].origin, "dfn");
  const V3 mean_a = normal_from_dip(30, 120);
  for (const Fracture3& f : r.model.fractures) {
    if (f.set == 0) {
      EXPECT_EQ(f.shape, FractureShape::Disc);
      EXPECT_LT((f.normal - mean_a).norm(), 1e-12);  // no kappa: all at the mean
      EXPECT_DOUBLE_EQ(f.radius, 1);
    } else {
      EXPECT_EQ(f.shape, FractureShape::Polygon);
      EXPECT_EQ(f.vertices.size(), 5u);
    }
    EXPECT_GT(fracture_area_in_box(f, r.model.domain), 0);  // the margin's misses are dropped
  }
  const auto& a = r.report["fracture_sets"][0];
  EXPECT_EQ(a["generated"], 200);
  EXPECT_EQ(a["in_domain"].get<std::size_t>(), count_of_set(r.model, 0));
  EXPECT_DOUBLE_EQ(a["asked"]["margin"].get<double>(), 1);  // the constant radius
  EXPECT_TRUE(a["asked"]["kappa"].is_null());
  EXPECT_DOUBLE_EQ(r.report["fracture_sets"][1]["asked"]["margin"].get<double>(), 3);  // rmax
  // The count's expected P32: 200 pi / 12^3.
  EXPECT_NEAR(r.report["sets"][0]["asked_p32"].get<double>(), 200 * kPi / 1728, 1e-12);
  EXPECT_DOUBLE_EQ(r.report["sets"][1]["asked_p32"].get<double>(), 0.5);
  // A law without a largest radius: 3 mean radii.
  const DlResult3 ln =
      run3("fracture_sets:\n  - {dip: 0, dip_direction: 0, size: {law: exponential, mean: 0.5}, count: 5}\n");
  EXPECT_DOUBLE_EQ(ln.report["fracture_sets"][0]["asked"]["margin"].get<double>(), 1.5);
  EXPECT_EQ(ln.model.sets[0].name, "F1");
}

TEST(Scenario3d, FractureSetErrorsNameFileLineAndKey) {
  const std::string set = "fracture_sets:\n  - {name: A, dip: 30, dip_direction: 120, ";  // the set is on line 5
  expect_error(set + "size: {law: constant, radius: 1}}\n",
               {"test.yaml:5:", "fracture_sets[0]", "exactly one of count, p32, none given"});
  expect_error(set + "size: {law: constant, radius: 1}, count: 3, p32: 1}\n", {"test.yaml:5:", "count and p32"});
  expect_error(set + "size: {law: constant, radius: 1}, count: 0}\n", {"test.yaml:5:", "fracture_sets[0].count"});
  expect_error(set + "size: {law: constant, radius: 1}, count: 3, sides: 4}\n",
               {"test.yaml:5:", "fracture_sets[0].sides", "polygon"});
  expect_error(set + "size: {law: gamma, radius: 1}, count: 3}\n",
               {"test.yaml:5:", "fracture_sets[0].size.law", "gamma"});
  expect_error(set + "size: {law: power_law, alpha: 2, rmin: 2, rmax: 1}, count: 3}\n",
               {"test.yaml:5:", "fracture_sets[0].size.rmax", "greater than rmin"});
  const std::string no_std = error3(set + "size: {law: lognormal, mean: 1}, count: 3}\n");
  EXPECT_EQ(no_std, "test.yaml:5: required key 'fracture_sets[0].size.std' is missing.");
  expect_error(set + "size: {law: power_law, alpha: 1, rmin: 1, rmax: 2}, count: 3}\n",
               {"test.yaml:5:", "fracture_sets[0].size.alpha", "> 1"});
  expect_error(set + "size: {law: constant, radius: 1}, count: 3, kapa: 4}\n",
               {"test.yaml:5:", "fracture_sets[0].kapa", "did you mean 'kappa'"});
  expect_error("fracture_sets:\n  - {dip: 95, dip_direction: 0, size: {law: constant, radius: 1}, count: 3}\n",
               {"test.yaml:5:", "fracture_sets[0].dip", "[0, 90]"});
  expect_error(set + "size: {law: constant, radius: 0.001}, p32: 1e6}\n",
               {"test.yaml:5:", "fracture_sets[0].p32 cannot be generated", "limit"});
  expect_error(set +
                   "size: {law: constant, radius: 1}, count: 3}\n  - {name: A, dip: 0, dip_direction: 0, "
                   "size: {law: constant, radius: 1}, count: 3}\n",
               {"test.yaml:6:", "fracture_sets[1].name", "'A' is already the name of another set"});
}

TEST(Scenario3d, SameSeedSameNetworkAndSetsIndependent) {
  const std::string sets =
      "fracture_sets:\n"
      "  - {name: A, dip: 45, dip_direction: 200, kappa: 10, size: {law: lognormal, mean: 1, std: 0.4}, p32: 1}\n";
  const DlResult3 a = run3(sets), b = run3(sets);
  ASSERT_EQ(a.model.fractures.size(), b.model.fractures.size());
  for (std::size_t i = 0; i < a.model.fractures.size(); ++i) {
    EXPECT_EQ(a.model.fractures[i].centre, b.model.fractures[i].centre);
    EXPECT_EQ(a.model.fractures[i].normal, b.model.fractures[i].normal);
  }
  EXPECT_EQ(a.report.dump(), b.report.dump());
  // Another seed, another network.
  const DlResult3 c = generate_3d_from_scenario(
      YamlNode::load_string("dimension: 3\nseed: 6\ndomain: {box: [0, 0, 0, 10, 10, 10]}\n" + sets, "test.yaml"));
  EXPECT_NE(c.model.fractures.front().centre, a.model.fractures.front().centre);
  // Adding a persistent set and a second fracture set leaves set A as it was.
  const DlResult3 d = run3(sets +
                           "  - {name: B, dip: 80, dip_direction: 0, size: {law: constant, radius: 2}, count: 10}\n"
                           "persistent_sets:\n  - {name: S, dip: 0, dip_direction: 0, spacing: 3}\n");
  ASSERT_GE(d.model.fractures.size(), a.model.fractures.size());
  for (std::size_t i = 0; i < a.model.fractures.size(); ++i)
    EXPECT_EQ(d.model.fractures[i].centre, a.model.fractures[i].centre);
  EXPECT_EQ(d.model.provenance.seed, 5u);
  EXPECT_EQ(d.model.provenance.scenario_path, "test.yaml");
  EXPECT_NE(d.model.provenance.scenario_text.find("persistent_sets"), std::string::npos);
  EXPECT_FALSE(d.model.provenance.program_version.empty());
}

TEST(Scenario3d, AchievedP32IsCloseToTheAskedForALargeSet) {
  // About 6 * 12^3 / pi = 3300 discs of radius 1 (margin 1 by default: no
  // edge effect); the share in the domain varies by about 1.5 %.
  const DlResult3 by_p32 = run3(
      "fracture_sets:\n  - {name: A, dip: 50, dip_direction: 90, kappa: 5, size: {law: constant, radius: 1}, p32: "
      "6}\n");
  const auto& s = by_p32.report["sets"][0];
  EXPECT_NEAR(s["p32"].get<double>(), 6, 0.3);
  EXPECT_NEAR(s["p32"].get<double>(), p32_in_box(by_p32.model.fractures, by_p32.model.domain), 1e-12);
  // By count: the expected P32 count pi r^2 / (12^3) is the asked one.
  const DlResult3 by_count = run3(
      "fracture_sets:\n  - {name: A, dip: 50, dip_direction: 90, size: {law: constant, radius: 1}, shape: polygon,\n"
      "     sides: 8, count: 5000}\n");
  const double asked = by_count.report["sets"][0]["asked_p32"].get<double>();
  EXPECT_NEAR(asked, 5000 * kPi / 1728, 1e-9);
  EXPECT_NEAR(by_count.report["sets"][0]["p32"].get<double>(), asked, 0.05 * asked);
}

TEST(Scenario3d, ReportMeasuresOrientationAndSize) {
  const DlResult3 r = run3(
      "fracture_sets:\n  - {name: A, dip: 85, dip_direction: 30, kappa: 40, size: {law: constant, radius: 0.5}, "
      "count: 3000}\n");
  const auto& o = r.report["sets"][0]["orientation"];
  // A steep set straddles the horizon: its stored normals are folded, the
  // estimate unfolds them.
  EXPECT_NEAR(o["dip"].get<double>(), 85, 1.5);
  EXPECT_NEAR(o["dip_direction"].get<double>(), 30, 1.5);
  EXPECT_NEAR(o["kappa"].get<double>(), 40, 4);
  EXPECT_DOUBLE_EQ(r.report["sets"][0]["mean_radius"].get<double>(), 0.5);
  // P10 and P21 as the measure functions give them.
  const auto& f = r.model.fractures;
  EXPECT_DOUBLE_EQ(r.report["sets"][0]["p10"]["x"].get<double>(), p10_along(f, V3(0, 5, 5), V3(10, 5, 5)));
  EXPECT_DOUBLE_EQ(r.report["sets"][0]["p21"]["xy"].get<double>(),
                   p21_on(f, Rectangle3{V3(0, 0, 5), V3(10, 0, 0), V3(0, 10, 0)}));
  EXPECT_EQ(r.report["totals"]["fractures"].get<std::size_t>(), f.size());
  const std::string text = format_report3(r.report);
  EXPECT_NE(text.find("DL report, 3D (seed 5)"), std::string::npos) << text;
  EXPECT_NE(text.find("Totals: "), std::string::npos) << text;
}

// ---- the measures on known fractures --------------------------------------

TEST(Scenario3d, P10AndP21OfPlanesPolygonsAndDiscs) {
  Fracture3 plane;
  plane.shape = FractureShape::Plane;
  plane.normal = V3(1, 0, 0);
  plane.centre = V3(5, 3, 3);
  Fracture3 square;
  square.shape = FractureShape::Polygon;
  square.normal = V3(0, 0, 1);
  square.vertices = {V3(4, 4, 5), V3(6, 4, 5), V3(6, 6, 5), V3(4, 6, 5)};
  square.centre = V3(5, 5, 5);
  const std::vector<Fracture3> both{plane, square};
  EXPECT_DOUBLE_EQ(p10_along(both, V3(0, 5, 5), V3(10, 5, 5)), 0.1);  // the plane; the line lies in the square's plane
  EXPECT_DOUBLE_EQ(p10_along(both, V3(5.5, 5, 0), V3(5.5, 5, 10)), 0.1);  // the square only
  // On y = 5: the plane's trace is 10 long, the square's 2.
  EXPECT_DOUBLE_EQ(p21_on(both, Rectangle3{V3(0, 5, 0), V3(10, 0, 0), V3(0, 0, 10)}), 0.12);
  // On z = 5 the square lies in the plane (no trace); the plane's trace is 10.
  EXPECT_DOUBLE_EQ(p21_on(both, Rectangle3{V3(0, 0, 5), V3(10, 0, 0), V3(0, 10, 0)}), 0.1);
  // Discs agree with the disc measures.
  std::vector<Disc> discs{{V3(5, 5, 5), normal_from_dip(40, 70), 3, 0}, {V3(2, 7, 4), normal_from_dip(80, 200), 2, 0}};
  std::vector<Fracture3> as_fractures;
  for (const Disc& d : discs) as_fractures.push_back(to_fracture(d));
  const Rectangle3 rect{V3(0, 5, 0), V3(10, 0, 0), V3(0, 0, 10)};
  EXPECT_NEAR(p21_on(as_fractures, rect), p21_on(discs, rect), 1e-12);
  EXPECT_EQ(p10_along(as_fractures, V3(0, 5, 5), V3(10, 5, 5)), p10_along(discs, V3(0, 5, 5), V3(10, 5, 5)));
}

// ---- persistent_sets and planes ------------------------------------------

TEST(Scenario3d, PersistentSetsAndPlanes) {
  const DlResult3 r = run3(
      "persistent_sets:\n  - {name: S, dip: 0, dip_direction: 0, spacing: 2}\n"
      "planes:\n"
      "  - {name: fault, dip: 90, dip_direction: 90, point: [5, 5, 5]}\n"
      "  - {name: joint, dip: 45, dip_direction: 0, point: [5, 5, 5], radius: 2}\n");
  ASSERT_EQ(r.model.sets.size(), 3u);  // persistent first, then one set per plane
  EXPECT_EQ(r.model.sets[1].name, "fault");
  EXPECT_EQ(count_of_set(r.model, 0), 4u);  // z = 2, 4, 6, 8 (z = 0 and 10 only touch the box)
  EXPECT_EQ(r.report["persistent_sets"][0]["planes"], 4);
  EXPECT_DOUBLE_EQ(r.report["sets"][0]["p32"].get<double>(), 0.4);
  EXPECT_DOUBLE_EQ(r.report["sets"][1]["p10"]["x"].get<double>(), 0.1);
  EXPECT_EQ(r.model.fractures.back().shape, FractureShape::Disc);
  EXPECT_DOUBLE_EQ(r.model.fractures.back().radius, 2);
  expect_error("planes:\n  - {name: far, dip: 0, dip_direction: 0, point: [5, 5, 20]}\n",
               {"test.yaml:5:", "planes[0] misses the domain"});
  expect_error("planes:\n  - {name: p, dip: 0, dip_direction: 0, point: [5, 5]}\n",
               {"test.yaml:5:", "planes[0].point must be a point [x, y, z], got 2 numbers"});
  expect_error("persistent_sets:\n  - {name: S, dip: 0, dip_direction: 0, spacing: 1e-6}\n",
               {"test.yaml:5:", "persistent_sets[0].spacing cannot be generated", "limit"});
  expect_error("persistent_sets:\n  - {name: S, dip: 0, dip_direction: 0, spacing: 1, randomness: 1}\n",
               {"test.yaml:5:", "persistent_sets[0].randomness"});
  // The fuzz target scenario3d's finding (docs/reliability.md): a point 2^64 m
  // up in the cube [0, 10]^3 with spacing 12 is (2^64 - 10) / 12 = 1.54e18
  // spacings above it, beyond the 1e9 of kMaxSpacingsToPoint; the error names
  // the point, not the spacing.
  expect_error("persistent_sets:\n  - {name: S, dip: 0, dip_direction: 0, spacing: 12, point: [0, 0, 18446744073709551616]}\n",
               {"test.yaml:5:", "persistent_sets[0].point lies 1.54e+18 spacings from the domain", "1e+09"});
}

// ---- layering ---------------------------------------------------------------

TEST(Scenario3d, LayeringReportsTheRealisedFsiPerBed) {
  const DlResult3 r = run3(
      "fracture_sets:\n  - {name: A, dip: 30, dip_direction: 0, size: {law: constant, radius: 1}, count: 3}\n"
      "layering:\n"
      "  thickness: {distribution: constant, value: 2.5}\n"
      "  sets:\n"
      "    - {name: V, dip: 90, dip_direction: 90, fsi: 2.5}\n");
  ASSERT_EQ(r.model.sets.size(), 3u);  // A, then V, then the bedding set
  EXPECT_EQ(r.model.sets[1].name, "V");
  EXPECT_EQ(r.model.sets[2].origin, "bedding");
  EXPECT_EQ(r.model.layers.size(), 4u);
  const auto& l = r.report["layering"];
  EXPECT_EQ(l["beds"], 4);
  for (const auto& bed : l["sets"][0]["per_bed"]) {
    EXPECT_DOUBLE_EQ(bed["asked_median_spacing"].get<double>(), 1.0);
    EXPECT_NEAR(bed["realised_fsi"].get<double>(), 2.5, 1e-9);  // no randomness: exact
  }
  expect_error(
      "layering:\n  thickness: {distribution: constant, value: 1}\n  sets:\n"
      "    - {name: H, dip: 2, dip_direction: 0, fsi: 1}\n",
      {"test.yaml:7:", "layering.sets[0].dip", "5 degrees"});
  expect_error(
      "fracture_sets:\n  - {name: V, dip: 30, dip_direction: 0, size: {law: constant, radius: 1}, count: 3}\n"
      "layering:\n  thickness: {distribution: constant, value: 1}\n  sets:\n    - {name: V, fsi: 1}\n",
      {"test.yaml:9:", "layering.sets[0].name", "'V' is already the name of another set"});
  expect_error("layering:\n  thickness: {distribution: lognormal, mean: 1, std: 0.5, minimum: 5}\n",
               {"test.yaml:5:", "layering.thickness.minimum"});
  expect_error("layering:\n  thickness: {distribution: constant, value: 1e-6}\n",
               {"test.yaml:5:", "layering.thickness cannot be generated", "beds"});
}

// ---- fracture_files -------------------------------------------------------

TEST(Scenario3d, FractureFilesFromFabAndCsv) {
  const std::string label = test::data_path("s3d_test.yaml");  // relative paths resolve to tests/data
  const DlResult3 r =
      run3("fracture_files:\n  - {file: dl3_fractures.fab}\n  - {file: dl3_polygons.csv, set_prefix: 'csv '}\n", label);
  ASSERT_GE(r.model.sets.size(), 3u);
  EXPECT_EQ(r.model.sets[0].name, "Joint set A");
  EXPECT_EQ(r.model.sets[0].origin, "fab");
  bool csv = false;
  for (const JointSetInfo& s : r.model.sets) csv = csv || (s.name.rfind("csv ", 0) == 0 && s.origin == "csv");
  EXPECT_TRUE(csv);
  const auto& f = r.report["fracture_files"];
  EXPECT_EQ(f[0]["in_domain"].get<std::size_t>() + f[1]["in_domain"].get<std::size_t>(), r.model.fractures.size());
  // Two files naming the same set need a prefix.
  const std::string twice =
      error3("fracture_files:\n  - {file: dl3_polygons.csv}\n  - {file: dl3_polygons.csv}\n", label);
  EXPECT_NE(twice.find("s3d_test.yaml:6: fracture_files[1].file brings the set"), std::string::npos) << twice;
  const std::string missing = error3("fracture_files:\n  - {file: nope.fab}\n", label);
  EXPECT_NE(missing.find("s3d_test.yaml:5: fracture_files[0].file names a fracture file with an error"),
            std::string::npos)
      << missing;
  expect_error("fracture_files:\n  - {file: traces.txt}\n", {"test.yaml:5:", "fracture_files[0].file", ".fab"});
}

// ---- excavations -------------------------------------------------------------

TEST(Scenario3d, ExcavationsAreConvexRegionsWithOutwardNormals) {
  const DlResult3 r = run3(
      "excavations:\n"
      "  - {shape: tunnel, start: [0, 5, 5], end: [10, 5, 5], radius: 1.5, sides: 16}\n"
      "  - {name: gallery, shape: tunnel, section: rectangle, start: [5, 0, 2], end: [5, 10, 2], width: 2, height: 1}\n"
      "  - {shape: box, min: [8, 8, 8], max: [12, 12, 12]}\n"
      "  - {shape: slope, dip: 45, dip_direction: 90, point: [5, 5, 10], floor: 9}\n"
      "  - {shape: half_spaces, planes: [{normal: [0, 0, -1], point: [0, 0, 9.5]}]}\n");
  ASSERT_EQ(r.model.excavations.size(), 5u);
  const auto& e = r.report["excavations"];
  // The 16-gon prism: 10 * (16 / 2) r^2 sin(2 pi / 16).
  EXPECT_NEAR(e[0]["volume_in_domain"].get<double>(), 10 * 8 * 2.25 * std::sin(kPi / 8), 1e-9);
  EXPECT_EQ(e[0]["half_spaces"], 18);
  EXPECT_EQ(r.model.excavations[0].name, "E1");
  EXPECT_NEAR(e[1]["volume_in_domain"].get<double>(), 20, 1e-9);
  EXPECT_NEAR(e[2]["volume_in_domain"].get<double>(), 8, 1e-9);  // the part in the domain
  // Slope: the air above the face z = 15 - x (through (5, 5, 10), dipping 45
  // degrees east) and above z = 9; its section across y is a triangle of 0.5
  // (5 < x < 6) and a strip of 4 x 1 (6 < x < 10), over 10 m of y.
  EXPECT_NEAR(e[3]["volume_in_domain"].get<double>(), 45, 1e-9);
  EXPECT_NEAR(e[4]["volume_in_domain"].get<double>(), 50, 1e-9);
  // The rectangle's height is along +z: its crown at z = 2.5, its walls at x = 4 and 6.
  const ConvexRegion& g = r.model.excavations[1].region;
  EXPECT_TRUE(g.contains(V3(5, 5, 2.49)));
  EXPECT_FALSE(g.contains(V3(5, 5, 2.51)));
  EXPECT_TRUE(g.contains(V3(5.99, 5, 2)));
  EXPECT_FALSE(g.contains(V3(6.01, 5, 2)));
  // The circle: a vertex at the crown, the axis inside, the caps at start and end.
  const ConvexRegion& t = r.model.excavations[0].region;
  EXPECT_TRUE(t.contains(V3(5, 5, 6.49)));
  EXPECT_FALSE(t.contains(V3(5, 5, 6.51)));
  EXPECT_FALSE(t.contains(V3(-0.01, 5, 5)));
  EXPECT_FALSE(t.contains(V3(10.01, 5, 5)));
  // Slope: open air above the face and the floor, rock below.
  const ConvexRegion& s = r.model.excavations[3].region;
  EXPECT_TRUE(s.contains(V3(9, 5, 9.5)));
  EXPECT_FALSE(s.contains(V3(4, 5, 9.5)));  // behind the crest
  EXPECT_FALSE(s.contains(V3(9, 5, 8.9)));  // below the floor

  expect_error("excavations:\n  - {shape: box, min: [20, 20, 20], max: [30, 30, 30]}\n",
               {"test.yaml:5:", "excavations[0] does not reach into the domain"});
  expect_error("excavations:\n  - {shape: tunnel, start: [0, 5, 5], end: [0, 5, 5], radius: 1}\n",
               {"test.yaml:5:", "excavations[0].end must differ from start"});
  expect_error("excavations:\n  - {shape: tunnel, start: [0, 5, 5], end: [9, 5, 5], width: 1}\n",
               {"test.yaml:5:", "unknown key 'excavations[0].width'"});
  expect_error("excavations:\n  - {shape: cone}\n", {"test.yaml:5:", "excavations[0].shape", "cone"});
  expect_error("excavations:\n  - {shape: half_spaces, planes: [{normal: [0, 0, 0], point: [1, 1, 1]}]}\n",
               {"test.yaml:5:", "excavations[0].planes[0].normal must not be the zero vector"});
}

// ---- points and trace_planes ----------------------------------------------

TEST(Scenario3d, PointsAndTracePlanes) {
  const DlResult3 r = run3(
      "points:\n  - {name: crown, kind: fixed, at: [5, 5, 6]}\n  - {name: m, at: [1, 2, 3]}\n"
      "trace_planes:\n  - {name: mid-x, point: [5, 5, 5], dip: 90, dip_direction: 90}\n");
  ASSERT_EQ(r.model.points.size(), 2u);
  EXPECT_EQ(r.model.points[0].kind, PointKind::Fixed);
  EXPECT_EQ(r.model.points[1].p, V3(1, 2, 3));
  EXPECT_EQ(r.report["points"]["measurement"], 1);
  ASSERT_EQ(r.trace_planes.size(), 1u);
  EXPECT_EQ(r.trace_planes[0].name, "mid-x");
  EXPECT_NEAR(r.report["trace_planes"][0]["section_area"].get<double>(), 100, 1e-9);
  expect_error("points:\n  - {name: far, at: [5, 5, 11]}\n", {"test.yaml:5:", "points[0].at", "outside the domain"});
  expect_error("points:\n  - {name: flat, at: [5, 5]}\n", {"test.yaml:5:", "points[0].at must be a point [x, y, z]"});
  expect_error("trace_planes:\n  - {name: a/b, point: [5, 5, 5], dip: 0, dip_direction: 0}\n",
               {"test.yaml:5:", "trace_planes[0].name", "letters, digits"});
  expect_error("trace_planes:\n  - {name: up, point: [5, 5, 50], dip: 0, dip_direction: 0}\n",
               {"test.yaml:5:", "trace_planes[0] misses the domain"});
}

}  // namespace dda::dl
