// Measurement points placed by block (`points` items with `block`;
// df/src/io/scenario_block_points.hpp) in 3D, on the V4 wedge cut by DC:
// where they start (the wedge's centroid by the tetrahedron formula), that
// they ride with the wedge (the same displacement as an explicit point at
// the same place, and the analytical slide), and one sentence for each
// mistake. 2D: test_block_points.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "../common/input_error_of.hpp"
#include "../dc/dc3d_test_util.hpp"
#include "dda/dc/cut3d.hpp"
#include "dda/df/io/scenario3d.hpp"
#include "dda/df/3d/simulation3d.hpp"
#include "dda/dl/dfn3d.hpp"

namespace dda::df3 {
namespace {

using dda::testing::input_error_of;

constexpr double kG = 9.81;
constexpr double kDeg = kPi / 180;

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// ---------------------------------------------------------------- 3D ----
// V4 (docs/validation.md), as examples/shaking_table_wedge cuts it: the box
// x in [-8, 8], y in [-2, 10], z in [0, 10] cut by the persistent planes A
// 51.4/065.8 and B 51.4/295.2 through T = (0, 0, 10), the top (z+) and the
// face y = 10 (y+) free. The block above both planes is the tetrahedral
// wedge that slides on both (slides_two_faces); the three below it hold it.
struct Wedge {
  PolyhedronModel blocks;
  int wedge = -1;
  Vec3 centroid;  // by the tetrahedron formula
  Vec3 line;      // unit line of intersection, pointing down
};

Wedge wedge_blocks() {
  Wedge w;
  const Vec3 nA = dl::normal_from_dip(51.4, 65.8), nB = dl::normal_from_dip(51.4, 295.2), T(0, 0, 10);
  w.line = nA.cross(nB).normalized();
  if (w.line.z() > 0) w.line = -w.line;
  FractureModel fm;
  fm.domain = {Vec3(-8, -2, 0), Vec3(8, 10, 10)};
  fm.sets = {{"A", "user"}, {"B", "user"}};
  fm.fractures = {dc::test3::plane(nA, T, 0), dc::test3::plane(nB, T, 1)};
  dc::Cut3dOptions options;
  options.free_boundaries = {"z+", "y+"};
  w.blocks = dc::cut_blocks_3d(fm, options).model;
  for (std::size_t b = 0; b < w.blocks.blocks.size(); ++b) {
    bool above = true;
    for (const Vec3& v : w.blocks.blocks[b].vertices) above = above && nA.dot(v - T) > -1e-9 && nB.dot(v - T) > -1e-9;
    if (above) w.wedge = static_cast<int>(b);
  }
  // The wedge's corners, each where three of its planes meet: T; D, where
  // the line of intersection leaves the face y = 10; EA and EB, where A and
  // B meet the ground z = 10 on that face (nA . (x - T) = 0 with y = 10,
  // z = 10). Its centroid is the mean of the four (tetrahedron):
  // (0.0747, 7.5, 8.691), the example's hand-rounded (0.075, 7.5, 8.69).
  const Vec3 D = T + (10 / w.line.y()) * w.line;
  const Vec3 EA(-10 * nA.y() / nA.x(), 10, 10), EB(-10 * nB.y() / nB.x(), 10, 10);
  w.centroid = (T + D + EA + EB) / 4;
  // An explicit measurement point at that centroid, as the blocks file of
  // a scenario that names it by its position has it.
  w.blocks.points = {{"explicit", PointKind::Measurement, w.centroid}};
  return w;
}

const Wedge& wedge() {
  static const Wedge w = wedge_blocks();
  return w;
}

// phi = 10 on both planes, the run of test_simulation3d_wedge.cpp (penalty
// 1e10 N/m, dt 1 ms, 0.5 s).
std::string scenario3d() {
  return R"(dimension: 3
materials:
  default: {density: 2600, young: 1.0e10, poisson: 0.25}
joints:
  default: {friction_deg: 10}
fixed: {below: 7}
control: {dt: 0.001, total_time: 0.5, normal_penalty: 1.0e10, shear_penalty: 1.0e10, contact_reach: 0.01}
points:
  - {name: by_class, block: {removability: [slides_two_faces]}}
  - {name: by_id, block: )" + std::to_string(wedge().wedge) + R"(}
  - {name: by_point, block: {containing: [0, 5, 9.5]}}
  - {name: apex, block: {containing: [0, 5, 9.5]}, at: [0, 0, 10]}
)";
}

DfScenario3 read3d(const std::string& text) {
  return read_df3_scenario(YamlNode::load_string(text, "s.yaml"), wedge().blocks, "w.h5");
}

TEST(BlockPoints3d, ByClassIdAndContainedPointAtTheWedgeCentroid) {
  const Wedge& w = wedge();
  ASSERT_GE(w.wedge, 0);
  ASSERT_EQ(w.blocks.blocks.size(), 4u);
  EXPECT_NEAR(w.centroid.x(), 0.0747, 1e-4);  // the hand-computed figures above
  EXPECT_NEAR(w.centroid.y(), 7.5, 1e-12);
  EXPECT_NEAR(w.centroid.z(), 8.691, 1e-3);
  const std::vector<MeasurementPoint3> m = read3d(scenario3d()).model.measurements;
  ASSERT_EQ(m.size(), 5u);  // the blocks file's, then the scenario's by block in file order
  for (std::size_t i = 1; i < 4; ++i) {
    EXPECT_EQ(m[i].block, w.wedge) << m[i].name;
    EXPECT_LT((m[i].position - w.centroid).norm(), 1e-9) << m[i].name;
  }
  EXPECT_EQ(m[4].name, "apex");  // given `at`: the wedge's corner T (on its boundary is in)
  EXPECT_EQ(m[4].block, w.wedge);
  EXPECT_EQ(m[4].position, Vec3(0, 0, 10));
}

// The wedge slides along the line of intersection: a = g (sin psi - K tan
// phi cos psi) = 2.3731 m/s^2 (V4, psi = 27.63, K = 1.42013), s(0.5 s) =
// 0.2966 m, within the 2 % of test_simulation3d_wedge.cpp. The points at
// its centroid move as the explicit one does, to rounding.
TEST(BlockPoints3d, RidesWithTheSlidingWedge) {
  const DfScenario3 s = read3d(scenario3d());
  Simulation3 sim(s.model);
  for (int k = 0; k < 500; ++k) sim.step(1e-3);
  auto displacement = [&](const std::string& name) {
    for (std::size_t i = 0; i < s.model.measurements.size(); ++i)
      if (s.model.measurements[i].name == name) return sim.histories()[i].back().displacement;
    ADD_FAILURE() << name;
    return Vec3(0, 0, 0);
  };
  const double psi = 27.63 * kDeg, a = kG * (std::sin(psi) - 1.42013 * std::tan(10 * kDeg) * std::cos(psi));
  const double expected = 0.5 * a * 0.25;
  const Vec3 u = displacement("by_class");
  EXPECT_NEAR(u.dot(wedge().line), expected, 0.02 * expected);
  EXPECT_LT((u - u.dot(wedge().line) * wedge().line).norm(), 0.01 * u.norm());  // along the line
  for (const std::string name : {"by_id", "by_point", "explicit"})
    EXPECT_LT((displacement(name) - u).norm(), 1e-12) << name;
  // The apex T, 7.6 m from the centroid, moves as the centroid does up to
  // the wedge's small rotation while it slides (measured 3.3e-5 m).
  EXPECT_LT((displacement("apex") - u).norm(), 1e-4);
  std::printf("3D by block: s(0.5 s) = %.6f m along the line, expected %.6f m; explicit point off by %.1e m, "
              "apex by %.1e m\n",
              u.dot(wedge().line), expected, (displacement("explicit") - u).norm(), (displacement("apex") - u).norm());
}

TEST(BlockPoints3d, EveryMistakeIsOneSentence) {
  const std::string text = scenario3d();
  const std::string first = "{name: by_class, block: {removability: [slides_two_faces]}}";
  struct Case {
    std::string to, message;
  };
  const std::vector<Case> cases{
      {"{name: by_class, block: 4}", "s.yaml:9: points[0].block is block 4, but w.h5 has 4 blocks (ids 0 to 3)."},
      {"{name: by_class, block: {removability: [falls]}}",
       "s.yaml:9: points[0].block.removability selects no block of w.h5."},
      {"{name: by_class, block: {below: 7}}",
       "s.yaml:9: points[0].block.below selects 3 blocks of w.h5 (" + [&] {
         std::string ids;
         for (int b = 0; b < 4; ++b)
           if (b != wedge().wedge) ids += (ids.empty() ? "" : ", ") + std::to_string(b);
         return ids;
       }() + "), but a point rides with one: narrow the selection or give the block's id (block: " +
           std::to_string(wedge().wedge == 0 ? 1 : 0) + ")."},
      {"{name: by_class, block: {containing: [0, 0, 20]}}",
       "s.yaml:9: points[0].block.containing puts (0, 0, 20) outside every block of w.h5."},
      {"{name: by_class, block: {containing: [0, 5, 9.5], below: 7}}",
       "s.yaml:9: points[0].block must select one block with exactly one of containing, bodies, below, box, outside, "
       "removability, got containing, below."},
      {"{name: by_class, block: {blocks: [0]}}", "s.yaml:9: unknown key 'points[0].block.blocks'"},
      {"{name: by_class, block: {removability: [slides_two_faces]}, at: [0, 0, 0]}",
       "s.yaml:9: points[0].at puts point 'by_class' at (0, 0, 0), outside block " + std::to_string(wedge().wedge) +
           " (centroid (0.0747, 7.5, 8.69)), the block it names."},
  };
  for (const Case& c : cases) {
    const std::string e = input_error_of([&] { read3d(replaced(text, first, c.to)); });
    EXPECT_EQ(e.rfind(c.message, 0), 0u) << "got: " << e << "\nexpected to start with: " << c.message;
  }
  // The corner T lies on the faces of every block: in more than one.
  EXPECT_EQ(input_error_of([&] { read3d(replaced(text, first, "{name: by_class, block: {containing: [0, 0, 10]}}")); })
                .rfind("s.yaml:9: points[0].block.containing puts (0, 0, 10) on the boundary between blocks ", 0),
            0u);
  // The check before any block exists reads the selection's values too.
  EXPECT_EQ(input_error_of([&] {
              check_df3_scenario(YamlNode::load_string(replaced(text, "[slides_two_faces]", "[slides]"), "s.yaml"));
            }),
            "s.yaml:9: points[0].block.removability[0] must be a block-theory class (not_exposed, tapered, removable, "
            "falls, slides_one_face, slides_two_faces), got 'slides'.");
}

}  // namespace
}  // namespace dda::df3
