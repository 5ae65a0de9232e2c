#pragma once
// Columns of blocks for the wave-propagation tests: a stack of n blocks of
// w x h from y = 0, glued to each other (their interfaces are DC's
// artificial cuts, so the contacts carry tension and shear without limit),
// no gravity, a viscous boundary on the base through which an incident wave
// enters, and a measurement point at the centroid of every block.
#include <cmath>
#include <string>

#include "dda/common/line_model.hpp"
#include "dda/df/2d/model.hpp"
#include "df_test_models.hpp"
#include "tapered_sine.hpp"

namespace dda::df::test {

struct ColumnSpec {
  int blocks = 40;                   // rows
  int columns = 1;                   // blocks side by side in each row (glued)
  bool viscous_sides = false;        // dashpots on the left and right sides too
  bool free_field_sides = false;     // free-field boundaries on the left and right sides
  bool viscous_top = false;          // and on the top (the column then has no free surface)
  bool viscous_base = true;          // false: no dashpots and no incident wave at all
  double width = 2.0, height = 2.5;  // m, of each block
  Material material = rock(2000, 1e9);
  double penalty = 0;                // N/m of the glued interfaces; 0: 1000 E
  int joint_above = -1;              // a real joint (set 0) on top of this block instead of glue
  JointProperties joint;             // its properties
};

// A half-sine-squared (Hann) pulse of peak `amplitude` and duration `tau`
// along `direction`, as a finely sampled table.
inline TimeHistory hann_pulse(double amplitude, double tau, const Vec2& direction) {
  TimeHistory h;
  const int n = 400;
  for (int k = 0; k <= n; ++k) {
    const double t = tau * k / n;
    const double s = std::sin(kPi * t / tau);
    h.t.push_back(t);
    h.value.push_back(amplitude * s * s * direction);
  }
  h.t.push_back(tau * 1.5);  // and rest
  h.value.push_back(Vec2::Zero());
  return h;
}

// The displacement of a Hann velocity pulse (its integral, trapezoidal on
// the pulse's samples): a smooth shift by amplitude * tau / 2.
inline TimeHistory hann_shift(double amplitude, double tau, const Vec2& direction) {
  const TimeHistory pulse = hann_pulse(amplitude, tau, direction);
  TimeHistory shift;
  Vec2 u(0, 0);
  for (std::size_t k = 0; k < pulse.t.size(); ++k) {
    if (k > 0) u += 0.5 * (pulse.t[k] - pulse.t[k - 1]) * (pulse.value[k] + pulse.value[k - 1]);
    shift.t.push_back(pulse.t[k]);
    shift.value.push_back(u);
  }
  return shift;
}

// A sine of `amplitude` and angular frequency `omega` for `cycles` cycles,
// ramped in and out over one cycle each with a Hann taper.
inline TimeHistory tapered_sine(double amplitude, double omega, int cycles, const Vec2& direction) {
  TimeHistory h;
  dda::wave_test::tapered_sine_samples(amplitude, omega, cycles, [&](double t, double v) {
    h.t.push_back(t);
    h.value.push_back(v * direction);
  });
  return h;
}

// Block index of row k, column j.
inline int column_block(const ColumnSpec& c, int k, int j) { return k * c.columns + j; }

// With several columns the sides are viscous too (no input), so that what
// reaches them leaves; the measurement points are those of the middle
// column (point k: row k).
inline ModelInput wave_column(const ColumnSpec& c, const TimeHistory& incident) {
  ModelInput in;
  ViscousBoundary v;
  for (int k = 0; k < c.blocks; ++k)
    for (int j = 0; j < c.columns; ++j) {
      Block b = make_block(rectangle(j * c.width, k * c.height, c.width, c.height), kBoundarySet);
      // Edges: 0 bottom, 1 right, 2 top, 3 left.
      if (k > 0) b.edge_set[0] = k - 1 == c.joint_above ? 0 : kArtificialSet;
      if (k < c.blocks - 1) b.edge_set[2] = k == c.joint_above ? 0 : kArtificialSet;
      if (j > 0) b.edge_set[3] = kArtificialSet;
      if (j < c.columns - 1) b.edge_set[1] = kArtificialSet;
      const int id = column_block(c, k, j);
      if (k == 0 && c.viscous_base) v.edges.push_back({id, 0, true});
      if (c.viscous_top && k == c.blocks - 1) v.edges.push_back({id, 2, false});
      const bool side = c.viscous_sides || c.free_field_sides;
      if (side && j == 0) v.edges.push_back({id, 3, false, c.free_field_sides});
      if (side && j == c.columns - 1) v.edges.push_back({id, 1, false, c.free_field_sides});
      in.geometry.blocks.push_back(b);
    }
  const int mid = c.columns / 2;
  for (int k = 0; k < c.blocks; ++k) {
    std::string name = "b";  // (appending, not "b" + ...: GCC 12 warns falsely on that)
    name += std::to_string(k);
    in.measurements.push_back({name, {(mid + 0.5) * c.width, (k + 0.5) * c.height}, column_block(c, k, mid)});
  }
  in.geometry.sets = {{"J", "user"}};
  in.materials = {c.material};
  in.joint_sets = {c.joint};
  in.default_joint.normal_penalty = c.penalty > 0 ? c.penalty : 1000 * c.material.young;
  in.gravity = {0, 0};
  v.incident_velocity = incident;
  v.base_y = 0;
  v.surface_y = c.blocks * c.height;
  if (!v.edges.empty()) in.viscous_boundary = v;
  return in;
}

}  // namespace dda::df::test
