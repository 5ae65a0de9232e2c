// Disc and polygon fracture sets as Fracture3.
#include <cmath>
#include <iterator>

#include "dda/common/geometry.hpp"
#include "dda/dl/fractures3d.hpp"

namespace dda::dl {

Fracture3 to_fracture(const Disc& disc) {
  Fracture3 f;
  f.shape = FractureShape::Disc;
  f.normal = disc.normal;
  f.centre = disc.centre;
  f.radius = disc.radius;
  f.set = disc.set;
  return f;
}

Fracture3 regular_polygon(const Disc& disc, int sides, double rotation_rad) {
  Fracture3 f;
  f.shape = FractureShape::Polygon;
  f.normal = disc.normal;
  f.centre = disc.centre;  // the centroid of a regular polygon is its centre
  f.set = disc.set;
  const double n = sides, step = 2 * kPi / n;
  // Area of a regular n-gon of circumradius R: (n / 2) R^2 sin(2 pi / n);
  // equal to pi r^2 so that a P32 target counts the same area as for discs.
  const double circumradius = disc.radius * std::sqrt(2 * kPi / (n * std::sin(step)));
  const auto [e1, e2] = plane_basis(disc.normal);  // (e1, e2, normal) right-handed: counter-clockwise
  f.vertices.reserve(static_cast<std::size_t>(sides));
  for (int k = 0; k < sides; ++k) {
    const double a = rotation_rad + step * k;
    f.vertices.push_back(disc.centre + circumradius * (std::cos(a) * e1 + std::sin(a) * e2));
  }
  return f;
}

std::vector<Fracture3> generate_fracture_set(const DiscSetSpec& spec, int set, const Box3& domain, double margin,
                                             Stream& rng) {
  std::vector<double> turns;
  const std::vector<Disc> discs = generate_disc_set(spec, set, domain, margin, rng, &turns);
  std::vector<Fracture3> out;
  out.reserve(discs.size());
  for (std::size_t i = 0; i < discs.size(); ++i)
    out.push_back(spec.polygon_sides ? regular_polygon(discs[i], spec.polygon_sides, turns[i]) : to_fracture(discs[i]));
  return out;
}

std::vector<Fracture3> generate_fractures(const std::vector<DiscSetSpec>& sets, const Box3& domain, double margin,
                                          std::uint64_t seed, int first_set) {
  std::vector<Fracture3> all;
  for (std::size_t i = 0; i < sets.size(); ++i) {
    Stream rng(seed, "dfn3d.set", i);
    auto part = generate_fracture_set(sets[i], first_set + static_cast<int>(i), domain, margin, rng);
    all.insert(all.end(), std::make_move_iterator(part.begin()), std::make_move_iterator(part.end()));
  }
  return all;
}

}  // namespace dda::dl
