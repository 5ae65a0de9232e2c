// The wedge a slope cuts out of two planes, and Hoek & Bray's water on it
// (wedge_body.hpp).
#include "dda/analysis/wedge_body.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "dda/common/error.hpp"

namespace dda::analysis {
namespace {

// The point on three planes n_k . x = d_k.
Vec3 meet(const Vec3& n0, double d0, const Vec3& n1, double d1, const Vec3& n2, double d2) {
  Eigen::Matrix3d m;
  m.row(0) = n0.transpose();
  m.row(1) = n1.transpose();
  m.row(2) = n2.transpose();
  if (std::abs(m.determinant()) < 1e-9) throw InputError("Wedge: three of the planes meet in no single point.");
  return m.partialPivLu().solve(Vec3(d0, d1, d2));
}

}  // namespace

WedgeBody wedge_body(const Plane& plane1, const Plane& plane2, const SlopeFaces& slope) {
  if (!(slope.height_m > 0.0 && std::isfinite(slope.height_m)))
    throw InputError("Wedge: the height of the wedge must be > 0 m.");
  const Vec3 n1 = plane1.normal(), n2 = plane2.normal(), nf = slope.face.normal(), nu = slope.upper.normal();
  Vec3 line = n1.cross(n2);
  if (line.norm() < 1e-9) throw InputError("Wedge: the two planes are parallel (no line of intersection).");
  line.normalize();
  if (line.z() > 0.0) line = -line;  // down the line
  if (!(line.z() < -1e-9)) throw InputError("Wedge: the line of intersection is horizontal; it rises to no crest.");
  WedgeBody b;
  b.height_m = slope.height_m;
  b.top = -slope.height_m / -line.z() * line;  // up the line from the toe, H higher
  // The line must run into the rock behind the face (P behind the face plane)
  // and the face must be steeper than the line, or it does not daylight.
  if (!(nf.dot(b.top) < 0.0))
    throw InputError("Wedge: the line of intersection does not daylight in the slope face (it plunges more steeply "
                     "than the face, or away from it).");
  const double du = nu.dot(b.top);
  b.crest1 = meet(n1, 0.0, nf, 0.0, nu, du);
  b.crest2 = meet(n2, 0.0, nf, 0.0, nu, du);
  // Each crest point lies on the upper side of the other plane, or that
  // plane overlies this one.
  if (n2.dot(b.crest1) < -1e-9 * slope.height_m || n1.dot(b.crest2) < -1e-9 * slope.height_m)
    throw InputError("Wedge: one plane overlies the other along the crest; the tetrahedral wedge of Hoek & Bray's "
                     "solution does not form.");
  const Vec3 p = b.top, q1 = b.crest1, q2 = b.crest2;
  b.volume_m3 = std::abs(p.dot(q1.cross(q2))) / 6.0;
  b.area1_m2 = p.cross(q1).norm() / 2.0;
  b.area2_m2 = p.cross(q2).norm() / 2.0;
  if (!(b.volume_m3 > 0.0)) throw InputError("Wedge: the four planes enclose no volume.");
  return b;
}

WedgeWaterForces hoek_bray_water(const WedgeBody& body, double water_unit_weight) {
  const double mean_pressure = water_unit_weight * body.height_m / 6.0;  // a third of the peak gamma_w H / 2
  return {mean_pressure * body.area1_m2, mean_pressure * body.area2_m2};
}

}  // namespace dda::analysis
