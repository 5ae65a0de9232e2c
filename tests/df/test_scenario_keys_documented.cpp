// Every scenario key the forward run reads is documented in docs/scenario.md:
//   - the parameters each registered friction law declares (its spec) and
//     the numbers of each normal law, in the row of that law's table;
//   - every key the 2D and 3D DF readers allow (df/src/io/scenario*.cpp), as
//     they declare them to the strict YAML reader (YamlNode::allow, heard
//     through observe_allowed_keys while the scenarios below are read), and
//     the top-level sections (scenario_sections()).
// So that no reader escapes the check, every allow() call in
// df/src/io/scenario* must have been heard: a new reader section needs a
// scenario below that reaches it.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "dda/common/error.hpp"
#include "dda/common/scenario.hpp"
#include "dda/common/yaml_reader.hpp"
#include "dda/df/core/friction.hpp"
#include "dda/df/core/normal_law.hpp"
#include "dda/df/io/scenario.hpp"
#include "dda/df/io/scenario3d.hpp"
#include "df_io_test_models3d.hpp"
#include "df_test_models.hpp"

namespace dda::df {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = DDA_SOURCE_DIR;

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

const std::string& scenario_doc() {
  static const std::string text = read_text(kSource / "docs" / "scenario.md");
  return text;
}

bool mentions(const std::string& text, const std::string& key) {
  return text.find("`" + key + "`") != std::string::npos;
}

// The part of docs/scenario.md under the first heading whose title starts
// with `start`, up to the next heading of the same or a higher level ("" if
// there is none).
std::string doc_section(const std::string& start) {
  std::istringstream in(scenario_doc());
  std::string out;
  int level = 0;
  bool code = false;  // inside a ``` block, where "# ..." is a YAML comment
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("```", 0) == 0) code = !code;
    const std::size_t hashes = line.find_first_not_of('#');
    const bool heading = !code && hashes > 0 && hashes != std::string::npos && line[hashes] == ' ';
    if (level > 0 && heading && static_cast<int>(hashes) <= level) break;
    if (level == 0 && heading && line.compare(hashes + 1, start.size(), start) == 0) level = static_cast<int>(hashes);
    if (level > 0) out += line + "\n";
  }
  return out;
}

// The scenario's top-level section of a key path: "loading" of
// "loading.earthquake.filter", "points" of "points[0].block".
std::string top_section(const std::string& path) { return path.substr(0, path.find_first_of(".[")); }

// A key of `path` is documented when the doc's section of its top-level
// section names it (3D: or the section on the 3D forward run, which gives
// what differs from 2D).
bool documented(const std::string& path, const std::string& key, bool three_d) {
  if (path.empty()) return mentions(scenario_doc(), key);
  if (mentions(doc_section("`" + top_section(path) + "`"), key)) return true;
  return three_d && mentions(doc_section("The 3D forward run"), key);
}

// The row of docs/scenario.md's law table that starts with `name`.
std::string law_row(const std::string& name) {
  std::istringstream in(scenario_doc());
  for (std::string line; std::getline(in, line);)
    if (line.rfind("| `" + name + "` |", 0) == 0) return line;
  return "";
}

TEST(ScenarioKeysDocumented, EveryFrictionLawParameter) {
  ASSERT_FALSE(friction_laws().empty());
  for (const FrictionLawEntry& law : friction_laws()) {
    const std::string row = law_row(law.name);
    ASSERT_FALSE(row.empty()) << "docs/scenario.md has no row for friction law " << law.name;
    const FrictionLawSpec spec = law.spec();
    for (const FrictionParameter& p : spec.numbers)
      EXPECT_NE(row.find("`" + p.key + "`"), std::string::npos)
          << "docs/scenario.md: friction law " << law.name << " does not document its parameter " << p.key;
    for (const FrictionOption& w : spec.words) {
      EXPECT_NE(row.find("`" + w.key + "`"), std::string::npos)
          << "docs/scenario.md: friction law " << law.name << " does not document its option " << w.key;
      for (const std::string& c : w.choices)
        EXPECT_NE(row.find("`" + c + "`"), std::string::npos)
            << "docs/scenario.md: friction law " << law.name << " does not document " << w.key << ": " << c;
    }
  }
}

