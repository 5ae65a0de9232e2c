#include "dda/analysis/orientation.hpp"

#include <charconv>
#include <cmath>

#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"

namespace dda::analysis {

Vec3 Plane::normal() const {
  const double d = deg2rad(dip_deg), b = deg2rad(dip_direction_deg);
  return Vec3(std::sin(d) * std::sin(b), std::sin(d) * std::cos(b), std::cos(d));
}

Vec3 Plane::dip_vector() const {
  const double d = deg2rad(dip_deg), b = deg2rad(dip_direction_deg);
  return Vec3(std::cos(d) * std::sin(b), std::cos(d) * std::cos(b), -std::sin(d));
}

Plane parse_plane(const std::string& text, const std::string& what) {
  const auto sep = text.find_first_of("/,");
  auto bad = [&](const std::string& why) {
    return InputError(what + ": '" + text + "' " + why);
  };
  if (sep == std::string::npos) throw bad("is not a plane; write dip/dip-direction in degrees, e.g. 20/090.");
  auto number = [&](std::string s, double& v) {
    while (!s.empty() && s.front() == ' ') s.erase(s.begin());
    while (!s.empty() && s.back() == ' ') s.pop_back();
    const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    return !s.empty() && r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(v);
  };
  Plane p;
  if (!number(text.substr(0, sep), p.dip_deg) || !number(text.substr(sep + 1), p.dip_direction_deg))
    throw bad("is not a plane; write dip/dip-direction in degrees, e.g. 20/090.");
  if (p.dip_deg < 0.0 || p.dip_deg > 90.0) throw bad("has a dip outside 0..90 degrees.");
  p.dip_direction_deg = std::fmod(std::fmod(p.dip_direction_deg, 360.0) + 360.0, 360.0);
  return p;
}

TrendPlunge trend_plunge(const Vec3& direction) {
  Vec3 d = direction.normalized();
  if (d.z() > 0.0) d = -d;
  TrendPlunge tp;
  tp.plunge_deg = rad2deg(std::asin(std::min(1.0, -d.z())));
  double tr = rad2deg(std::atan2(d.x(), d.y()));
  if (tr < 0.0) tr += 360.0;
  if (std::hypot(d.x(), d.y()) < 1e-12) tr = 0.0;
  tp.trend_deg = tr;
  return tp;
}

Vec3 horizontal(double azimuth_deg) {
  const double a = deg2rad(azimuth_deg);
  return Vec3(std::sin(a), std::cos(a), 0.0);
}

}  // namespace dda::analysis
