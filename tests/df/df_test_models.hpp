#pragma once
// Small hand-built models shared by the DF tests.
#include <cmath>

#include "dda/common/block_model.hpp"
#include "dda/common/geometry.hpp"
#include "dda/df/model.hpp"

namespace dda::df::test {

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

// A block with its integrals filled in; every edge carries joint set `set`.
inline Block make_block(const Polygon2& vertices, int set = 0) {
  Block b;
  b.vertices = vertices;
  b.edge_set.assign(vertices.size(), set);
  const PolygonMoments m = polygon_moments(vertices);
  b.area = m.area;
  b.centroid = m.centroid;
  b.sxx = m.sxx;
  b.syy = m.syy;
  b.sxy = m.sxy;
  return b;
}

inline Material rock(double density = 2000, double young = 1e9) {
  Material m;
  m.density = density;
  m.young = young;
  m.poisson = 0.25;
  m.plane = PlaneMode::Stress;
  return m;
}

}  // namespace dda::df::test
