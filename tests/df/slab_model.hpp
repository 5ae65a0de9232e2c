#pragma once
// The flexible slab of the friction-instability tests (docs/friction.md,
// "A flexible slab"; examples/friction_instabilities/make_slab.py builds the
// same model for the example): a slab of `blocks` blocks bonded into one
// body, pressed onto a fixed base by a surcharge and dragged at its right
// end through a spring (a bolt) by a driver block that a moving fixed point
// carries at vd. The slab-base interface (joint set 0) has the joint's
// friction law; the cuts between the slab's blocks (set 1) are bonded far
// above the run's stresses, so the slab stays one body unless a bond breaks.
#include <string>

#include "dda/df/2d/model.hpp"
#include "df_test_models.hpp"

namespace dda::df::test {

struct Slab {
  double length = 1.0, height = 0.1;  // m
  int blocks = 20;
  double young = 1e9, poisson = 0.25, density = 2000;
  double sigma = 1e5;                 // Pa, the surcharge: sigma L / blocks on each block's centroid
  double spring = 0;                  // N/m
  double pull = 0;                    // N, the spring's force at t = 0 (bolt pretension)
  double vd = 0.01;                   // m/s, the driver's speed
  double t_end = 1;                   // s, the driver's table runs one second past it
  double dt = 1e-5;
  JointProperties interface;          // set 0
};

inline double slab_block_width(const Slab& s) { return s.length / s.blocks; }

// Blocks: 0 the base [-0.5, L + 0.5] x [-0.2, 0], 1..n the slab's blocks
// from left to right, n + 1 the driver [L + 0.8, L + 0.9] x [0, 0.1].
// Measurements: for slab block i (0-based), points 2i and 2i + 1 just inside
// its bottom-left and bottom-right corners (the interface's slip and
// opening there).
inline ModelInput slab_model(const Slab& s) {
  ModelInput in;
  const double w = slab_block_width(s), L = s.length;
  in.geometry.blocks.push_back(make_block(rectangle(-0.5, -0.2, L + 1.0, 0.2), 0));
  for (int i = 0; i < s.blocks; ++i) {
    Block b = make_block(rectangle(i * w, 0, w, s.height), 0);
    // Edges: 0 bottom (the interface), 1 right, 2 top, 3 left.
    b.edge_set[1] = i + 1 < s.blocks ? 1 : kBoundarySet;
    b.edge_set[2] = kBoundarySet;
    b.edge_set[3] = i > 0 ? 1 : kBoundarySet;
    in.geometry.blocks.push_back(b);
  }
  in.geometry.blocks.push_back(make_block(rectangle(L + 0.8, 0, 0.1, 0.1), kBoundarySet));
  in.geometry.sets = {{"interface", "user"}, {"cuts", "user"}};
  Material rock = test::rock(s.density, s.young);
  rock.poisson = s.poisson;
  rock.plane = PlaneMode::Strain;
  in.materials = {rock};
  JointProperties cuts;
  cuts.friction_deg = 45;
  cuts.cohesion = 1e9;
  cuts.tensile_strength = 1e9;
  in.joint_sets = {s.interface, cuts};
  in.control.dt = s.dt;
  in.control.dynamic = 1.0;
  in.control.initial_equilibrium = true;
  for (const double x : {-0.25, L / 2, L + 0.25}) in.fixed_points.push_back({"base", {x, -0.1}, 0, {}});
  const int driver = s.blocks + 1;
  in.fixed_points.push_back(
      {"driver", {L + 0.85, 0.05}, driver, {}, TimeHistory{{0, s.t_end + 1}, {Vec2(0, 0), Vec2(s.vd * (s.t_end + 1), 0)}}});
  Bolt spring;
  spring.name = "spring";
  spring.anchor = {L + 0.85, 0.05};
  spring.head = {L - w / 2, s.height / 5};
  spring.anchor_block = driver;
  spring.head_block = s.blocks;
  spring.stiffness = s.spring;
  spring.pretension = s.pull;
  in.bolts.push_back(spring);
  for (int i = 0; i < s.blocks; ++i) {
    std::string name = "p";  // (appending, not "p" + ...: GCC 12 warns falsely on that)
    name += std::to_string(i);
    in.loads.push_back({name, {(i + 0.5) * w, s.height / 2}, {0, -s.sigma * w}, i + 1});
    in.measurements.push_back({name + "l", {i * w + 0.02 * w, 0.02 * w}, i + 1});
    in.measurements.push_back({name + "r", {(i + 0.98) * w, 0.02 * w}, i + 1});
  }
  return in;
}

}  // namespace dda::df::test
