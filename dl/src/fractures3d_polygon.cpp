// A polygon fracture from vertices read from a file: checked, fitted, oriented.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

#include "builder.hpp"  // detail::format_number
#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"
#include "dda/dl/fractures3d.hpp"

namespace dda::dl {

using detail::format_number;

Fracture3 polygon_fracture(std::vector<Vec3> v, int set, const std::string& where, double planarity) {
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!v[i].allFinite())
      throw InputError(where + " has a non-finite coordinate at vertex " + std::to_string(i + 1) + ".");
  // Files often close a polygon by repeating its first vertex.
  if (v.size() > 3 && v.back() == v.front()) v.pop_back();
  if (v.size() < 3)
    throw InputError(where + " has " + std::to_string(v.size()) + " vertices; a polygon needs at least 3.");

  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : v) mean += p;
  mean /= static_cast<double>(v.size());
  double size = 0;
  for (const Vec3& p : v) size = std::max(size, (p - mean).norm());
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i)
    if ((v[(i + 1) % n] - v[i]).norm() <= 1e-12 * size)
      throw InputError(where + " has vertices " + std::to_string(i + 1) + " and " + std::to_string((i + 1) % n + 1) +
                       " at the same point.");

  // Newell's normal is the polygon's vector area: exact for a planar polygon
  // and the area-weighted mean plane of a slightly warped one.
  const Vec3 area = vector_area(v);
  if (!(area.norm() > 1e-12 * size * size))
    throw InputError(where + " has no area (its vertices are collinear).");
  const Vec3 normal = area.normalized();
  std::size_t worst = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (std::abs(normal.dot(v[i] - mean)) > std::abs(normal.dot(v[worst] - mean))) worst = i;
  const double off = std::abs(normal.dot(v[worst] - mean));
  if (off > planarity * size)
    throw InputError(where + " is not planar: vertex " + std::to_string(worst + 1) + " is " + format_number(off, 3) +
                     " m off the fitted plane, more than " + format_number(planarity) + " of its size " +
                     format_number(size, 4) + " m.");
  for (Vec3& p : v) p -= normal.dot(p - mean) * normal;

  // Convex: counter-clockwise about `normal` (by construction), no vertex
  // turning clockwise beyond the tolerance, and one turn in all (a star
  // polygon turns the same way at every vertex but winds twice).
  const auto [e1, e2] = plane_basis(normal);
  double total_turn = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 a = v[i] - v[(i + n - 1) % n], b = v[(i + 1) % n] - v[i];
    const Vec2 a2(a.dot(e1), a.dot(e2)), b2(b.dot(e1), b.dot(e2));
    const double s = cross(a2, b2) / (a2.norm() * b2.norm());
    if (s < -planarity)
      throw InputError(where + " is not convex: it turns inwards at vertex " + std::to_string(i + 1) + ".");
    total_turn += std::atan2(cross(a2, b2), a2.dot(b2));
  }
  if (std::abs(total_turn - 2 * kPi) > 1e-6)
    throw InputError(where + " is not convex: its edges wind round " + format_number(total_turn / (2 * kPi), 3) +
                     " times instead of once.");

  Fracture3 f;
  f.shape = FractureShape::Polygon;
  f.normal = normal;
  if (upper_hemisphere(normal) != normal) {
    f.normal = -normal;
    std::reverse(v.begin(), v.end());  // counter-clockwise about the stored normal
  }
  f.centre = polygon_centroid(v);
  f.vertices = std::move(v);
  f.set = set;
  return f;
}

}  // namespace dda::dl
