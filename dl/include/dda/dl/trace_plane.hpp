#pragma once
// Trace plane: a planar section of a 3D fracture model, as a 2D line model
// that the 2D cutter takes as it is (the hybrid 3D network -> 2D DDA workflow).
//
// The section's own coordinates (u, v), origin at the given point:
//  * n, the plane's unit normal with n . z >= 0 (normal_from_dip's, or a
//    given normal reversed if it points down; a horizontal normal is kept as
//    given, so it picks the side a vertical section is seen from);
//  * u = (z x n) / |z x n|, the strike direction, horizontal, with the plane
//    dipping to its right (right-hand rule: strike = dip direction - 90 deg);
//    a horizontal plane takes u = x (east);
//  * v = n x u, up the dip line (v . z = sin dip >= 0), so (u, v, n) is
//    right-handed; a horizontal plane takes v = y (north), and a vertical
//    section has v = z - point.z.
// Looking at the section from the side n points to, u is to the right and v
// up, and counter-clockwise in (u, v) is counter-clockwise about n. A
// vertical section striking east (dip direction 180, seen from the south)
// has u = x, v = z.
#include "dda/common/fracture_model.hpp"
#include "dda/common/line_model.hpp"

namespace dda::dl {

struct TraceFrame {
  Vec3 origin{0, 0, 0};
  Vec3 u{1, 0, 0}, v{0, 1, 0}, n{0, 0, 1};
  Vec2 to_plane(const Vec3& p) const { return {u.dot(p - origin), v.dot(p - origin)}; }
  Vec3 to_space(const Vec2& q) const { return origin + q.x() * u + q.y() * v; }
};

// The frame of the plane through `point` with the given dip and dip
// direction (degrees), or with normal `normal` (either sign, any length > 0).
// InputError for a bad dip, a zero normal or a non-finite point.
TraceFrame trace_frame(const Vec3& point, double dip_deg, double dip_direction_deg);
TraceFrame trace_frame(const Vec3& point, const Vec3& normal);

// The section of the model by the frame's plane:
//  * domain: the polygon where the plane cuts the domain box, counter-
//    clockwise in (u, v); InputError if the plane misses the box;
//  * excavations: where the plane cuts each excavation (within the domain),
//    the ones it misses left out;
//  * lines: one per fracture crossing the plane inside the domain (a Plane's
//    chord across the domain, a disc's or polygon's chord clipped to it),
//    with its set, kind (beds stay Bedding) and layer; fractures parallel to
//    the plane (within 1e-9 rad) leave none;
//  * sets copied; provenance copied;
//  * layers: the beds as coordinates along their 2D normal, with
//    bedding_dip_deg their apparent dip in the section (counter-clockwise from
//    u, in [-90, 90]); layers and the lines' layer indices are renumbered
//    bottom to top if the section turns the beds over; no layers if the plane
//    is parallel to the beds;
//  * points: left empty (3D points rarely lie on the plane).
LineModel trace_section(const FractureModel& model, const TraceFrame& frame);

}  // namespace dda::dl
