// The strict scenario reader: every kind of bad input is one sentence that
// names the file, the line and the key path.
#include <gtest/gtest.h>

#include "dda/common/error.hpp"
#include "dda/common/scenario.hpp"
#include "dda/common/yaml_reader.hpp"

using dda::InputError;
using dda::Range;
using dda::YamlNode;

namespace {

// Runs `f` and returns the InputError message (fails the test if none).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return "";
}

const char* kScenario =
    "name: test\n"                 // line 1
    "domain:\n"                    // line 2
    "  box: [0, 0, 10, 5]\n"       // line 3
    "joint_sets:\n"                // line 4
    "  - name: J1\n"               // line 5
    "    mean_length: -3\n"        // line 6
    "    mean_lenght: 4\n"         // line 7
    "    dip: steep\n"             // line 8
    "    spacing: [1, 2]\n";       // line 9

}  // namespace

TEST(YamlReader, ReadsTypedValues) {
  const YamlNode root = YamlNode::load_string("a: 1.5\nb: 7\nc: hello\nd: true\ne: [1, 2]\n", "t.yaml");
  EXPECT_DOUBLE_EQ(root.number("a"), 1.5);
  EXPECT_EQ(root.integer("b"), 7);
  EXPECT_EQ(root.text("c"), "hello");
  EXPECT_TRUE(root.flag("d", false));
  EXPECT_EQ(root.point("e"), dda::Vec2(1, 2));
  EXPECT_DOUBLE_EQ(root.number("missing", 2.5, Range::positive()), 2.5);
}

TEST(YamlReader, OutOfRangeNamesFileLineAndKeyPath) {
  const YamlNode root = YamlNode::load_string(kScenario, "tunnel.yaml");
  const YamlNode set = root.list("joint_sets").at(0);
  const std::string msg = error_of([&] { set.number("mean_length", Range::positive()); });
  EXPECT_EQ(msg, "tunnel.yaml:6: joint_sets[0].mean_length must be > 0, got -3.");
}

