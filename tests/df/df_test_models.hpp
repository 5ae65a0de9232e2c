#pragma once
// Small hand-built models shared by the DF tests.
#include <cmath>
#include <map>
#include <string>

#include "dda/common/block_model.hpp"
#include "dda/common/block_shape.hpp"
#include "dda/common/geometry.hpp"
#include "dda/df/2d/model.hpp"

namespace dda::df::test {

// The tests' blocks are made as the benchmarks' are (dda/common/block_shape.hpp).
using dda::make_block;

inline Polygon2 rectangle(double x0, double y0, double w, double h) {
  return {{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}};
}

// Rotates a polygon (or point) by `angle` radians about the origin.
inline Vec2 rotated(const Vec2& p, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * p.x() - s * p.y(), s * p.x() + c * p.y()};
}
inline Polygon2 rotated(const Polygon2& poly, double angle) {
  Polygon2 out;
  for (const Vec2& p : poly) out.push_back(rotated(p, angle));
  return out;
}

inline Material rock(double density = 2000, double young = 1e9) {
  Material m;
  m.density = density;
  m.young = young;
  m.poisson = 0.25;
  m.plane = PlaneMode::Stress;
  return m;
}

// A brick wall (running bond, bricks 1 x 0.5 m) of `rows` x `cols` on a
// base held by three fixed points, under gravity: a contact-rich model.
inline ModelInput brick_wall(int rows, int cols, const std::string& solver = "auto") {
  ModelInput in;
  in.geometry.blocks.push_back(make_block(rectangle(-1, -1, cols + 3, 1)));
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      in.geometry.blocks.push_back(make_block(rectangle(c + 0.5 * (r % 2), 0.5 * r, 1, 0.5)));
  in.materials = {rock(2600, 5e9)};
  JointProperties j;
  j.friction_deg = 35;
  in.joint_sets = {j};
  in.control.dt = 1e-3;
  in.control.w0 = 1.0;
  in.control.solver = solver;
  for (const double x : {-0.5, 0.5 * cols, cols + 1.5}) in.fixed_points.push_back({"base", Vec2(x, -0.5), 0, {}});
  return in;
}

// Two 1 m blocks side by side, joint set "J" (0) between them, given about
// `origin` (the model's local origin, coordinate_range.hpp).
inline BlockModel two_blocks(const Vec2& origin = Vec2(0, 0)) {
  BlockModel m;
  m.sets = {{"J", "user"}};
  for (int k = 0; k < 2; ++k) {
    Block b = make_block(rectangle(k, 0, 1, 1));
    b.edge_set = {kBoundarySet, k == 0 ? 0 : kBoundarySet, kBoundarySet, k == 1 ? 0 : kBoundarySet};
    m.blocks.push_back(b);
  }
  m.origin = origin;
  return m;
}

// A joint with friction law `name`, its numeric parameters and its option
// words (as a scenario's joints section gives them).
inline JointProperties friction_joint(const std::string& name, std::map<std::string, double> numbers,
                                      std::map<std::string, std::string> words = {}) {
  JointProperties j;
  j.friction_law = name;
  j.friction_parameters = std::move(numbers);
  j.friction_options = std::move(words);
  return j;
}

}  // namespace dda::df::test
