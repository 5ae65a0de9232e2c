// The report: asked vs realised, totals, and the text table.
#include <gtest/gtest.h>

#include "dl_test_util.hpp"

namespace dda::dl {

TEST(DlReport, ShapeAndTotals) {
  const auto r = test::run(R"(name: report
seed: 42
domain: {box: [0, 0, 30, 20]}
joint_sets:
  - {name: J1, dip: 60, mean_length: 5, mean_bridge: 1, mean_spacing: 0.54, randomness: 0.5}
layering:
  thickness: {distribution: lognormal, mean: 1.0, std: 0.631, minimum: 0.7}
  sets:
    - {name: V, dip: 90, fsi: 1.3, randomness: 0.5}
excavations:
  - {shape: circle, center: [15, 10], radius: 3}
points:
  - {name: mp1, at: [2, 2]}
)");
  const auto& j = r.report;
  const auto& s = j["statistical_sets"][0];
  EXPECT_EQ(s["name"], "J1");
  EXPECT_EQ(s["asked"]["mean_length"].get<double>(), 5.0);
  // A few thousand traces: realised means within 10 % (about 5 standard errors).
  EXPECT_NEAR(s["realised"]["mean_length"].get<double>(), 5.0, 0.5);
  EXPECT_NEAR(s["realised"]["mean_spacing"].get<double>(), 0.54, 0.054);
  EXPECT_GT(s["in_domain"]["traces"].get<int>(), 100);
  const auto& l = j["layering"];
  EXPECT_EQ(l["layers"].size(), r.model.layers.size());
  EXPECT_EQ(l["sets"][0]["per_layer"].size(), r.model.layers.size());
  EXPECT_EQ(l["layers"][0]["target_fsi"].get<double>(), 1.3);
  // Totals agree with the model.
  EXPECT_EQ(j["totals"]["lines"].get<std::size_t>(), r.model.lines.size());
  EXPECT_EQ(j["totals"]["sets"].get<std::size_t>(), 3u);  // J1, bedding, V
  EXPECT_EQ(j["totals"]["points"].get<int>(), 1);
  std::size_t lines = 0;
  double p21 = 0;
  for (const auto& set : j["sets"]) {
    lines += set["lines"].get<std::size_t>();
    p21 += set["p21"].get<double>();
  }
  EXPECT_EQ(lines, r.model.lines.size());
  EXPECT_NEAR(p21, j["totals"]["p21"].get<double>(), 1e-9);

  const std::string text = format_report(j);
  for (const char* needle : {"seed 42", "Statistical sets", "J1", "Layering", "target FSI", "Excavations", "circle",
                             "All sets", "bedding", "Totals"})
    EXPECT_NE(text.find(needle), std::string::npos) << needle << "\n" << text;
}

TEST(DlReport, FormatsAnEmptyReport) {
  const std::string text = format_report(nlohmann::json::object());
  EXPECT_NE(text.find("DL report"), std::string::npos);
}

}  // namespace dda::dl
