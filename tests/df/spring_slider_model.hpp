#pragma once
// The spring-slider of the friction tests (docs/validation.md V6, V7 and the
// instabilities of docs/friction.md): a slider on a fixed base, pulled
// through a spring (a rock bolt) by a driver block that a moving fixed point
// carries along a prescribed displacement history (the "load point" of a
// spring-slider experiment).
#include <map>
#include <string>

#include "dda/df/2d/model.hpp"
#include "df_test_models.hpp"

namespace dda::df::test {

constexpr double kG = 9.81;

// Geometry (m): a fixed base [-1.5, 2.5] x [-0.5, 0]; the slider [0, 1] x
// [0, 0.5]; the driver [3.0, 3.2] x [0, 0.2], clear of both. The bolt runs
// horizontally at y = 0.1 from the driver's centre to (0.9, 0.1) in the
// slider: low, so its pull tips the slider little (the corners share the
// normal force as W/2 +- F 0.1 m / 1 m, both stay in compression).
// Rock: E = 10 GPa, so the blocks are rigid next to the 1e5 N/m spring
// (their own stiffness is ~E = 1e10 N/m) and the contact penalty (50 E =
// 5e11 N/m) lets the slider sink W / pn = 2e-8 m: the analytical rigid
// slider on a rigid base.
struct SpringSlider {
  double slider_density = 2000;  // kg/m^3: 0.5 m^2 x 2000 = 1000 kg per unit thickness
  double spring = 1e5;           // N/m
  double normal_load = 0;        // N, extra downward force on the slider's centre
  double dt = 1e-4;
  double dynamic = 1.0;
  JointProperties joint;
  TimeHistory driver;            // driver displacement u(t), m
  double pretension = 0;         // N, the spring's force at t = 0 (over the driver's u(0))
  double slider_speed = 0;       // m/s, the slider's initial velocity along x
  bool settle = true;            // Control::initial_equilibrium (false for a slider started in motion)
};

inline ModelInput spring_slider(const SpringSlider& s) {
  ModelInput in;
  in.geometry.blocks.push_back(make_block(rectangle(-1.5, -0.5, 4, 0.5)));
  in.geometry.blocks.push_back(make_block(rectangle(0, 0, 1, 0.5)));
  in.geometry.blocks.push_back(make_block(rectangle(3.0, 0, 0.2, 0.2)));
  in.materials = {test::rock(2000, 1e10), test::rock(s.slider_density, 1e10)};
  in.block_material = {0, 1, 0};
  in.joint_sets = {s.joint};
  in.control.dt = s.dt;
  in.control.dynamic = s.dynamic;
  // Contacts start stuck under the weight and the driver's initial pull
  // (settle), or the slider starts sliding at slider_speed.
  in.control.initial_equilibrium = s.settle;
  if (s.slider_speed != 0) {
    in.initial_velocity.assign(3, Vector6d::Zero());
    in.initial_velocity[1][0] = s.slider_speed;
  }
  for (const double x : {-1.0, 0.5, 2.0}) in.fixed_points.push_back({"base", {x, -0.25}, 0, {}});
  in.fixed_points.push_back({"driver", {3.1, 0.1}, 2, {}, s.driver});
  Bolt spring;
  spring.name = "spring";
  spring.anchor = {3.1, 0.1};
  spring.head = {0.9, 0.1};
  spring.anchor_block = 2;
  spring.head_block = 1;
  spring.stiffness = s.spring;
  spring.pretension = s.pretension;
  in.bolts.push_back(spring);
  if (s.normal_load > 0) in.loads.push_back({"press", {0.5, 0.25}, {0, -s.normal_load}, 1});
  in.measurements.push_back({"slider", {0.5, 0.25}, 1});
  return in;
}

inline JointProperties law(const std::string& name, std::map<std::string, double> numbers) {
  JointProperties j;
  j.friction_law = name;
  j.friction_parameters = std::move(numbers);
  return j;
}

}  // namespace dda::df::test
