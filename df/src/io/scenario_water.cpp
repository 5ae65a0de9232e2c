// The `water` section of the scenario (scenario_water.hpp).
#include "io/scenario_water.hpp"

#include <cmath>
#include <string>

namespace dda::df {
namespace {

// The section's surface: `level` or `surface` (exactly one).
template <int dim>
void read_surface(const YamlNode& w, WaterTable<dim>& out) {
  if (w.one_of({"level", "surface"}) == "level") {
    out.level = w.number("level");
    if (!std::isfinite(out.level)) w.fail_key("level", "must be a finite number");
    return;
  }
  const YamlNode s = w.child("surface");
  const char* shape = dim == 2 ? "[[x, h], ...] (at least two points, x increasing)"
                               : "[[x, y, h], [x, y, h], [x, y, h]] (three points of a plane)";
  if (!s.is_sequence()) s.fail(std::string("must be a list ") + shape);
  for (const YamlNode& row : s.items()) {
    const std::vector<double> v = row.as_numbers();
    if (static_cast<int>(v.size()) != dim) s.fail(std::string("must be a list ") + shape + ", but a point has " +
                                                  std::to_string(v.size()) + " numbers");
    typename WaterTable<dim>::Point p;
    for (int k = 0; k < dim; ++k) {
      if (!std::isfinite(v[k])) row.fail("must hold finite numbers");
      p[k] = v[k];
    }
    if (dim == 2 && !out.knots.empty() && !(p.x() > out.knots.back().x()))
      row.fail("must lie right of the point before it (x must increase along the surface)");
    out.knots.push_back(p);
  }
  if (dim == 2 && out.knots.size() < 2) s.fail(std::string("must be a list ") + shape);
  if (dim == 3) {
    if (out.knots.size() != 3) s.fail(std::string("must be a list ") + shape);
    // Seen from above the three points must span a triangle (else the plane is vertical).
    const auto& k = out.knots;
    const double area2 = (k[1].x() - k[0].x()) * (k[2].y() - k[0].y()) - (k[1].y() - k[0].y()) * (k[2].x() - k[0].x());
    if (std::abs(area2) <= 1e-12 * (k[1] - k[0]).squaredNorm() + 1e-300)
      s.fail("holds three points in one vertical plane (seen from above they must make a triangle)");
  }
}

}  // namespace

template <int dim>
std::optional<WaterTable<dim>> read_water(const YamlNode& root) {
  const std::optional<YamlNode> w = root.optional_child("water");
  if (!w) return std::nullopt;
  if (!w->is_map()) w->fail("must be a mapping such as {level: 12, unit_weight: 9810}");
  w->allow({"level", "surface", "unit_weight"});
  WaterTable<dim> out;
  out.unit_weight = w->number("unit_weight", out.unit_weight, Range::positive());
  read_surface(*w, out);
  return out;
}

template std::optional<WaterTable<2>> read_water<2>(const YamlNode&);
template std::optional<WaterTable<3>> read_water<3>(const YamlNode&);

}  // namespace dda::df
