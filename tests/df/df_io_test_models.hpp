#pragma once
// The 2D models and results of the results, checkpoint and writer tests
// (the 3D ones are in df_io_test_models3d.hpp).
#include "dda/df/io/results.hpp"
#include "df_test_models.hpp"

namespace dda::df::test {

// A 1 x 1 block falling freely onto a fixed 4 x 1 base from 0.1 m, for
// 0.3 s at dt 2 ms, with a measurement point on top of it.
inline ModelInput drop_model() {
  ModelInput in;
  in.geometry.blocks.push_back(make_block(rectangle(0, 0, 4, 1), 0));
  in.geometry.blocks.push_back(make_block(rectangle(1.5, 1.1, 1, 1), 0));
  in.geometry.sets = {{"J", "user"}};
  in.geometry.points = {{{"f", PointKind::Fixed, {0.5, 0.5}}, 0},
                        {{"g", PointKind::Fixed, {3.5, 0.5}}, 0},
                        {{"top", PointKind::Measurement, {2, 1.6}}, 1}};
  in.geometry.provenance.seed = 11;
  in.materials = {rock(2000, 1e9)};
  in.control.dt = 2e-3;
  in.control.total_time = 0.3;
  add_points_from_block_model(in.geometry, {}, in);
  return in;
}

// An empty results file for the model of `in`: frames every 10 steps,
// made-up provenance.
inline Results fresh_results(const ModelInput& in) {
  Results r;
  r.blocks = in.geometry;
  r.source.provenance.scenario_path = "test";
  r.output.every = 10;
  return r;
}

}  // namespace dda::df::test
