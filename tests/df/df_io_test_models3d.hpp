#pragma once
// The blocks of the 3D scenario and results tests: V1 in 3D as DC would
// write it, a 1 m cube on a 10 x 10 x 1 m base whose top is a plane dipping
// 20 deg east, the plane's top face and the cube's bottom of joint set 0
// ("slide"), optionally with points of the blocks file.
#include <vector>

#include "dda/common/polyhedron_model.hpp"
#include "dda/df/3d/block3d.hpp"
#include "dda/df/io/results3d.hpp"
#include "df_test_models3d.hpp"

namespace dda::df3::testing {

inline PolyhedronModel incline_blocks(std::vector<ModelPoint3> points = {}) {
  const Eigen::Matrix3d r = plane_rotation(20, 90);
  PolyhedronModel m;
  m.blocks = {box({-5, -5, -1}, {5, 5, 0}, r), box({-0.5, -0.5, 0}, {0.5, 0.5, 1}, r)};
  m.blocks[0].faces[1].set = 0;  // the plane's top
  m.blocks[1].faces[0].set = 0;  // the cube's bottom
  for (Polyhedron& p : m.blocks) refresh_geometry(p), p.body = -1;
  m.sets = {{"slide", "plane"}};
  m.points = std::move(points);
  return m;
}

// An empty results file for `blocks`: frames every 10 steps, made-up
// provenance.
inline Results3 fresh_results3(const PolyhedronModel& blocks) {
  Results3 r;
  r.blocks = blocks;
  r.source.provenance.scenario_path = "test";
  r.source.blocks_path = "blocks3d.h5";
  r.output.every = 10;
  return r;
}

}  // namespace dda::df3::testing
