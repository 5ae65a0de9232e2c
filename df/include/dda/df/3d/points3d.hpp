#pragma once
// Points of the 3D solver: fixed (and moving) points, point loads and
// measurement points, each a material point of one block, given by its
// position at the start of the run (x east, y north, z up; m).
#include <optional>
#include <string>
#include <vector>

#include "dda/common/geometry3d.hpp"
#include "dda/df/3d/block3d.hpp"

namespace dda::df3 {

// A piecewise-linear table of a vector against time, t strictly increasing;
// before the first time it holds the first value, after the last the last.
struct TimeHistory3 {
  std::vector<double> t;
  std::vector<Vec3> value;

  // InputError naming `what` unless the table is usable.
  void check(const std::string& what) const;
  Vec3 at(double time) const;
  // Exact mean over [t0, t1] (at(t0) when t1 <= t0).
  Vec3 average(double t0, double t1) const;
};

// A point of a free block held by a penalty spring at its start position
// plus `motion(t)` (a moving point), or at its start position.
struct FixedPoint3 {
  int block = -1;
  Vec3 position{0, 0, 0};
  std::optional<TimeHistory3> motion;  // prescribed displacement (m)
  double penalty = 0;              // N/m; 0: ten times Model3::normal_penalty
};

// A force on a material point, constant or following a table (N).
struct PointLoad3 {
  int block = -1;
  Vec3 position{0, 0, 0};
  TimeHistory3 force;
};

struct MeasurementPoint3 {
  std::string name;
  int block = -1;
  Vec3 position{0, 0, 0};
};

// One sample of a measurement point.
struct MeasurementSample3 {
  double time = 0;
  Vec3 position{0, 0, 0};      // where the material point is
  Vec3 displacement{0, 0, 0};  // from the start of the run
  Vec3 velocity{0, 0, 0};      // of the material point (end of the step)
  Vector6d stress = Vector6d::Zero();  // of its block, [sx sy sz tyz tzx txy], Pa
};

}  // namespace dda::df3
