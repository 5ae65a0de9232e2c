#pragma once
// Plain 2D geometry on doubles: the common vocabulary of DL, DC and DF.
//
// Conventions used everywhere in the project:
//  * x is horizontal (east), y is vertical (up) in 2D sections; metres.
//  * Polygons are stored as vertex lists without a repeated closing vertex,
//    counter-clockwise (positive signed area).
//  * Angles in input files are degrees; inside the code they are radians.
#include <Eigen/Core>
#include <vector>

namespace dda {

using Vec2 = Eigen::Vector2d;
using Polygon2 = std::vector<Vec2>;

constexpr double kPi = 3.14159265358979323846;
inline double deg2rad(double deg) { return deg * kPi / 180.0; }
inline double rad2deg(double rad) { return rad * 180.0 / kPi; }

// 2D cross product (z component of a x b).
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

struct Box2 {
  Vec2 lo{0, 0};
  Vec2 hi{0, 0};
  double width() const { return hi.x() - lo.x(); }
  double height() const { return hi.y() - lo.y(); }
};

// Exact polygon integrals ("simplex integration": sum of signed triangles from
// the origin), valid for any simple polygon, convex or not.
struct PolygonMoments {
  double area = 0;        // signed: positive for counter-clockwise
  Vec2 centroid{0, 0};
  double sxx = 0;         // integral of (x-x0)^2 dA about the centroid
  double syy = 0;         // integral of (y-y0)^2 dA
  double sxy = 0;         // integral of (x-x0)(y-y0) dA
};

PolygonMoments polygon_moments(const Polygon2& poly);
double signed_area(const Polygon2& poly);
Box2 bounding_box(const Polygon2& poly);
// Even-odd rule; points exactly on the boundary may go either way.
bool point_in_polygon(const Polygon2& poly, const Vec2& p);
// Distance from p to the polygon's boundary (its nearest edge).
double distance_to_boundary(const Polygon2& poly, const Vec2& p);
// Reverses the vertex order if the polygon is clockwise.
void make_counter_clockwise(Polygon2& poly);
// Extent of the polygon along `dir` (the caliper width across the direction
// perpendicular to it).
double extent_along(const Polygon2& poly, const Vec2& dir);

// Whether two convex counter-clockwise polygons share an area: a
// separating-axis test where touching within `tol` (edge to edge, corner to
// edge) counts as apart.
bool convex_polygons_overlap(const Polygon2& a, const Polygon2& b, double tol);

// The part of `subject` inside the convex counter-clockwise polygon `clip`
// (Sutherland-Hodgman); empty if they do not overlap.
Polygon2 clip_to_convex(const Polygon2& subject, const Polygon2& clip);

// Convex hull, counter-clockwise, without collinear points.
Polygon2 convex_hull(Polygon2 points);

// Caliper (Feret) measures of a block, on its convex hull. The one
// definition of a block's elongation used by DC's sliver filter and by the
// block statistics: aspect = length / min_width, so an L x W rectangle has
// aspect L/W in any orientation and a square 1.
struct FeretMeasures {
  double min_width = 0;     // smallest caliper width (minimum Feret diameter)
  double length = 0;        // caliper width perpendicular to the minimum one
  double max_diameter = 0;  // largest distance between two vertices
  double aspect = 0;        // length / min_width (infinity for a degenerate polygon)
};
FeretMeasures feret_measures(const Polygon2& poly);
double min_feret_width(const Polygon2& poly);

}  // namespace dda