TEST(ScenarioKeysDocumented, EveryNormalLawParameter) {
  ASSERT_FALSE(normal_laws().empty());
  for (const NormalLawEntry& law : normal_laws()) {
    const std::string row = law_row(law.name);
    ASSERT_FALSE(row.empty()) << "docs/scenario.md has no row for normal law " << law.name;
    for (const NormalLawParameter& p : law.numbers)
      EXPECT_NE(row.find("`" + p.key + "`"), std::string::npos)
          << "docs/scenario.md: normal law " << law.name << " does not document its parameter " << p.key;
  }
}

// ---- The readers' keys.

// Two blocks of 2 x 1 m side by side, joint sets "bed" and "cross", a
// fixed, a load and a measurement point.
BlockModel blocks_2d() {
  BlockModel m;
  m.sets = {{"bed", "layered"}, {"cross", "layered"}};
  m.layers = {Layer{0, 1, 0, 0}};
  for (int col = 0; col < 2; ++col) {
    Block b = test::make_block(test::rectangle(2.0 * col, 0, 2, 1));
    b.edge_set = {0, col == 0 ? 1 : kBoundarySet, kBoundarySet, col == 1 ? 1 : kBoundarySet};
    b.layer = 0;
    m.blocks.push_back(b);
  }
  m.points = {{{"anchor", PointKind::Fixed, {1, 0.5}}, 0},
              {{"push", PointKind::Load, {3, 0.5}}, 1},
              {{"crown", PointKind::Measurement, {1, 0.9}}, 0}};
  return m;
}

std::vector<ModelPoint3> points_3d() {
  const Eigen::Matrix3d r = df3::testing::plane_rotation(20, 90);
  return {{"top", PointKind::Measurement, r * Vec3(0, 0, 0.9)},
          {"push", PointKind::Load, r * Vec3(0, 0, 0.5)},
          {"base", PointKind::Fixed, r * Vec3(0, 0, -0.5)}};
}

const std::string kRecord = std::string(DDA_TEST_DATA_DIR) + "/rec_small.at2";

// 2D scenarios, together reaching every allow() of the 2D readers. A read
// may end in an error once the keys are declared (the keys are what counts).
std::vector<std::string> scenarios_2d() {
  return {
      R"(materials:
  default: {density: 2500, young: 2.0e10, poisson: 0.2}
  zones:
    - {layers: [0, 0], young: 1.0e10}
joints:
  default: {friction_deg: 35, cohesion: 1000}
  cross:
    friction_law: {name: slip_weakening, mu_s: 0.6, mu_d: 0.4, dc: 0.001}
    normal_law: {name: oden_martins, c_n: 1.0e12, m_n: 1.5}
loading:
  gravity: 9.8
  point_loads:
    - {point: push, force: [100, 0]}
fixed:
  boundary: [bottom]
  points:
    - {point: anchor, penalty: 1.0e12}
points:
  - {name: slider, block: {containing: [3, 0.5]}}
bolts:
  - {name: b1, from: [1, 0.5], to: [3, 0.5], stiffness: 1.0e8}
water: {level: 0.5}
control: {dt: 0.002, total_time: 0.1, damping: {ratio: 0.05, frequency: 10}}
)",
      R"(joints:
  cross: {}
control: {dt: 0.002, total_time: 0.1}
)",
      R"(loading:
  earthquake: {record: )" + kRecord + R"(, mode: incident, filter: {type: lowpass, corner: 2.5}}
boundaries: {viscous: [bottom], free_field: [left, right]}
control: {dt: 0.002, total_time: 0.1}
)",
  };
}

std::vector<std::string> scenarios_3d() {
  return {
      R"(dimension: 3
materials:
  default: {density: 2500, young: 2.0e10, poisson: 0.2}
  zones:
    - {box: [-1, -1, -1, 1, 1, 1], young: 1.0e10}
joints:
  default: {friction_deg: 35}
  slide: {friction_law: {name: degradation, phi_peak: 35, phi_residual: 22, dc: 0.001}}
loading:
  gravity: 9.8
  point_loads:
    - {point: push, force: [0, 100, 0]}
fixed:
  blocks: [0]
  points:
    - {point: base, penalty: 1.0e12}
points:
  - {name: cube, block: {containing: [0, 0, 0.5]}}
bolts:
  - {name: b1, from: [0, 0, -0.5], to: [0, 0, 0.5], stiffness: 1.0e8}
boundaries: {viscous: [bottom]}
water: {level: 0.5}
control: {dt: 0.002, total_time: 0.1, damping: {ratio: 0.05, frequency: 10}}
)",
      R"(dimension: 3
loading:
  earthquake: {record: )" + kRecord + R"(, filter: {type: lowpass, corner: 2.5}}
fixed: {below: -0.2}
control: {dt: 0.002, total_time: 0.1}
)",
  };
}

