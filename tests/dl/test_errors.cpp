// Every bad input is one InputError naming the file, the line and the key.
#include <gtest/gtest.h>

#include "dl_test_util.hpp"

namespace dda::dl {

namespace {

struct BadCase {
  const char* what;
  const char* yaml;
  std::vector<std::string> expected;  // substrings of the message
};

const std::string kDomain = "seed: 1\ndomain: {box: [0, 0, 20, 10]}\n";  // lines 1-2

}  // namespace

TEST(DlErrors, EveryBadInputNamesFileLineAndKey) {
  const std::vector<BadCase> cases = {
      {"negative mean length",
       "joint_sets:\n  - name: J1\n    dip: 60\n    mean_length: -3\n    mean_bridge: 1\n    mean_spacing: 1\n",
       {"test.yaml:6:", "joint_sets[0].mean_length", "must be > 0", "-3"}},
      {"randomness of 1",
       "joint_sets:\n  - {dip: 60, mean_length: 3, mean_bridge: 1, mean_spacing: 1, randomness: 1}\n",
       {"test.yaml:4:", "joint_sets[0].randomness", "[0, 1)"}},
      {"dip out of range",
       "joint_sets:\n  - {dip: 180, mean_length: 3, mean_bridge: 1, mean_spacing: 1}\n",
       {"test.yaml:4:", "joint_sets[0].dip"}},
      {"too many lines",
       "joint_sets:\n  - {dip: 0, mean_length: 0.01, mean_bridge: 0, mean_spacing: 0.001}\n",
       {"test.yaml:4:", "joint_sets[0].mean_spacing", "5 million"}},
      {"misspelt key",
       "joint_sets:\n  - {dip: 0, mean_lenght: 1, mean_bridge: 0, mean_spacing: 1}\n",
       {"test.yaml:4:", "joint_sets[0].mean_lenght", "did you mean 'mean_length'"}},
      {"duplicate set name",
       "joint_sets:\n  - {name: A, dip: 0, mean_length: 1, mean_bridge: 0, mean_spacing: 1}\n"
       "  - {name: A, dip: 90, mean_length: 1, mean_bridge: 0, mean_spacing: 1}\n",
       {"test.yaml:5:", "joint_sets[1].name", "already"}},
      {"unknown excavation shape",
       "excavations:\n  - {shape: oval, center: [5, 5]}\n",
       {"test.yaml:4:", "excavations[0].shape", "oval"}},
      {"excavation outside the domain",
       "excavations:\n  - {shape: circle, center: [19, 5], radius: 3}\n",
       {"test.yaml:4:", "excavations[0]", "outside the domain"}},
      {"horseshoe invert below the circle",
       "excavations:\n  - {shape: horseshoe, center: [10, 5], radius: 2, invert_depth: 2}\n",
       {"test.yaml:4:", "excavations[0].invert_depth", "smaller than the radius"}},
      {"arch rise above a semicircle",
       "excavations:\n  - {shape: arch, center: [10, 2], width: 4, wall_height: 1, rise: 3}\n",
       {"test.yaml:4:", "excavations[0].rise"}},
      {"point outside the domain",
       "points:\n  - {name: p1, at: [1, 1]}\n  - {name: far, kind: load, at: [25, 5]}\n",
       {"test.yaml:5:", "points[1].at", "'far'", "outside the domain"}},
      {"duplicate point name",
       "points:\n  - {name: p1, at: [1, 1]}\n  - {name: p1, at: [2, 2]}\n",
       {"test.yaml:5:", "points[1].name", "'p1'"}},
      {"unknown point kind",
       "points:\n  - {name: p1, kind: bolt, at: [1, 1]}\n",
       {"test.yaml:4:", "points[0].kind", "bolt"}},
      {"log-normal mean too small for its std (found by the fuzz target scenario2d)",
       "layering:\n  thickness:\n    mean: 4.9e-324\n    std: 0.631\n    minimum: 0.7\n",
       {"test.yaml:5:", "layering.thickness.mean", "too small for a log-normal thickness with std 0.631"}},
      {"minimum thickness too high",
       "layering:\n  thickness:\n    mean: 1\n    std: 0.3\n    minimum: 3\n",
       {"test.yaml:7:", "layering.thickness.minimum", "1%"}},
      {"mean and sigma mixed",
       "layering:\n  thickness: {mean: 1, sigma: 0.3}\n",
       {"test.yaml:4:", "layering.thickness.sigma"}},
      {"layer joints along the beds",
       "layering:\n  dip: 10\n  thickness: {distribution: constant, value: 1}\n  sets:\n    - {dip: 12, fsi: 1}\n",
       {"test.yaml:7:", "layering.sets[0].dip", "5 degrees"}},
      {"zero fsi",
       "layering:\n  thickness: {distribution: constant, value: 1}\n  sets:\n    - {dip: 90, fsi: 0}\n",
       {"test.yaml:6:", "layering.sets[0].fsi", "> 0"}},
      {"zero-length user line",
       "lines:\n  - {set: f, from: [1, 1], to: [1, 1]}\n",
       {"test.yaml:4:", "lines[0].to", "zero length"}},
      {"user line outside",
       "lines:\n  - {set: f, from: [30, 1], to: [40, 1]}\n",
       {"test.yaml:4:", "lines[0]", "outside the domain"}},
      {"missing trace file",
       "traces:\n  - {file: no_such.csv}\n",
       {"test.yaml:4:", "traces[0].file", "no_such.csv", "cannot open"}},
  };
  for (const BadCase& c : cases) {
    const std::string msg = test::error_of(kDomain + c.yaml);
    ASSERT_FALSE(msg.empty()) << c.what << ": no error";
    for (const std::string& s : c.expected) EXPECT_NE(msg.find(s), std::string::npos) << c.what << ": " << msg;
    // One sentence: no line breaks, ends with a full stop.
    EXPECT_EQ(msg.find('\n'), std::string::npos) << c.what;
    EXPECT_EQ(msg.back(), '.') << c.what << ": " << msg;
  }
}

TEST(DlErrors, DomainProblems) {
  EXPECT_NE(test::error_of("seed: 1\n").find("domain"), std::string::npos);
  std::string msg = test::error_of("domain: {box: [0, 0, -1, 5]}\n");
  EXPECT_NE(msg.find("test.yaml:1: domain.box"), std::string::npos) << msg;
  msg = test::error_of("domain:\n  polygon: [[0, 0], [4, 4], [4, 0], [0, 3]]\n");
  EXPECT_NE(msg.find("test.yaml:2: domain.polygon"), std::string::npos) << msg;
  EXPECT_NE(msg.find("simple"), std::string::npos) << msg;
  msg = test::error_of("domain: {box: [0, 0, 1, 1], polygon: [[0, 0], [1, 0], [0, 1]]}\n");
  EXPECT_NE(msg.find("exactly one of box, polygon"), std::string::npos) << msg;
  msg = test::error_of("domain: {box: [0, 0, 1, 1]}\nlayring: {}\n");
  EXPECT_NE(msg.find("test.yaml:2: unknown key 'layring'"), std::string::npos) << msg;
}

}  // namespace dda::dl
