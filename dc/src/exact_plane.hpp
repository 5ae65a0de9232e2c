#pragma once
// Exact side-of-plane tests for points given as the meeting point of three
// planes ("plane-based" geometry).
//
// The 3D cutter never stores a constructed point as the truth: every vertex
// of a block is the intersection of three input planes, and every plane is
// a x + b y + c z + d = 0 with double coefficients taken as exact. Whether a
// vertex lies below, on or above another plane is then the sign of a 4x4
// determinant of input doubles, which a filtered evaluation decides exactly
// (exact_plane_cgal.cpp). No chain of cuts ever loses precision, so
// topology (which vertices a cut keeps, which faces touch) is always
// consistent, whatever the degeneracy: planes through vertices, coplanar
// fractures, three sets meeting in one point.
#include <array>

#include "dda/common/geometry3d.hpp"

namespace dda::dc::exact {

struct Plane {
  Vec3 n{0, 0, 1};
  double d = 0;  // n . x + d = 0
  double value_at(const Vec3& x) const { return n.dot(x) + d; }
};

// Sign (-1, 0, +1) of det(n_p, n_q, n_r): zero iff the three planes do not
// meet in a single point.
int orientation(const Plane& p, const Plane& q, const Plane& r);

// Sign of h.value_at(x) at the exact point x where p, q and r meet, whose
// orientation (above) is `orient` (non-zero).
int side(const Plane& p, const Plane& q, const Plane& r, int orient, const Plane& h);

// The meeting point of three planes in doubles (for output and bounds only;
// never for a decision). Requires orientation != 0.
Vec3 meeting_point(const Plane& p, const Plane& q, const Plane& r);

}  // namespace dda::dc::exact
