// Measurement points placed by block (`points` items with `block`;
// df/src/io/scenario_block_points.hpp) in 2D: where they start (the block's
// centroid, computed here by hand), that they ride with their block (the
// same displacement as an explicit point at the same place, and the
// analytical slide), and one sentence for each mistake. 3D:
// test_block_points3d.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "../common/input_error_of.hpp"
#include "dda/df/io/scenario.hpp"
#include "dda/df/2d/simulation.hpp"
#include "df_test_models.hpp"

namespace dda::df {
namespace {

using dda::testing::input_error_of;

constexpr double kG = 9.81;
constexpr double kDeg = kPi / 180;

std::string yaml_point(const Vec2& p) {
  char s[96];
  std::snprintf(s, sizeof s, "[%.17g, %.17g]", p.x(), p.y());
  return s;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// ---------------------------------------------------------------- 2D ----
// V1 (docs/validation.md): a 1 x 1 m block (block 1) on an 8 x 1 m slab
// (block 0, held by three fixed points) whose top dips 30 deg, as
// test_v1_sliding.cpp builds it: in the slope frame, then rotated. The
// blocks file also has an explicit measurement point `explicit` at the
// block's centre.
constexpr double kAlpha = 30 * kDeg;

Vec2 slope(double x, double y) { return test::rotated(Vec2(x, y), kAlpha); }

BlockModel incline2d() {
  BlockModel m;
  m.sets = {{"slide", "user"}};
  m.blocks = {test::make_block(test::rotated(test::rectangle(0, -1, 8, 1), kAlpha)),
              test::make_block(test::rotated(test::rectangle(6, 0, 1, 1), kAlpha))};
  for (const double x : {0.5, 4.0, 7.5})
    m.points.push_back({{"base" + std::to_string(static_cast<int>(x * 10)), PointKind::Fixed, slope(x, -0.5)}, 0});
  m.points.push_back({{"explicit", PointKind::Measurement, slope(6.5, 0.5)}, 1});
  return m;
}

// The slider's centre (6.5, 0.5) in the slope frame, rotated by 30 deg by
// hand: x = 6.5 cos 30 - 0.5 sin 30 = 5.62917 - 0.25, y = 6.5 sin 30 +
// 0.5 cos 30 = 3.25 + 0.43301.
const Vec2 kSliderCentroid(6.5 * std::sqrt(3.0) / 2 - 0.25, 3.25 + 0.5 * std::sqrt(3.0) / 2);

const std::string kScenario2d = R"(materials:
  default: {density: 2000, young: 5.0e10, poisson: 0.25, plane: stress}
joints:
  default: {friction_deg: 20}
control: {dt: 0.001, total_time: 1}
points:
  - {name: by_id, block: 1}
  - {name: by_point, block: {containing: )" + yaml_point(slope(6.2, 0.8)) + R"(}}
  - {name: corner, block: 1, at: )" + yaml_point(slope(7, 1)) + R"(}
)";

DfScenario read2d(const std::string& text) {
  return read_df_scenario(YamlNode::load_string(text, "s.yaml"), incline2d(), "b.h5");
}

const MeasurementPoint& named(const std::vector<MeasurementPoint>& points, const std::string& name) {
  for (const MeasurementPoint& p : points)
    if (p.name == name) return p;
  ADD_FAILURE() << "no measurement point " << name;
  return points.front();
}

TEST(BlockPoints2d, ByIdAndByContainedPointAtTheCentroid) {
  const std::vector<MeasurementPoint> m = read2d(kScenario2d).input.measurements;
  ASSERT_EQ(m.size(), 4u);  // the blocks file's, then the scenario's by block in file order
  EXPECT_EQ(m[1].name, "by_id");
  EXPECT_EQ(m[2].name, "by_point");
  EXPECT_EQ(m[3].name, "corner");
  for (const std::string name : {"by_id", "by_point"}) {
    EXPECT_EQ(named(m, name).block, 1) << name;
    EXPECT_LT((named(m, name).position - kSliderCentroid).norm(), 1e-12) << name;
  }
  // Given `at`: that point (a corner of the block: on its boundary is in).
  EXPECT_EQ(named(m, "corner").block, 1);
  EXPECT_EQ(named(m, "corner").position, slope(7, 1));
}

// The slider slides 1 s with phi = 20: s = g (sin 30 - cos 30 tan 20) / 2 =
// 0.906 m (V1), within V1's 1 % (test_v1_sliding.cpp). The point at the
// centroid and the explicit point at the same place move alike to rounding.
TEST(BlockPoints2d, RidesWithItsSlidingBlock) {
  const DfScenario s = read2d(kScenario2d);
  Simulation sim(build_model(s.input));
  sim.run_until(1.0);
  auto displacement = [&](const std::string& name) {
    for (std::size_t i = 0; i < s.input.measurements.size(); ++i)
      if (s.input.measurements[i].name == name) return sim.histories()[i].back().displacement;
    ADD_FAILURE() << name;
    return Vec2(0, 0);
  };
  const double expected = 0.5 * kG * (std::sin(kAlpha) - std::cos(kAlpha) * std::tan(20 * kDeg));
  const Vec2 u = displacement("by_id");
  EXPECT_NEAR(u.norm(), expected, 0.01 * expected);
  EXPECT_LT(std::abs(u.normalized().dot(slope(1, 0)) + 1), 1e-4);  // straight down the slope
  EXPECT_LT((displacement("by_point") - u).norm(), 1e-12);
  EXPECT_LT((displacement("explicit") - u).norm(), 1e-12);
  // The corner, 0.71 m from the centre, moves as the centre does up to the
  // block's rotation while it slides (measured 1.1e-7 m).
  EXPECT_LT((displacement("corner") - u).norm(), 1e-6);
  std::printf("2D by block: s(1 s) = %.6f m, expected %.6f m; explicit point off by %.1e m, corner by %.1e m\n",
              u.norm(), expected, (displacement("explicit") - u).norm(), (displacement("corner") - u).norm());
}

TEST(BlockPoints2d, EveryMistakeIsOneSentence) {
  struct Case {
    std::string from, to, message;
  };
  const std::vector<Case> cases{
      {"{name: by_id, block: 1}", "{name: by_id, block: 2}",
       "s.yaml:7: points[0].block is block 2, but b.h5 has 2 blocks (ids 0 to 1)."},
      {"{name: by_id, block: 1}", "{name: by_id, block: slider}",
       "s.yaml:7: points[0].block must be a block id (a whole number >= 0: its index in the blocks file, its "
       "block_id in ParaView) or a selection such as {containing: [x, y]}, got 'slider'."},
      {"{name: by_id, block: 1}", "{name: by_id, block: {containing: [50, 50]}}",
       "s.yaml:7: points[0].block.containing puts (50, 50) outside every block of b.h5."},
      // On the joint between slider and slab: in both blocks, so in neither.
      {"{name: by_id, block: 1}", "{name: by_id, block: {containing: " + yaml_point(slope(6.5, 0)) + "}}",
       "s.yaml:7: points[0].block.containing puts (5.63, 3.25) on the boundary between blocks 0, 1 of b.h5, so it "
       "names no one block: move it inside one of them or give its id (block: 0)."},
      {"{name: by_id, block: 1}", "{name: by_id, block: {}}",
       "s.yaml:7: points[0].block must select one block with exactly one of containing, none given."},
      {"{name: by_id, block: 1}", "{name: by_id, block: {removability: [falls]}}",
       "s.yaml:7: unknown key 'points[0].block.removability'"},
      {"{name: by_id, block: 1}", "{name: by_id, block: 0, at: " + yaml_point(slope(6.5, 0.5)) + "}",
       "s.yaml:7: points[0].at puts point 'by_id' at (5.38, 3.68), outside block 0 (centroid (3.71, 1.57)), the block "
       "it names."},
      {"{name: by_id, block: 1}", "{name: by_id, kind: load, block: 1}",
       "s.yaml:7: points[0].kind is 'load', but only a measurement point can be placed by block (give a load point "
       "its position in at, without block)."},
      {"{name: by_id, block: 1}", "{name: explicit, block: 1}",
       "s.yaml:7: points[0].name 'explicit' is already the name of another point (of b.h5 or of this list)."},
      {"{name: by_id, block: 1}", "{name: by_id, block: 1, at: [1, 2, 3]}",
       "s.yaml:7: points[0].at must be [x, y] (two numbers), got 3 numbers."},
  };
  for (const Case& c : cases) {
    const std::string text = replaced(kScenario2d, c.from, c.to);
    const std::string e = input_error_of([&] { read2d(text); });
    EXPECT_EQ(e.rfind(c.message, 0), 0u) << "got: " << e << "\nexpected to start with: " << c.message;
  }
  // The check before any block exists (`dda run` before cutting) reads the keys too.
  EXPECT_EQ(input_error_of([&] {
              check_df_scenario(YamlNode::load_string(replaced(kScenario2d, "block: 1}", "block: -1}"), "s.yaml"));
            }),
            "s.yaml:7: points[0].block must be a block id (a whole number >= 0: its index in the blocks file, its "
            "block_id in ParaView) or a selection such as {containing: [x, y]}, got '-1'.");
}

}  // namespace
}  // namespace dda::df

