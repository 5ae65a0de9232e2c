#pragma once
// Small 3D models shared by the DF 3D tests.
#include <cmath>
#include <numbers>
#include <vector>

#include "dda/common/polyhedron_model.hpp"
#include "dda/df/3d/simulation3d.hpp"

namespace dda::df3::testing {

// Axis-aligned box [lo, hi] turned by r about the origin; face loops
// counter-clockwise seen from outside (normals are recomputed by Simulation3).
inline Polyhedron box(const Vec3& lo, const Vec3& hi, const Eigen::Matrix3d& r = Eigen::Matrix3d::Identity()) {
  Polyhedron p;
  for (int i = 0; i < 8; ++i)
    p.vertices.push_back(r * Vec3(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z()));
  for (const auto& loop : std::vector<std::vector<int>>{
           {0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}) {
    PolyFace f;
    f.vertices = loop;
    p.faces.push_back(f);
  }
  return p;
}

// The rotation that turns the horizontal plane z = 0 into a plane of the
// given dip and dip direction (degrees; x east, y north, dip direction
// clockwise from north): +dip about y (dipping towards +x), then about z by
// 90 - dip direction. Its columns are the down-dip direction, the strike
// and the upward normal.
inline Eigen::Matrix3d plane_rotation(double dip_deg, double dip_direction_deg) {
  const double a = dip_deg * std::numbers::pi / 180, b = (90 - dip_direction_deg) * std::numbers::pi / 180;
  Eigen::Matrix3d ry, rz;
  ry << std::cos(a), 0, std::sin(a), 0, 1, 0, -std::sin(a), 0, std::cos(a);
  rz << std::cos(b), -std::sin(b), 0, std::sin(b), std::cos(b), 0, 0, 0, 1;
  return rz * ry;
}

// Three layers of 1 m cubes in running bond (every other layer shifted by
// half a cube) on a plane dipping 15 deg, the bottom layer fixed, friction
// 10 deg: the upper layers slide, so contacts open, lock and slide.
inline Model3 sliding_stack() {
  const Eigen::Matrix3d r = plane_rotation(15, 90);
  Model3 m;
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 4; ++x) {
        const Vec3 lo(x + 0.5 * (z % 2), y, z);
        m.blocks.push_back(box(lo, lo + Vec3(1, 1, 1), r));
        m.fixed.push_back(z == 0);
      }
  m.default_joint.friction_deg = 10;
  return m;
}

}  // namespace dda::df3::testing
