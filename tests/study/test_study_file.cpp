// The study file: its reader's refusals (file, line and key named) and the
// expansion of grid, seeds and draws into cases.
#include <gtest/gtest.h>

#include <set>

#include "../common/input_error_of.hpp"
#include "../common/scratch_dir_test.hpp"
#include "dda/common/atomic_file.hpp"
#include "dda/study/expand.hpp"
#include "dda/study/study.hpp"
#include "dda/study/summary.hpp"

namespace dda::study {
namespace {

using dda::testing::input_error_of;

class StudyFile : public dda::testing::ScratchDirTest {
 protected:
  StudyFile() : ScratchDirTest("dda-study-file") {}
  Study read(const std::string& text) {
    write_text_atomically(path("study.yaml"), text);
    return read_study(path("study.yaml"), check_wedge_document);
  }
  std::string refusal(const std::string& text) {
    write_text_atomically(path("study.yaml"), text);
    return input_error_of([&] { read_study(path("study.yaml"), check_wedge_document); });
  }
};

// The seed wedge (docs/analytical.md): planes 51.4/065.8 and 51.4/295.2.
const std::string kWedge =
    "wedge:\n"
    "  plane1: {dip: 51.4, dip_direction: 65.8}\n"
    "  plane2: {dip: 51.4, dip_direction: 295.2}\n"
    "  phi: 30\n";

TEST_F(StudyFile, GridSeedsAndDrawsMultiply) {
  // 3 x 2 grid; a wedge takes no seeds, so 6 grid points x 5 draws.
  const Study s = read(kWedge +
                       "vary:\n  phi: [20, 30, 40]\n  plane1.dip: [45, 55]\n"
                       "sample:\n  seed: 3\n  draws: 5\n  values:\n    plane2.dip: {distribution: normal, mean: 51.4, std: 2}\n"
                       "measure: [fs]\n");
  EXPECT_EQ(s.grid_points(), 6u);
  EXPECT_EQ(s.case_count(), 30u);
  EXPECT_EQ(s.value_columns(), (std::vector<std::string>{"phi", "plane1.dip", "plane2.dip"}));
  // Case i = grid * 5 + draw, the last key fastest: case 7 is grid point 1
  // (phi 20, dip 55), draw 2; case 29 the last grid point (40, 55), draw 4.
  const Case c7 = make_case(s, 7);
  EXPECT_EQ(c7.id, "c0007");
  EXPECT_EQ(c7.values[0], "20");
  EXPECT_EQ(c7.values[1], "55");
  EXPECT_EQ(*c7.draw, 2u);
  EXPECT_EQ(c7.doc["plane1"]["dip"].as<double>(), 55.0);
  const Case c29 = make_case(s, 29);
  EXPECT_EQ(c29.values[0], "40");
  EXPECT_EQ(c29.values[1], "55");
  EXPECT_EQ(*c29.draw, 4u);
  // Every (phi, dip) pair appears five times.
  std::set<std::pair<std::string, std::string>> pairs;
  for (std::size_t i = 0; i < s.case_count(); ++i) {
    const Case c = make_case(s, i);
    pairs.insert({c.values[0], c.values[1]});
  }
  EXPECT_EQ(pairs.size(), 6u);
}

TEST_F(StudyFile, DrawsReproduceAndAreCommonAcrossTheGrid) {
  const std::string text = kWedge + "vary:\n  phi: [25, 35]\n" +
                           "sample:\n  seed: 11\n  draws: 4\n  values:\n"
                           "    plane2.dip: {distribution: uniform, min: 40, max: 60}\n"
                           "measure: [fs]\n";
  const Study a = read(text);
  const Study b = read(text);
  for (std::size_t i = 0; i < a.case_count(); ++i) {
    const Case ca = make_case(a, i), cb = make_case(b, i);
    EXPECT_EQ(ca.values, cb.values) << "case " << i;
    // Draw d has the same value at both grid points (common random numbers).
    EXPECT_EQ(ca.values[1], make_case(a, i % 4).values[1]);
  }
  // The four draws differ from each other, and another sample seed changes them.
  std::set<std::string> drawn;
  for (std::size_t d = 0; d < 4; ++d) drawn.insert(make_case(a, d).values[1]);
  EXPECT_EQ(drawn.size(), 4u);
  const Study c = read(kWedge + "vary:\n  phi: [25, 35]\n" +
                       "sample:\n  seed: 12\n  draws: 4\n  values:\n"
                       "    plane2.dip: {distribution: uniform, min: 40, max: 60}\n"
                       "measure: [fs]\n");
  EXPECT_NE(make_case(c, 0).values[1], make_case(a, 0).values[1]);
  // The drawn text is the double itself: it reads back to the value set in the document.
  const Case c0 = make_case(a, 0);
  EXPECT_EQ(std::stod(c0.values[1]), c0.doc["plane2"]["dip"].as<double>());
}

TEST_F(StudyFile, LinkedKeysChangeTogether) {
  // One grid axis of two key paths (2 points) times plane2.dip (2 values).
  const Study s = read(kWedge + "vary:\n  \"phi, plane1.dip\": [[20, 45], [30, 55]]\n  plane2.dip: [50, 52]\n" +
                       "measure: [fs]\n");
  EXPECT_EQ(s.case_count(), 4u);
  EXPECT_EQ(s.value_columns(), (std::vector<std::string>{"phi", "plane1.dip", "plane2.dip"}));
  const Case c = make_case(s, 3);
  EXPECT_EQ(c.values, (std::vector<std::string>{"30", "55", "52"}));
  EXPECT_EQ(c.doc["phi"].as<double>(), 30.0);
  EXPECT_EQ(c.doc["plane1"]["dip"].as<double>(), 55.0);
  const std::string m = refusal(kWedge + "vary:\n  \"phi, plane1.dip\": [[20, 45], [30]]\nmeasure: [fs]\n");
  EXPECT_NE(m.find("study.yaml:6: vary.phi, plane1.dip[1] must be a list of 2 values, one per key path, got 1"),
            std::string::npos)
      << m;
}

TEST_F(StudyFile, UnknownKeyPathIsNamedWithItsLine) {
  const std::string m = refusal(kWedge + "vary:\n  phi: [20]\n  plane1.dipp: [45]\nmeasure: [fs]\n");
  // Line 7 holds the list of plane1.dipp; the wedge reader names the key it does not know.
  EXPECT_NE(m.find("study.yaml:7: vary.plane1.dipp"), std::string::npos) << m;
  EXPECT_NE(m.find("unknown key 'plane1.dipp'"), std::string::npos) << m;
  EXPECT_NE(m.find("did you mean 'dip'"), std::string::npos) << m;
}

TEST_F(StudyFile, MissingIntermediateKeyIsNamed) {
  const std::string m = refusal(kWedge + "vary:\n  plane3.dip: [45]\nmeasure: [fs]\n");
  EXPECT_NE(m.find("study.yaml:6: vary.plane3.dip[0] names no key of the base (the base has no plane3)"),
            std::string::npos)
      << m;
}

TEST_F(StudyFile, ValueOutOfRangeIsNamedWithItsOwnLine) {
  const std::string m = refusal(kWedge + "vary:\n  phi:\n    - 30\n    - 95\nmeasure: [fs]\n");
  // The second value, on line 8, is above the wedge reader's range for phi.
  EXPECT_NE(m.find("study.yaml:8: vary.phi[1] = 95 is refused by the wedge reader: phi must be"), std::string::npos)
      << m;
}

TEST_F(StudyFile, EmptyGridIsRefused) {
  EXPECT_NE(refusal(kWedge + "vary:\n  phi: []\nmeasure: [fs]\n").find("study.yaml:6: vary.phi has no values"),
            std::string::npos);
  EXPECT_NE(refusal(kWedge + "vary: {}\nmeasure: [fs]\n").find("study.yaml:5: vary is empty"), std::string::npos);
  const std::string m = refusal(kWedge + "sample: {seed: 1, draws: 0, values: {phi: {distribution: normal, mean: 30, std: 2}}}\n"
                                         "measure: [fs]\n");
  EXPECT_NE(m.find("sample.draws must be in [1, "), std::string::npos) << m;
}

TEST_F(StudyFile, OtherRefusals) {
  // A pipeline measure in a wedge study.
  EXPECT_NE(refusal(kWedge + "measure: [kinetic_energy]\n").find("which a wedge study does not have; its kinds are fs"),
            std::string::npos);
  // Seeds in a wedge study.
  EXPECT_NE(refusal(kWedge + "seeds: 3\nmeasure: [fs]\n").find("study.yaml:5: seeds is for scenario realisations"),
            std::string::npos);
  // A failure rule on a measure the study does not have.
  EXPECT_NE(refusal(kWedge + "measure: [fs]\nfailure: {measure: FS, below: 1}\n")
                .find("failure.measure names no measure of the study: 'FS'"),
            std::string::npos);
  // A truncation window that keeps almost nothing of its law.
  EXPECT_NE(refusal(kWedge +
                    "sample: {seed: 1, draws: 2, values: {phi: {distribution: truncated_normal, mean: 30, std: 1, "
                    "min: 40, max: 45}}}\nmeasure: [fs]\n")
                .find("% of its law between min and max"),
            std::string::npos);
  // One key given values in two places.
  EXPECT_NE(refusal(kWedge + "vary:\n  phi: [20, 30]\nsample: {seed: 1, draws: 2, values: {phi: {distribution: "
                             "normal, mean: 30, std: 2}}}\nmeasure: [fs]\n")
                .find("study.yaml: sets the key path 'phi' twice"),
            std::string::npos);
  // A Fisher key path that holds no number of the base.
  EXPECT_NE(refusal(kWedge + "sample: {seed: 1, draws: 2, fisher: [{dip: plane1.strike, dip_direction: "
                             "plane1.dip_direction, kappa: 30}]}\nmeasure: [fs]\n")
                .find("sample.fisher[0].dip names no number of the base: 'plane1.strike'"),
            std::string::npos);
}

TEST_F(StudyFile, SummaryCsvHasOneRowPerCaseInRoundTripPrecision) {
  const Study s = read(kWedge + "vary:\n  phi: [20, 30]\nmeasure: [fs, plunge]\nfailure: {measure: fs, below: 1}\n");
  std::vector<Case> cases{make_case(s, 0), make_case(s, 1)};
  // 0.1 + 0.2 is not 0.3: its shortest round-trip text has 17 digits.
  std::vector<CaseRecord> records{{true, 0.5, "", {0.1 + 0.2, 2.0}}, {false, 1.25, "case failed, \"badly\"", {}}};
  EXPECT_EQ(summary_csv(s, cases, records),
            "case,seed,draw,phi,fs,plunge,failed,status,seconds,error\n"
            "c0000,,,20,0.30000000000000004,2,1,ok,0.5,\n"
            "c0001,,,30,,,,failed,1.25,\"case failed, \"\"badly\"\"\"\n");
}

}  // namespace
}  // namespace dda::study
