#pragma once
// Clipping segments to a simple polygon (convex or not).
#include <vector>

#include "dda/common/geometry.hpp"

namespace dda::dl {

struct Segment {
  Vec2 a{0, 0};
  Vec2 b{0, 0};
  double length() const { return (b - a).norm(); }
};

// The parts of segment ab inside `poly` (a simple polygon, any orientation),
// in order from a to b. Parts shorter than `min_length` are dropped. A segment
// running along the boundary counts as inside.
std::vector<Segment> clip_segment(const Polygon2& poly, const Segment& s, double min_length = 1e-12);

// True if the polygon has no two non-adjacent edges that touch or cross.
bool is_simple_polygon(const Polygon2& poly);

// True if `inner` lies inside `outer` (every vertex inside or on the boundary
// and no edge of `inner` crosses an edge of `outer`).
bool polygon_inside(const Polygon2& outer, const Polygon2& inner);

}  // namespace dda::dl
