// Section `excavations`: a list of openings, each a shape.
#include <cmath>

#include "builder.hpp"
#include "dda/dl/clip.hpp"
#include "dda/dl/excavation.hpp"

namespace dda::dl::detail {

namespace {

int segments_of(const YamlNode& n, long long fallback) {
  return static_cast<int>(n.integer("segments", fallback, Range::closed(3, 100000)));
}

Polygon2 read_shape(const YamlNode& n, const std::string& shape, const Builder& b) {
  if (shape == "rectangle") {
    n.allow({"shape", "center", "width", "height"});
    return rectangle_outline(b.local(n.point("center")), n.number("width", Range::positive()),
                             n.number("height", Range::positive()));
  }
  if (shape == "circle") {
    n.allow({"shape", "center", "radius", "segments"});
    return circle_outline(b.local(n.point("center")), n.number("radius", Range::positive()), segments_of(n, 48));
  }
  if (shape == "horseshoe") {
    n.allow({"shape", "center", "radius", "invert_depth", "segments"});
    const double r = n.number("radius", Range::positive());
    const double d = n.number("invert_depth", 0.5 * r, Range::non_negative());
    if (d >= r) n.fail_key("invert_depth", "must be smaller than the radius " + format_number(r) + ", got " + format_number(d));
    return horseshoe_outline(b.local(n.point("center")), r, d, segments_of(n, 48));
  }
  if (shape == "arch") {
    n.allow({"shape", "center", "width", "wall_height", "rise", "segments"});
    const double w = n.number("width", Range::positive());
    const double wall = n.number("wall_height", Range::non_negative());
    const double rise = n.number("rise", 0.5 * w, Range::positive());
    if (rise > 0.5 * w + 1e-12 * w)
      n.fail_key("rise", "must be at most half the width (" + format_number(0.5 * w) + ", a semicircle), got " +
                             format_number(rise));
    return arch_outline(b.local(n.point("center")), w, wall, std::min(rise, 0.5 * w), segments_of(n, 24));
  }
  // polygon
  n.allow({"shape", "vertices"});
  Polygon2 poly = n.polygon("vertices");
  for (Vec2& v : poly) v = b.local(v);
  if (!is_simple_polygon(poly)) n.fail_key("vertices", "must be a simple polygon (its edges cross or touch)");
  make_counter_clockwise(poly);
  return poly;
}

}  // namespace

void read_excavations(const YamlNode& root, Builder& b) {
  nlohmann::json rep = nlohmann::json::array();
  for (const YamlNode& n : root.list_or_empty("excavations")) {
    if (!n.is_map()) n.fail("must be a mapping with a shape (rectangle, circle, horseshoe, arch or polygon)");
    const std::string shape = n.choice("shape", {"rectangle", "circle", "horseshoe", "arch", "polygon"});
    Polygon2 poly = read_shape(n, shape, b);
    if (!b.model.domain.empty() && !polygon_inside(b.model.domain, poly))
      n.fail("lies partly or wholly outside the domain; an excavation must be inside it");
    for (std::size_t i = 0; i < b.model.excavations.size(); ++i)
      for (const Vec2& p : poly)
        if (point_in_polygon(b.model.excavations[i], p))
          n.fail("overlaps excavations[" + std::to_string(i) + "]; merge them into one polygon");
    rep.push_back({{"shape", shape}, {"area", std::abs(signed_area(poly))}, {"vertices", poly.size()}});
    b.model.excavations.push_back(std::move(poly));
  }
  b.report["excavations"] = rep;
}

}  // namespace dda::dl::detail