// One declaration heard, and whether a 3D reader made it.
struct Heard {
  AllowedKeys keys;
  bool three_d = false;
};

// Every allow() heard while `read` runs, by "file:line:path" and dimension
// (the joints reader, say, serves both).
void hear(const std::function<void()>& read, bool three_d, std::map<std::string, Heard>& heard) {
  observe_allowed_keys([&heard, three_d](const AllowedKeys& a) {
    heard[a.file + ":" + std::to_string(a.line) + ":" + a.path + (three_d ? ":3d" : ":2d")] = {a, three_d};
  });
  try {
    read();
  } catch (const InputError&) {
    // the keys were declared before the reader went on to check the values
  }
  observe_allowed_keys({});
}

std::map<std::string, Heard> heard_from_the_readers() {
  std::map<std::string, Heard> heard;
  const BlockModel b2 = blocks_2d();
  for (const std::string& text : scenarios_2d())
    hear([&] { read_df_scenario(load_scenario_text(text, "s.yaml"), b2, "b.h5"); }, false, heard);
  const PolyhedronModel b3 = df3::testing::incline_blocks(points_3d());
  for (const std::string& text : scenarios_3d())
    hear([&] { df3::read_df3_scenario(load_scenario_text(text, "s.yaml"), b3, "b3.h5"); }, true, heard);
  return heard;
}

// The allow() calls of the DF readers' sources, "df/src/io/NAME:LINE".
std::set<std::string> allow_calls_in_the_readers() {
  std::set<std::string> calls;
  const std::regex call(R"((\.|->)allow\()");
  for (const auto& e : fs::directory_iterator(kSource / "df" / "src" / "io")) {
    const std::string name = e.path().filename().string();
    if (name.rfind("scenario", 0) != 0) continue;
    std::ifstream in(e.path());
    int n = 0;
    for (std::string line; std::getline(in, line);) {
      ++n;
      const std::size_t code = line.find_first_not_of(' ');
      if (code != std::string::npos && line.compare(code, 2, "//") == 0) continue;
      if (std::regex_search(line, call)) calls.insert("df/src/io/" + name + ":" + std::to_string(n));
    }
  }
  return calls;
}

TEST(ScenarioKeysDocumented, TheScenariosReachEveryReader) {
  std::set<std::string> reached;
  for (const auto& [where, h] : heard_from_the_readers()) {
    const std::string site = h.keys.file + ":" + std::to_string(h.keys.line);
    const std::size_t at = site.find("df/src/");
    if (at != std::string::npos) reached.insert(site.substr(at));
  }
  const std::set<std::string> calls = allow_calls_in_the_readers();
  ASSERT_GT(calls.size(), 10u) << "the search for allow() calls found almost none";
  for (const std::string& c : calls)
    EXPECT_TRUE(reached.count(c)) << c << " declares scenario keys that no scenario of this test reaches: "
                                  << "add one to scenarios_2d() or scenarios_3d()";
}

TEST(ScenarioKeysDocumented, EveryKeyTheReadersAllow) {
  std::map<std::string, std::set<std::string>> missing;  // key -> where it is allowed
  for (const auto& [where, h] : heard_from_the_readers())
    for (const std::string& key : h.keys.keys)
      if (!documented(h.keys.path, key, h.three_d))
        missing[key].insert((h.keys.path.empty() ? "(top level)" : h.keys.path) + (h.three_d ? " (3D)" : ""));
  for (const std::string& key : scenario_sections())
    if (!mentions(scenario_doc(), key)) missing[key].insert("(top level)");
  for (const auto& [key, paths] : missing) {
    std::string at;
    for (const std::string& p : paths) at += (at.empty() ? "" : ", ") + p;
    ADD_FAILURE() << "docs/scenario.md does not document the key " << key << " (allowed in " << at << ")";
  }
}

}  // namespace
}  // namespace dda::df
