// Block displacement field, mass and elasticity matrices, exact rotation update.
#include "dda/df/block_kinematics.hpp"

#include <array>
#include <cmath>

namespace dda::df {

BlockGeometry block_geometry(const Polygon2& vertices) {
  const PolygonMoments pm = polygon_moments(vertices);
  return {pm.area, pm.centroid, pm.sxx, pm.syy, pm.sxy};
}

Matrix26d t_matrix(const Vec2& centroid, const Vec2& p) {
  const double X = p.x() - centroid.x(), Y = p.y() - centroid.y();
  Matrix26d t;
  t << 1, 0, -Y, X, 0, Y / 2,
       0, 1, X, 0, Y, X / 2;
  return t;
}

namespace {
// An entry of T as c0 + cX X + cY Y.
struct Linear {
  double c0 = 0, cx = 0, cy = 0;
};
}  // namespace

Matrix6d mass_matrix(const BlockGeometry& g, double density) {
  // Rows of T as linear polynomials (see t_matrix).
  const std::array<Linear, kDofs> r1{{{1, 0, 0}, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, {0, 0, 0}, {0, 0, 0.5}}};
  const std::array<Linear, kDofs> r2{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {0, 0, 1}, {0, 0.5, 0}}};
  // Integral of a product of two linear polynomials about the centroid,
  // where the first moments vanish.
  auto integral = [&g](const Linear& p, const Linear& q) {
    return p.c0 * q.c0 * g.area + p.cx * q.cx * g.sxx + p.cy * q.cy * g.syy + (p.cx * q.cy + p.cy * q.cx) * g.sxy;
  };
  Matrix6d m;
  for (int a = 0; a < kDofs; ++a)
    for (int b = 0; b < kDofs; ++b) m(a, b) = density * (integral(r1[a], r1[b]) + integral(r2[a], r2[b]));
  return m;
}

Matrix3d elastic_matrix(const Material& m) {
  const double e = m.young, nu = m.poisson;
  Matrix3d d;
  if (m.plane == PlaneMode::Stress) {
    const double c = e / (1 - nu * nu);
    d << c, c * nu, 0, c * nu, c, 0, 0, 0, c * (1 - nu) / 2;
  } else {
    const double c = e / ((1 + nu) * (1 - 2 * nu));
    d << c * (1 - nu), c * nu, 0, c * nu, c * (1 - nu), 0, 0, 0, c * (1 - 2 * nu) / 2;
  }
  return d;
}

Vec2 move_point(const Vec2& centroid, const Vector6d& d, const Vec2& p) {
  const Vec2 r = p - centroid;
  const double c = std::cos(d[2]), s = std::sin(d[2]);
  const Vec2 rotated(c * r.x() - s * r.y(), s * r.x() + c * r.y());
  const Vec2 strained(d[3] * r.x() + 0.5 * d[5] * r.y(), d[4] * r.y() + 0.5 * d[5] * r.x());
  return centroid + Vec2(d[0], d[1]) + rotated + strained;
}

Vector3d rotate_stress(const Vector3d& s, double angle) {
  const double c = std::cos(angle), n = std::sin(angle);
  const double cc = c * c, nn = n * n, cn = c * n;
  return {cc * s[0] + nn * s[1] - 2 * cn * s[2], nn * s[0] + cc * s[1] + 2 * cn * s[2],
          cn * (s[0] - s[1]) + (cc - nn) * s[2]};
}

}  // namespace dda::df
