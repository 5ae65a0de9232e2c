#pragma once
// Vertical columns of square plates for the 3D wave tests
// (test_waves3d.cpp): plate k spans z in [k h, (k + 1) h] over a w x w
// square, a viscous base through which an incident wave enters, optionally
// dashpots on the top, and a measurement point at every plate's centroid.
// No gravity. Unbonded 3D contacts carry no tension and no shear without
// normal force, so two opposite point loads, on the lowest and the highest plate's
// centroids, press the column together (`precompression` p over the
// plates' area, well above the waves' stresses); the loads do no net work
// over a wave that passes.
//
// The column starts in the loads' equilibrium: the plates carry it as
// initial stress, sigma_zz = -p in the inner plates and -p / 2 in the end
// ones (a constant-strain block loaded at its centroid and at one face,
// h / 2 away, by P = p A: virtual work P h / 2 = sigma A h). Left to the
// start-up relaxation, a 20-plate column got only part of the way: a static
// solve with pseudo step dts takes out the imbalance of the column's first
// mode (omega = pi c / L = 44 rad/s) by a factor 1 + (omega dts)^2 / 2,
// 1.025 at dts = 5 ms, so its 50 solves left 30 %, which rang at 0.02 m/s,
// twenty times the pulse. What remains, the contacts' closure, is stiff
// and relaxes in a few solves.
//
// The closure p / kappa must stay far below the contact merge distance (1
// mm; docs/solver3d.md, "Contact identity"): beyond it the vertex of each
// plate on the other's face are two contacts at every corner, eight in
// all, and the joint is twice as stiff (a precompression of 1e5 Pa closed
// a joint of kappa = 2.2e7 Pa/m by 4.5 mm).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "dda/df/3d/simulation3d.hpp"
#include "df_test_models3d.hpp"
#include "tapered_sine.hpp"

namespace dda::df3::testing {

inline Material3 rock(double density, double young, double poisson = 0) {
  Material3 m;
  m.density = density;
  m.young = young;
  m.poisson = poisson;
  return m;
}

struct Column3 {
  int plates = 20;
  double width = 5, height = 2.5;       // m
  // Plates below `soft_from` are of materials[0], the others of the last
  // material (one material: all of it).
  std::vector<Material3> materials{rock(2000, 1e9)};
  int soft_from = 0;
  bool viscous_top = false;             // dashpots on the top face too (no free surface)
  double normal_penalty = 0;            // N/m per contact; 0: glued, 1000 times the stiffest plate's E A / h over its four corners
  double precompression = 1e5;          // Pa
};

// v_in(t) = amplitude sin^2(pi t / tau) for 0 <= t <= tau along z, then rest.
inline TimeHistory3 hann_pulse3(double amplitude, double tau) {
  TimeHistory3 h;
  const int n = 400;
  for (int k = 0; k <= n; ++k) {
    const double t = tau * k / n, s = std::sin(M_PI * t / tau);
    h.t.push_back(t);
    h.value.emplace_back(0, 0, amplitude * s * s);
  }
  return h;
}

// A sine of `amplitude` and angular frequency `omega` along z for `cycles`
// cycles, ramped in and out over one cycle each with a Hann taper, then rest.
inline TimeHistory3 tapered_sine3(double amplitude, double omega, int cycles) {
  TimeHistory3 h;
  dda::wave_test::tapered_sine_samples(amplitude, omega, cycles, [&](double t, double v) {
    h.t.push_back(t);
    h.value.emplace_back(0, 0, v);
  });
  return h;
}

inline Model3 wave_column3(const Column3& c, const TimeHistory3& incident) {
  Model3 m;
  m.materials = c.materials;
  double stiffest = 0;
  for (const Material3& mat : c.materials) stiffest = std::max(stiffest, mat.young);
  const int last = static_cast<int>(c.materials.size()) - 1;
  for (int k = 0; k < c.plates; ++k) {
    m.blocks.push_back(box(Vec3(0, 0, k * c.height), Vec3(c.width, c.width, (k + 1) * c.height)));
    m.block_material.push_back(k < c.soft_from ? 0 : last);
    std::string name = "p";
    name += std::to_string(k);
    m.measurements.push_back({name, k, Vec3(0.5 * c.width, 0.5 * c.width, (k + 0.5) * c.height)});
  }
  ViscousBoundary3 v;
  v.faces.push_back({0, 0, true});  // box face 0: the bottom
  if (c.viscous_top) v.faces.push_back({c.plates - 1, 1, false});
  v.incident_velocity = incident;
  m.viscous = v;
  const double area = c.width * c.width, p = c.precompression * area;
  m.loads.push_back({0, Vec3(0.5 * c.width, 0.5 * c.width, 0.5 * c.height), TimeHistory3{{0.0}, {Vec3(0, 0, p)}}});
  m.loads.push_back({c.plates - 1, Vec3(0.5 * c.width, 0.5 * c.width, (c.plates - 0.5) * c.height),
                     TimeHistory3{{0.0}, {Vec3(0, 0, -p)}}});
  for (int k = 0; k < c.plates; ++k) {
    const bool end = k == 0 || k == c.plates - 1;
    Vector6d stress = Vector6d::Zero();
    if (c.plates > 1) stress[2] = -(end ? 0.5 : 1.0) * c.precompression;
    m.initial_stress.push_back(stress);
  }
  m.gravity = Vec3::Zero();
  m.normal_penalty = c.normal_penalty > 0 ? c.normal_penalty : 1000 * stiffest * area / c.height / 4;
  m.shear_penalty = m.normal_penalty;
  m.default_joint.friction_deg = 60;
  return m;
}

}  // namespace dda::df3::testing
