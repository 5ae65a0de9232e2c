// Dip/dip direction <-> normal, and Fisher sampling of normals.
#include <algorithm>
#include <cmath>

#include "builder.hpp"  // detail::format_number
#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"
#include "dda/dl/dfn3d.hpp"

namespace dda::dl {

using detail::format_number;

Eigen::Vector3d normal_from_dip(double dip_deg, double dip_direction_deg) {
  if (!(dip_deg >= 0 && dip_deg <= 90))
    throw InputError("A dip must be between 0 and 90 degrees, got " + format_number(dip_deg) + ".");
  if (!std::isfinite(dip_direction_deg))
    throw InputError("A dip direction must be a finite number of degrees, got " + format_number(dip_direction_deg) +
                     ".");
  const double d = deg2rad(dip_deg), a = deg2rad(dip_direction_deg);
  return {std::sin(d) * std::sin(a), std::sin(d) * std::cos(a), std::cos(d)};
}

Eigen::Vector3d upper_hemisphere(const Eigen::Vector3d& n) {
  // Ties broken lexicographically on (z, y, x) so that a vertical plane also
  // has a single stored normal.
  const bool flip = n.z() < 0 || (n.z() == 0 && (n.y() < 0 || (n.y() == 0 && n.x() < 0)));
  return flip ? Eigen::Vector3d(-n) : n;
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> plane_basis(const Eigen::Vector3d& n) {
  // From the axis least aligned with n, so the cross product is well conditioned.
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();
  Eigen::Index k = 0;
  n.cwiseAbs().minCoeff(&k);
  axis[k] = 1;
  const Eigen::Vector3d e1 = axis.cross(n).normalized();
  return {e1, n.cross(e1)};
}

DipDirection dip_from_normal(const Eigen::Vector3d& n) {
  const double len = n.norm();
  if (!(len > 0) || !std::isfinite(len))
    throw InputError("A plane's normal must be a finite non-zero vector.");
  const Eigen::Vector3d u = upper_hemisphere(n / len);
  DipDirection out;
  // atan2 of the horizontal length and z rather than acos(z): accurate for
  // near-horizontal planes too.
  const double h = std::hypot(u.x(), u.y());
  out.dip_deg = rad2deg(std::atan2(h, u.z()));
  if (h > 0) {
    double a = rad2deg(std::atan2(u.x(), u.y()));  // azimuth clockwise from north
    if (a < 0) a += 360;
    out.dip_direction_deg = a >= 360 ? 0 : a;
  }
  return out;
}

Eigen::Vector3d sample_fisher(const Eigen::Vector3d& mean, double kappa, Stream& rng) {
  if (!(kappa >= 0))
    throw InputError("A Fisher concentration kappa must be >= 0 (or infinity), got " + format_number(kappa) + ".");
  const double len = mean.norm();
  if (!(len > 0) || !std::isfinite(len)) throw InputError("A Fisher mean direction must be a finite non-zero vector.");
  const Eigen::Vector3d m = mean / len;
  // Two draws even for kappa = infinity, so that a set's stream advances the
  // same way whatever its spread.
  const double u = rng.uniform01(), phi = 2 * kPi * rng.uniform01();
  if (std::isinf(kappa)) return m;
  // expm1/log1p keep the formula accurate for small kappa; below 1e-12 its
  // limit 1 - 2U (uniform on the sphere) is used directly.
  const double c = kappa < 1e-12 ? 1 - 2 * u : 1 + std::log1p(u * std::expm1(-2 * kappa)) / kappa;
  const double cos_t = std::clamp(c, -1.0, 1.0), sin_t = std::sqrt(1 - cos_t * cos_t);
  const auto [e1, e2] = plane_basis(m);
  return (cos_t * m + sin_t * (std::cos(phi) * e1 + std::sin(phi) * e2)).normalized();
}

}  // namespace dda::dl