TEST(YamlReader, UnknownKeySuggestsTheClosestAllowedKey) {
  const YamlNode root = YamlNode::load_string(kScenario, "tunnel.yaml");
  const YamlNode set = root.list("joint_sets").at(0);
  const std::string msg = error_of([&] { set.allow({"name", "mean_length", "dip", "spacing"}); });
  EXPECT_NE(msg.find("tunnel.yaml:7:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("unknown key 'joint_sets[0].mean_lenght'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("did you mean 'mean_length'"), std::string::npos) << msg;
}

TEST(YamlReader, WrongTypeNamesTheValue) {
  const YamlNode root = YamlNode::load_string(kScenario, "tunnel.yaml");
  const YamlNode set = root.list("joint_sets").at(0);
  EXPECT_EQ(error_of([&] { set.number("dip"); }), "tunnel.yaml:8: joint_sets[0].dip must be a number, got 'steep'.");
  EXPECT_EQ(error_of([&] { set.number("spacing"); }),
            "tunnel.yaml:9: joint_sets[0].spacing must be a number, got a list.");
}

TEST(YamlReader, MissingRequiredKeyNamesTheParentLine) {
  const YamlNode root = YamlNode::load_string(kScenario, "tunnel.yaml");
  const YamlNode set = root.list("joint_sets").at(0);
  EXPECT_EQ(error_of([&] { set.number("mean_spacing"); }),
            "tunnel.yaml:5: required key 'joint_sets[0].mean_spacing' is missing.");
}

TEST(YamlReader, SyntaxErrorNamesTheLine) {
  const std::string msg = error_of([] { YamlNode::load_string("a: 1\nb: [1, 2\nc: 3\n", "bad.yaml"); });
  EXPECT_EQ(msg.rfind("bad.yaml:", 0), 0u) << msg;
  EXPECT_NE(msg.find("is not valid YAML"), std::string::npos) << msg;
}

TEST(YamlReader, RejectsNonFiniteNumbersAndBadChoices) {
  const YamlNode root = YamlNode::load_string("a: .nan\nshape: hexagon\n", "s.yaml");
  EXPECT_EQ(error_of([&] { root.number("a"); }), "s.yaml:1: a must be a finite number, got '.nan'.");
  EXPECT_EQ(error_of([&] { root.choice("shape", {"circle", "rectangle"}); }),
            "s.yaml:2: shape must be one of circle, rectangle, got 'hexagon'.");
}

TEST(YamlReader, OneOfRequiresExactlyOne) {
  const YamlNode root = YamlNode::load_string("domain:\n  box: [0, 0, 1, 1]\n  polygon: [[0,0],[1,0],[0,1]]\n", "d.yaml");
  const std::string msg = error_of([&] { root.child("domain").one_of({"box", "polygon"}); });
  EXPECT_EQ(msg, "d.yaml:2: domain must have exactly one of box, polygon, got box and polygon.");
}

TEST(YamlReader, DegeneratePolygonIsRejected) {
  const YamlNode root = YamlNode::load_string("p: [[0,0],[1,1],[2,2]]\n", "p.yaml");
  EXPECT_EQ(error_of([&] { root.polygon("p"); }), "p.yaml:1: p must enclose a non-zero area.");
}

TEST(YamlReader, HugeNumbersAreRefusedForTheirSizeNotAsNoNumber) {
  // 1.1e300 is a number; it is beyond the +-1e300 every input is held to,
  // and the sentence says that (it used to say "must be a number").
  const YamlNode root = YamlNode::load_string("x: 1.1e300\n", "h.yaml");
  EXPECT_EQ(error_of([&] { root.number("x"); }), "h.yaml:1: x must be at most 1e+300 in magnitude, got 1.1e+300.");
}

TEST(Scenario, UnknownTopLevelSectionIsReported) {
  const std::string path = ::testing::TempDir() + "/unknown_section.yaml";
  FILE* f = std::fopen(path.c_str(), "w");
  std::fputs("domain:\n  box: [0, 0, 1, 1]\njoint_set:\n  - name: a\n", f);
  std::fclose(f);
  const std::string msg = error_of([&] { dda::load_scenario(path); });
  EXPECT_NE(msg.find(path + ":3: unknown key 'joint_set' (did you mean 'joint_sets'?)"), std::string::npos) << msg;
}

TEST(Scenario, MissingFileIsOneSentence) {
  EXPECT_EQ(error_of([] { dda::load_scenario("/nonexistent/s.yaml"); }),
            "/nonexistent/s.yaml: cannot open the scenario file.");
}

TEST(Scenario, SeedDefaultsToOneAndMustBeNonNegative) {
  EXPECT_EQ(dda::scenario_seed(YamlNode::load_string("name: a\n", "s.yaml")), 1u);
  EXPECT_EQ(dda::scenario_seed(YamlNode::load_string("seed: 42\n", "s.yaml")), 42u);
  EXPECT_EQ(error_of([] { dda::scenario_seed(YamlNode::load_string("seed: -4\n", "s.yaml")); }),
            "s.yaml:1: seed must be >= 0, got -4.");
}

// Strict loading (docs/reliability.md): yaml-cpp alone keeps the first of two
// equal keys and reads only the first document, so an edit further down a
// file would be ignored without a word.

TEST(YamlStrict, KeyGivenTwiceNamesTheKeyPathAndBothLines) {
  const char* text =
      "name: a\n"         // 1
      "control:\n"        // 2
      "  dt: 0.001\n"     // 3
      "  steps: 10\n"     // 4
      "  dt: 0.002\n";    // 5
  EXPECT_EQ(error_of([&] { YamlNode::load_string(text, "s.yaml"); }),
            "s.yaml: key 'control.dt' is given twice (lines 3 and 5).");
  EXPECT_EQ(error_of([] { YamlNode::load_string("seed: 1\nname: a\nseed: 2\n", "s.yaml"); }),
            "s.yaml: key 'seed' is given twice (lines 1 and 3).");
}

TEST(YamlStrict, KeyGivenTwiceInsideAListOrAFlowMapping) {
  EXPECT_EQ(error_of([] { YamlNode::load_string("sets:\n  - name: J1\n    dip: 30\n    dip: 40\n", "s.yaml"); }),
            "s.yaml: key 'sets[0].dip' is given twice (lines 3 and 4).");
  EXPECT_EQ(error_of([] { YamlNode::load_string("domain: {box: [0, 0, 1, 1], box: [0, 0, 2, 2]}\n", "s.yaml"); }),
            "s.yaml: key 'domain.box' is given twice (both on line 1).");
}

TEST(YamlStrict, EqualKeysInDifferentMappingsAndAliasesAreFine) {
  const YamlNode root =
      YamlNode::load_string("a: &m {x: 1, y: 2}\nb: *m\nc:\n  - {x: 3}\n  - {x: 4}\n", "s.yaml");
  EXPECT_EQ(root.child("b").number("y"), 2);
  EXPECT_EQ(root.keys(), (std::vector<std::string>{"a", "b", "c"}));
}

TEST(YamlStrict, SecondDocumentIsAnErrorNamingTheFileAndLine) {
  EXPECT_EQ(error_of([] { YamlNode::load_string("name: a\nseed: 1\n---\nseed: 2\n", "s.yaml"); }),
            "s.yaml:3: a second YAML document starts here ('---'); the file must hold exactly one.");
  // An empty second document counts too: it is still a stray separator.
  EXPECT_NE(error_of([] { YamlNode::load_string("name: a\n---\n", "s.yaml"); }).find("s.yaml:2: a second"),
            std::string::npos);
  // One document with its optional markers is fine.
  EXPECT_EQ(YamlNode::load_string("---\nname: a\n...\n", "s.yaml").text("name"), "a");
}

// Found by fuzzing (docs/reliability.md, "Fuzzing"): yaml-cpp 0.7's
// LoadAll never ended on a stray ',' where a node should start, filling
// the memory; the loader now says where the YAML is wrong.
TEST(YamlStrict, StrayCommaIsAnErrorNotAnEndlessParse) {
  EXPECT_EQ(error_of([] { YamlNode::load_string(",\n", "s.yaml"); }),
            "s.yaml:1: is not valid YAML (no node can start at column 1).");
  EXPECT_EQ(error_of([] { YamlNode::load_string("# a comment\n, layered: a\n", "s.yaml"); }),
            "s.yaml:2: is not valid YAML (no node can start at column 1).");
}

TEST(YamlStrict, LoadFileChecksToo) {
  const std::string path = ::testing::TempDir() + "/twice.yaml";
  FILE* f = std::fopen(path.c_str(), "w");
  std::fputs("domain:\n  box: [0, 0, 1, 1]\ndomain:\n  box: [0, 0, 2, 2]\n", f);
  std::fclose(f);
  EXPECT_EQ(error_of([&] { dda::load_scenario(path); }), path + ": key 'domain' is given twice (lines 1 and 3).");
}
