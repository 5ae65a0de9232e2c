// Section `domain`: {box: [xmin, ymin, xmax, ymax]} or {polygon: [[x, y], ...]}.
#include "builder.hpp"
#include "dda/dl/clip.hpp"

namespace dda::dl::detail {

void read_domain(const YamlNode& root, Builder& b) {
  const auto node = root.optional_child("domain");
  if (!node) {
    // A DDA geometry file brings its own outline (made by its lines).
    if (root.has("geometry")) {
      b.report["domain"] = nullptr;
      return;
    }
    root.fail_key("domain", "is required (a box [xmin, ymin, xmax, ymax] or a polygon) unless a geometry file is given");
  }
  node->allow({"box", "polygon"});
  const std::string kind = node->one_of({"box", "polygon"});
  Polygon2 poly;
  if (kind == "box") {
    const YamlNode box = node->child("box");
    const auto v = box.as_numbers();
    if (v.size() != 4) box.fail("must be [xmin, ymin, xmax, ymax], got " + std::to_string(v.size()) + " numbers");
    if (!(v[2] > v[0] && v[3] > v[1])) box.fail("must have xmax > xmin and ymax > ymin");
    poly = {Vec2(v[0], v[1]), Vec2(v[2], v[1]), Vec2(v[2], v[3]), Vec2(v[0], v[3])};
  } else {
    poly = node->polygon("polygon");
    if (!is_simple_polygon(poly)) node->fail_key("polygon", "must be a simple polygon (its edges cross or touch)");
    make_counter_clockwise(poly);
  }
  b.model.domain = poly;
  const Box2 bb = bounding_box(poly);
  b.report["domain"] = {{"kind", kind},
                        {"area", b.domain_area()},
                        {"vertices", poly.size()},
                        {"bbox", {bb.lo.x(), bb.lo.y(), bb.hi.x(), bb.hi.y()}}};
}

}  // namespace dda::dl::detail
