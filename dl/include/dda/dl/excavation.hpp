#pragma once
// Excavation outlines as counter-clockwise polygons.
//
//  rectangle: centred on `center`, sides parallel to the axes.
//  circle:    regular n-gon inscribed in the circle (vertex k at angle 2*pi*k/n);
//             area n/2 R^2 sin(2 pi / n).
//  horseshoe: the part of the circle (center, radius R) above a horizontal
//             chord (the flat invert) at `invert_depth` d below the centre,
//             0 <= d < R. The crown arc is split into
//             ceil(segments * arc_angle / (2 pi)) >= 2 equal pieces, where
//             arc_angle = pi + 2 asin(d / R); segments refers to the full circle.
//  arch:      flat floor of `width` centred on `center` (the floor midpoint),
//             vertical walls of `wall_height` >= 0, and a circular roof through
//             both wall tops with the crown `rise` above them
//             (0 < rise <= width/2; rise = width/2 is a semicircle). The roof
//             arc is split into `segments` equal pieces.
#include "dda/common/geometry.hpp"

namespace dda::dl {

Polygon2 rectangle_outline(const Vec2& center, double width, double height);
Polygon2 circle_outline(const Vec2& center, double radius, int segments);
Polygon2 horseshoe_outline(const Vec2& center, double radius, double invert_depth, int segments);
Polygon2 arch_outline(const Vec2& floor_center, double width, double wall_height, double rise, int segments);

// Number of crown pieces horseshoe_outline uses (exposed for tests).
int horseshoe_arc_pieces(double radius, double invert_depth, int segments);

}  // namespace dda::dl
