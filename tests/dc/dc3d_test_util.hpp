#pragma once
// Helpers for the 3D cutter tests: fracture models built by hand (not
// through DL) and the validity checks every polyhedron must pass.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <map>
#include <string>
#include <utility>

#include "dda/common/fracture_model.hpp"
#include "dda/common/polyhedron_model.hpp"

namespace dda::dc::test3 {

inline FractureModel empty_model(const Vec3& lo, const Vec3& hi, int sets = 1) {
  FractureModel m;
  m.domain = {lo, hi};
  for (int i = 0; i < sets; ++i) m.sets.push_back({"set" + std::to_string(i), "user"});
  return m;
}

inline Fracture3 plane(const Vec3& normal, const Vec3& point, int set = 0) {
  Fracture3 f;
  f.shape = FractureShape::Plane;
  f.normal = normal.normalized();
  f.centre = point;
  f.set = set;
  return f;
}

inline Fracture3 disc(const Vec3& normal, const Vec3& centre, double radius, int set = 0) {
  Fracture3 f = plane(normal, centre, set);
  f.shape = FractureShape::Disc;
  f.radius = radius;
  return f;
}

// Every check a convex block must pass: a closed, consistently oriented
// surface (each directed edge once, its reverse once), Euler V - E + F = 2,
// planar faces whose stored normal is the outward Newell normal, every
// vertex on the inner side of every face, and positive volume.
inline void expect_valid(const Polyhedron& p, double tol = 1e-9) {
  const double size = [&] {
    double s = 0;
    for (const auto& v : p.vertices) s = std::max(s, (v - p.vertices.front()).norm());
    return s;
  }();
  ASSERT_GT(size, 0);
  std::map<std::pair<int, int>, int> edges;
  for (const auto& f : p.faces) {
    ASSERT_GE(f.vertices.size(), 3u);
    Vec3 newell = Vec3::Zero();
    for (std::size_t i = 0; i < f.vertices.size(); ++i) {
      const int a = f.vertices[i], b = f.vertices[(i + 1) % f.vertices.size()];
      ++edges[{a, b}];
      const Vec3& pa = p.vertices[static_cast<std::size_t>(a)];
      const Vec3& pb = p.vertices[static_cast<std::size_t>(b)];
      newell += pa.cross(pb);
    }
    ASSERT_GT(newell.norm(), 0);
    EXPECT_NEAR(newell.normalized().dot(f.normal), 1.0, 1e-9) << "face normal is not the outward normal";
    const Vec3& q = p.vertices[static_cast<std::size_t>(f.vertices[0])];
    for (const auto& v : p.vertices) EXPECT_LE(f.normal.dot(v - q), tol * size) << "block is not convex";
    for (int i : f.vertices) EXPECT_NEAR(f.normal.dot(p.vertices[static_cast<std::size_t>(i)] - q), 0, tol * size);
  }
  for (const auto& [e, count] : edges) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(edges.count({e.second, e.first}), 1u) << "edge without its twin: surface not closed";
  }
  const long long V = static_cast<long long>(p.vertices.size());
  const long long E = static_cast<long long>(edges.size()) / 2;
  const long long F = static_cast<long long>(p.faces.size());
  EXPECT_EQ(V - E + F, 2);
  EXPECT_GT(p.volume, 0);
}

inline double total_volume(const PolyhedronModel& m) {
  double v = 0;
  for (const auto& b : m.blocks) v += b.volume;
  return v;
}

}  // namespace dda::dc::test3
