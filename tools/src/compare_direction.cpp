#include "compare_direction.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

#include "dda/analysis/orientation.hpp"
#include "dda/common/error.hpp"

namespace dda::cli {
namespace {

constexpr double kDeg = M_PI / 180.0;

std::string vector_text(const Eigen::Vector3d& v, int n) {
  std::ostringstream s;
  s << "(" << v.x() << ", " << v.y();
  if (n == 3) s << ", " << v.z();
  s << ")";
  return s.str();
}

Eigen::Vector3d unit_or_throw(const Eigen::Vector3d& v, const std::string& option) {
  if (!(v.norm() > 0) || !std::isfinite(v.norm())) throw InputError(option + ": the direction must not be zero.");
  return v.normalized();
}

// "T/P" in degrees -> unit vector (x east, y north, z up; plunge positive down).
Eigen::Vector3d trend_plunge_vector(const std::string& text) {
  const auto sep = text.find('/');
  double t = NAN, p = NAN;
  auto number = [](const std::string& s, double& v) {
    const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    return !s.empty() && r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(v);
  };
  if (sep == std::string::npos || !number(text.substr(0, sep), t) || !number(text.substr(sep + 1), p))
    throw InputError("--trend-plunge: '" + text + "' is not a direction; write trend/plunge in degrees, e.g. 090/20.");
  if (p < -90 || p > 90) throw InputError("--trend-plunge: '" + text + "' has a plunge outside -90..90 degrees.");
  return Eigen::Vector3d(std::sin(t * kDeg) * std::cos(p * kDeg), std::cos(t * kDeg) * std::cos(p * kDeg),
                         -std::sin(p * kDeg));
}

}  // namespace

Eigen::Vector3d intersection_line(const std::string& first, const std::string& second) {
  const analysis::Plane a = analysis::parse_plane(first, "--intersection");
  const analysis::Plane b = analysis::parse_plane(second, "--intersection");
  Eigen::Vector3d line = a.normal().cross(b.normal());
  if (line.norm() < 1e-9)
    throw InputError("--intersection: the planes " + first + " and " + second +
                     " are parallel and have no line of intersection.");
  line.normalize();
  if (line.z() > 1e-12 || (std::abs(line.z()) <= 1e-12 && line.dot(a.dip_vector()) < 0)) line = -line;
  return line;
}

CompareDirection compare_direction(const CompareDirectionOptions& o, bool three_d) {
  const int given = !std::isnan(o.dip) + !o.direction.empty() + !o.trend_plunge.empty() + !o.intersection.empty();
  const std::string choices = three_d ? "--direction, --trend-plunge or --intersection" : "--dip or --direction";
  if (given != 1) throw InputError(choices + ": give exactly one (the direction of the compared component).");
  CompareDirection d;
  if (!three_d) {
    if (!o.trend_plunge.empty() || !o.intersection.empty())
      throw InputError(std::string(o.trend_plunge.empty() ? "--intersection" : "--trend-plunge") +
                       ": is for 3D results; a 2D results file takes --dip D or --direction dx,dy.");
    if (!std::isnan(o.dip)) {
      d.unit = Eigen::Vector3d(std::cos(o.dip * kDeg), -std::sin(o.dip * kDeg), 0);
    } else {
      if (o.direction.size() != 2) throw InputError("--direction: give two numbers dx,dy for a 2D results file.");
      d.unit = unit_or_throw(Eigen::Vector3d(o.direction[0], o.direction[1], 0), "--direction");
    }
    d.how = vector_text(d.unit, 2);
    return d;
  }
  if (!std::isnan(o.dip))
    throw InputError("--dip: is for 2D results; for a 3D results file give --direction x,y,z, --trend-plunge T/P "
                     "or --intersection D/B D/B.");
  if (!o.direction.empty()) {
    if (o.direction.size() != 3) throw InputError("--direction: give three numbers x,y,z for a 3D results file.");
    d.unit = unit_or_throw(Eigen::Vector3d(o.direction[0], o.direction[1], o.direction[2]), "--direction");
    d.how = vector_text(d.unit, 3);
  } else if (!o.trend_plunge.empty()) {
    d.unit = trend_plunge_vector(o.trend_plunge);
    d.how = "trend/plunge " + o.trend_plunge + " " + vector_text(d.unit, 3);
  } else {
    if (o.intersection.size() != 2) throw InputError("--intersection: give two planes, e.g. 45/120 45/240.");
    d.unit = intersection_line(o.intersection[0], o.intersection[1]);
    const analysis::TrendPlunge tp = analysis::trend_plunge(d.unit);
    std::ostringstream s;
    s << "the line of " << o.intersection[0] << " and " << o.intersection[1] << ", trend/plunge " << tp.trend_deg
      << "/" << tp.plunge_deg << " " << vector_text(d.unit, 3);
    d.how = s.str();
  }
  return d;
}

}  // namespace dda::cli
