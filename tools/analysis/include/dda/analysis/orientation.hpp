#pragma once
// Planes and directions in 3D. Axes: x east, y north, z up (right-handed).
// Planes are given as dip / dip direction in degrees (dip 0..90, dip
// direction clockwise from north, 0..360); lines as trend / plunge in degrees
// (plunge positive downwards).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>

namespace dda::analysis {

using Vec3 = Eigen::Vector3d;

struct Plane {
  double dip_deg = 0.0;
  double dip_direction_deg = 0.0;
  // Upward unit normal: (sin d sin b, sin d cos b, cos d).
  Vec3 normal() const;
  // Unit vector down the dip (horizontal part towards the dip direction).
  Vec3 dip_vector() const;
};

// "20/090" or "20,90" -> Plane; InputError naming `what` if malformed or out
// of range (dip 0..90, dip direction any finite value, taken modulo 360).
Plane parse_plane(const std::string& text, const std::string& what);

// Trend (deg, 0..360 clockwise from north) and plunge (deg, positive down) of
// a direction; the vector is flipped to point downward first if it points up.
struct TrendPlunge {
  double trend_deg = 0.0;
  double plunge_deg = 0.0;
};
TrendPlunge trend_plunge(const Vec3& direction);
// Horizontal unit vector towards the azimuth (deg clockwise from north).
Vec3 horizontal(double azimuth_deg);

}  // namespace dda::analysis
