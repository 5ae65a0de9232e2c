#pragma once
// The V3 model (docs/validation.md) in 2D, shared by the earthquake tests: a block on
// a plane dipping 20 degrees towards +x, built as blocks plus a scenario so
// that the whole earthquake input path (scenario -> record -> mode ->
// solver) is exercised.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "df_test_models.hpp"
#include "dda/common/block_model.hpp"
#include "dda/common/yaml_reader.hpp"
#include "dda/df/io/scenario.hpp"

namespace dda::df::test {

constexpr double kV3Dip = 20.0;   // degrees, dipping towards +x (east)
constexpr double kV3Phi = 30.0;   // degrees
constexpr double kV3G = 9.81;

// Down the plane, in model axes.
inline Vec2 v3_downslope() {
  const double a = deg2rad(kV3Dip);
  return {std::cos(a), -std::sin(a)};
}

// Plane: a 10 m x 1 m slab whose top face dips 20 degrees towards +x, held
// by the fixed points base1..3; slider: 1 m x 1 m on it, 1.5 m from the
// upper end (local x = 1.5..2.5, downhill is local +x), leaving 7.5 m of
// run-out for the ~1.24 m it slides. Measurement points: `slider` (its
// centre) and `ground` (in the slab). Every edge belongs to set 0 ("joint").
inline BlockModel v3_blocks() {
  const double a = -deg2rad(kV3Dip);  // rotating by -dip makes local +x point down the plane
  BlockModel m;
  m.sets.push_back({"joint", "user"});
  m.blocks.push_back(make_block(rotated(rectangle(0, -1, 10, 1), a)));
  m.blocks.push_back(make_block(rotated(rectangle(1.5, 0, 1, 1), a)));
  auto point = [&](const std::string& name, PointKind kind, Vec2 local, int block) {
    m.points.push_back({{name, kind, rotated(local, a)}, block});
  };
  point("base1", PointKind::Fixed, {0.5, -0.5}, 0);
  point("base2", PointKind::Fixed, {5.0, -0.5}, 0);
  point("base3", PointKind::Fixed, {9.5, -0.5}, 0);
  point("ground", PointKind::Measurement, {5.0, -0.5}, 0);
  point("slider", PointKind::Measurement, {2.0, 0.5}, 1);
  return m;
}

// V3 ground acceleration as a CSV record (m/s^2): body acceleration
// +0.5 g sin(10 t) along x (docs/validation.md writes r = g [0.5 sin 10t, 0, -1]),
// i.e. ground acceleration a_g = -0.5 g sin(10 t). Sampled every 1 ms to
// 2 pi + 0.01 s; the same file feeds the Newmark reference.
inline std::string write_v3_record(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  const std::filesystem::path p = dir / "v3_ground.csv";
  std::ofstream f(p);
  f.precision(17);
  f << "t,ax,ay\n";
  const int n = static_cast<int>(std::ceil((2 * M_PI + 0.01) / 1e-3));
  for (int i = 0; i <= n; ++i) {
    const double t = i * 1e-3;
    f << t << "," << -0.5 * kV3G * std::sin(10 * t) << ",0\n";
  }
  return p.string();
}

// The DF scenario of V3 with the given earthquake entry (YAML flow mapping).
// Why these settings make a fair comparison with the rigid block:
//  * E = 50 GPa and the default penalty 50 E (2.5e12 N/m): the contact
//    compliance (m g / pn ~ 1e-8 m) and the block's own elastic bounce are
//    far below the metre of sliding (V1 found E and pn the error source).
//  * dt = 1 ms: the input changes sign every 0.31 s, so a step is 1/628 of
//    a period; Newmark uses 0.1 ms, converged to 5 digits.
//  * initial_equilibrium: the block starts at rest on its loaded contact,
//    as the rigid block does; without it the start-up slide while the
//    normal force builds up leaves a speed error (settle.cpp).
inline std::string v3_scenario(const std::string& earthquake, double total_time = 2 * M_PI) {
  char time[64];
  std::snprintf(time, sizeof time, "%.17g", total_time);
  return std::string("materials:\n  default: {density: 2000, young: 5e10, poisson: 0.25, plane: stress}\n"
                     "joints:\n  default: {friction_deg: 30}\n"
                     "loading:\n  gravity: [0, -9.81]\n  earthquake: ") +
         earthquake + "\ncontrol: {dt: 0.001, total_time: " + time + ", initial_equilibrium: true}\n";
}

inline DfScenario read_v3(const std::filesystem::path& dir, const std::string& earthquake,
                          double total_time = 2 * M_PI) {
  const YamlNode root = YamlNode::load_string(v3_scenario(earthquake, total_time), (dir / "v3.yaml").string());
  return read_df_scenario(root, v3_blocks(), "v3_blocks.h5");
}

}  // namespace dda::df::test
