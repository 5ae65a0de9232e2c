// Block displacement field, mass and elasticity matrices, exact rotation update.
#include "dda/df/2d/block_kinematics.hpp"

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

Matrix6d mass_matrix(const BlockGeometry& g, double density) {
  // With X, Y about the centroid (first moments zero) the rows of T are
  //   r1 = (1, 0, -Y, X, 0, Y/2),  r2 = (0, 1, X, 0, Y, X/2),
  // and M(a, b) = density * integral of r1a r1b + r2a r2b: area, Sxx, Syy
  // and Sxy terms only. Written out entry by entry (a generic product of
  // the rows' polynomials spent 700 flops a block on terms that are zero:
  // 3 % of a step on a 49k-block model); each entry is the same sum of the
  // same nonzero terms as that product, so the same to the last bit.
  const double s = g.area, sxx = g.sxx, syy = g.syy, sxy = g.sxy;
  Matrix6d m = Matrix6d::Zero();
  m(0, 0) = density * s;
  m(1, 1) = density * s;
  m(2, 2) = density * (syy + sxx);
  m(2, 3) = m(3, 2) = density * -sxy;
  m(2, 4) = m(4, 2) = density * sxy;
  m(2, 5) = m(5, 2) = density * (-0.5 * syy + 0.5 * sxx);
  m(3, 3) = density * sxx;
  m(3, 5) = m(5, 3) = density * (0.5 * sxy);
  m(4, 4) = density * syy;
  m(4, 5) = m(5, 4) = density * (0.5 * sxy);
  m(5, 5) = density * (0.25 * syy + 0.25 * sxx);
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
