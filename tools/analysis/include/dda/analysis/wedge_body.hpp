#pragma once
// The tetrahedral wedge a slope cuts out of two planes, and Hoek & Bray's
// water pressure on it (docs/analytical.md, "dda wedge"; Hoek & Bray, Rock
// Slope Engineering, the wedge's "short solution").
//
// The four planes: joint planes 1 and 2, the slope face and the upper slope
// surface (dip/dip-direction). The toe O is where the line of intersection
// of 1 and 2 daylights in the face; it is put at the origin. The line rises
// from O into the slope to P on the upper surface, `height` above O (the
// wedge's total height H); the upper surface passes through P. The other
// two corners are the crest points Q1 (plane 1, face, upper) and Q2 (plane
// 2, face, upper). Face i of the wedge is the triangle O, P, Q_i.
//
// Water (Hoek & Bray): the wedge is saturated, the water drains where the
// planes meet the free surfaces, so the pressure is zero along those
// traces and peaks at gamma_w H / 2 at the middle of the line of
// intersection (the hydrostatic pressure H / 2 below its top), varying
// linearly in between. Over each face that pyramid averages a third of its
// peak: U_i = gamma_w H A_i / 6, normal to the face.
#include "dda/analysis/orientation.hpp"

namespace dda::analysis {

struct SlopeFaces {
  Plane face, upper;
  double height_m = 0.0;  // H, > 0
};

struct WedgeBody {
  Vec3 toe = Vec3::Zero(), top = Vec3::Zero(), crest1 = Vec3::Zero(), crest2 = Vec3::Zero();  // O, P, Q1, Q2
  double volume_m3 = 0.0;
  double area1_m2 = 0.0, area2_m2 = 0.0;
  double height_m = 0.0;
};

// InputError with one sentence when the four planes make no such wedge (the
// line of intersection does not daylight in the face, or runs out of the
// upper surface first, or one plane overlies the other, which the short
// solution does not cover).
WedgeBody wedge_body(const Plane& plane1, const Plane& plane2, const SlopeFaces& slope);

// Hoek & Bray's water force on face 1 and 2 (kN for gamma_w in kN/m^3).
struct WedgeWaterForces {
  double u1 = 0.0, u2 = 0.0;
};
WedgeWaterForces hoek_bray_water(const WedgeBody& body, double water_unit_weight);

}  // namespace dda::analysis
