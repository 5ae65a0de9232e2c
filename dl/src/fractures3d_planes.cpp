// Deterministic planes and persistent (spaced) sets of planes.
#include <algorithm>
#include <cmath>
#include <string>

#include "builder.hpp"  // detail::format_number
#include "dda/common/error.hpp"
#include "dda/dl/fractures3d.hpp"

namespace dda::dl {

using detail::format_number;

namespace {

// normal_from_dip with the error naming the plane or set it belongs to.
Vec3 checked_normal(double dip_deg, double dip_direction_deg, const std::string& where) {
  if (!(dip_deg >= 0 && dip_deg <= 90))
    throw InputError(where + " has dip " + format_number(dip_deg) + "; it must be between 0 and 90 degrees.");
  if (!std::isfinite(dip_direction_deg))
    throw InputError(where + " has dip direction " + format_number(dip_direction_deg) +
                     "; it must be a finite number of degrees.");
  return normal_from_dip(dip_deg, dip_direction_deg);
}

bool finite(const Vec3& p) { return p.allFinite(); }

// The domain spans [t_lo, t_hi] along the normal n (extremes at corners).
std::pair<double, double> span_along(const Vec3& n, const Box3& domain) {
  double t_lo = 0, t_hi = 0;
  for (int c = 0; c < 8; ++c) {
    const Vec3 corner(c & 1 ? domain.hi.x() : domain.lo.x(), c & 2 ? domain.hi.y() : domain.lo.y(),
                      c & 4 ? domain.hi.z() : domain.lo.z());
    const double t = n.dot(corner);
    t_lo = c == 0 ? t : std::min(t_lo, t);
    t_hi = c == 0 ? t : std::max(t_hi, t);
  }
  return {t_lo, t_hi};
}

}  // namespace

double spacings_to_point(const PersistentSetSpec& spec, const Box3& domain) {
  const Vec3 n = normal_from_dip(spec.dip_deg, spec.dip_direction_deg);
  const auto [t_lo, t_hi] = span_along(n, domain);
  const double t0 = n.dot(spec.point.value_or(domain.lo));
  return std::max({0.0, t_lo - t0, t0 - t_hi}) / spec.spacing;
}

Fracture3 make_plane(const PlaneSpec& spec, int set) {
  const std::string where = "A deterministic plane";
  Fracture3 f;
  f.normal = checked_normal(spec.dip_deg, spec.dip_direction_deg, where);
  if (!finite(spec.point)) throw InputError(where + " must pass through a point with finite coordinates.");
  f.centre = spec.point;
  f.set = set;
  if (spec.radius) {
    if (!(*spec.radius > 0) || !std::isfinite(*spec.radius))
      throw InputError(where + " has radius " + format_number(*spec.radius) + "; it must be a finite number > 0.");
    f.shape = FractureShape::Disc;
    f.radius = *spec.radius;
  } else {
    f.shape = FractureShape::Plane;
  }
  return f;
}

std::vector<Fracture3> generate_persistent_set(const PersistentSetSpec& spec, int set, const Box3& domain,
                                               Stream& rng) {
  const std::string where = "Persistent set '" + spec.name + "'";
  validate_box(domain, "The domain of " + where);
  const Vec3 n = checked_normal(spec.dip_deg, spec.dip_direction_deg, where);
  if (!(spec.spacing > 0) || !std::isfinite(spec.spacing))
    throw InputError(where + " has spacing " + format_number(spec.spacing) + "; it must be a finite number > 0.");
  if (!(spec.randomness >= 0 && spec.randomness < 1))
    throw InputError(where + " has spacing randomness " + format_number(spec.randomness) +
                     "; it must be at least 0 and less than 1.");
  const Vec3 point = spec.point.value_or(domain.lo);
  if (!finite(point)) throw InputError(where + " must pass through a point with finite coordinates.");

  const auto [t_lo, t_hi] = span_along(n, domain);
  const double tol = 1e-9 * (domain.hi - domain.lo).norm();
  const double t0 = n.dot(point), s = spec.spacing;

  // Refuse before drawing when the walk (or the set) would be absurdly long.
  const double shortest = s * (1 - spec.randomness);
  const double steps = spec.randomness == 0
                           ? (t_hi - t_lo) / s
                           : (std::max(0.0, t_hi - t0) + std::max(0.0, t0 - t_lo)) / shortest;
  if (steps > kMaxPersistentPlanes)
    throw InputError(where + " would need about " + format_number(steps, 3) + " planes with spacing " +
                     format_number(s) + ", more than the limit of " + format_number(kMaxPersistentPlanes) + ".");

  // Without randomness the planes are t0 + k s with k counted in a double:
  // a point more than kMaxSpacingsToPoint spacings from the domain would put
  // k where ++k no longer changes it (beyond 2^53) and the loop below would
  // never end, and long before that the positions drift from the rounding
  // of t0 + k s. (With randomness `steps` above already bounds the walk.)
  const double reach = spacings_to_point(spec, domain);
  if (reach > kMaxSpacingsToPoint)
    throw InputError(where + " passes through a point " + format_number(reach, 3) +
                     " spacings from the domain, more than the limit of " + format_number(kMaxSpacingsToPoint) +
                     "; give a point nearer the domain.");

  std::vector<double> offsets;
  if (spec.randomness == 0) {
    // Integer multiples of the spacing from the point, not a running sum, so
    // that plane k is at t0 + k s to rounding however far from the point.
    const double k_lo = std::ceil((t_lo - t0) / s), k_hi = std::floor((t_hi - t0) / s);
    for (double k = k_lo; k <= k_hi; ++k) offsets.push_back(t0 + k * s);
  } else {
    offsets.push_back(t0);
    for (double t = t0; t < t_hi;) offsets.push_back(t += rng.around(s, spec.randomness));
    for (double t = t0; t > t_lo;) offsets.push_back(t -= rng.around(s, spec.randomness));
    std::sort(offsets.begin(), offsets.end());
  }

  std::vector<Fracture3> out;
  for (const double t : offsets) {
    if (!(t > t_lo + tol && t < t_hi - tol)) continue;
    const Polygon3 section = plane_in_box(n, t, domain);
    if (section.empty()) continue;
    Fracture3 f;
    f.shape = FractureShape::Plane;
    f.normal = n;
    f.centre = polygon_centroid(section);
    f.centre -= (n.dot(f.centre) - t) * n;  // on the plane to rounding, not merely to the clipping's accuracy
    f.set = set;
    out.push_back(f);
  }
  return out;
}

std::vector<Fracture3> generate_persistent_sets(const std::vector<PersistentSetSpec>& sets, const Box3& domain,
                                                std::uint64_t seed, int first_set) {
  std::vector<Fracture3> all;
  for (std::size_t i = 0; i < sets.size(); ++i) {
    Stream rng(seed, "persistent3d.set", i);
    const auto part = generate_persistent_set(sets[i], first_set + static_cast<int>(i), domain, rng);
    all.insert(all.end(), part.begin(), part.end());
  }
  return all;
}

}  // namespace dda::dl
