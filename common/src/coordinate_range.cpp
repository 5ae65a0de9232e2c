#include "dda/common/coordinate_range.hpp"

#include <algorithm>
#include <cmath>

#include "dda/common/error.hpp"
#include "dda/common/short_number.hpp"

namespace dda {
namespace {

template <int Dims, class Point>
void check(const std::vector<Point>& points, const std::string& source) {
  double farthest = 0;
  for (const Point& p : points)
    for (int k = 0; k < Dims; ++k) {
      if (!std::isfinite(p[k])) throw InputError(source + ": has a coordinate that is not a finite number.");
      farthest = std::max(farthest, std::abs(p[k]));
    }
  if (farthest > kFarthestCoordinate)
    throw InputError(source + ": has coordinates up to " + short_number(farthest) + " m, beyond the " +
                     short_number(kFarthestCoordinate) +
                     " m any model may reach (coordinates are metres; doubles there are more than 0.1 m apart).");
}

// One axis of the origin (the rule in coordinate_range.hpp): the centre of
// [lo, hi] rounded to a multiple of the largest power of two not above the
// extent, when the axis lies on one side of 0 within a factor 2; else 0.
double origin_on_axis(double lo, double hi, double size) {
  const bool one_side = (lo > 0 && hi <= 2 * lo) || (hi < 0 && lo >= 2 * hi);
  if (!one_side) return 0;
  const double extent = hi - lo > 0 ? hi - lo : size;
  if (!(extent > 0)) return lo;  // a single point: itself, exactly
  const double quantum = std::ldexp(1.0, std::ilogb(extent));  // <= extent
  // Rounding to the quantum moves the centre by at most half of it, so the
  // origin stays inside [lo, hi] (a multiple of the quantum lies there).
  const double o = std::round((0.5 * lo + 0.5 * hi) / quantum) * quantum;
  return std::clamp(o, lo, hi);
}

template <int Dims, class Point>
Point choose(const std::vector<Point>& points) {
  Point origin = Point::Zero();
  if (points.empty()) return origin;
  Point lo = points.front(), hi = points.front();
  for (const Point& p : points) {
    if (!p.allFinite()) return origin;
    lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  }
  const double size = (hi - lo).norm();
  const double farthest = std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
  if (farthest <= kLocalBeyondSizes * size && farthest <= kLocalBeyondMetres) return origin;
  for (int k = 0; k < Dims; ++k) origin[k] = origin_on_axis(lo[k], hi[k], size);
  return origin;
}

// A level along a bed normal moves by normal . origin.
void shift_layers(std::vector<Layer>& layers, double by) {
  for (Layer& l : layers) l.bottom -= by, l.top -= by;
}

}  // namespace

void check_coordinate_range(const std::vector<Vec2>& points, const std::string& source) { check<2>(points, source); }
void check_coordinate_range(const std::vector<Vec3>& points, const std::string& source) { check<3>(points, source); }
void check_coordinate_range(const LineModel& model, const std::string& source) {
  check<2>(model_positions(model), source);
}
void check_coordinate_range(const FractureModel& model, const std::string& source) {
  check<3>(model_positions(model), source);
}

double level_along_beds(const Vec2& p, double dip_deg) {
  if (dip_deg == 0) return p.y();
  const double dip = deg2rad(dip_deg);
  return -std::sin(dip) * p.x() + std::cos(dip) * p.y();
}

Vec2 choose_local_origin(const std::vector<Vec2>& points) { return choose<2>(points); }
Vec3 choose_local_origin(const std::vector<Vec3>& points) { return choose<3>(points); }

std::vector<Vec2> model_positions(const LineModel& model) {
  std::vector<Vec2> all(model.domain.begin(), model.domain.end());
  for (const Polygon2& e : model.excavations) all.insert(all.end(), e.begin(), e.end());
  for (const JointLine& l : model.lines) all.push_back(l.a), all.push_back(l.b);
  for (const ModelPoint& p : model.points) all.push_back(p.p);
  return all;
}

std::vector<Vec3> model_positions(const FractureModel& model) {
  std::vector<Vec3> all;
  if (model.domain_surface)
    all.insert(all.end(), model.domain_surface->vertices.begin(), model.domain_surface->vertices.end());
  else
    all.push_back(model.domain.lo), all.push_back(model.domain.hi);
  for (const Fracture3& f : model.fractures) {
    all.push_back(f.centre);
    all.insert(all.end(), f.vertices.begin(), f.vertices.end());
  }
  for (const ModelPoint3& p : model.points) all.push_back(p.p);
  return all;
}

void move_to_local_origin(LineModel& m) {
  // The domain bounds the model (lines are clipped to it); without one, all of it.
  const Vec2 o = choose_local_origin(m.domain.empty() ? model_positions(m) : m.domain);
  if (o == Vec2::Zero()) return;
  for (Vec2& v : m.domain) v -= o;
  for (Polygon2& e : m.excavations)
    for (Vec2& v : e) v -= o;
  for (JointLine& l : m.lines) l.a -= o, l.b -= o;
  for (ModelPoint& p : m.points) p.p -= o;
  shift_layers(m.layers, level_along_beds(o, m.bedding_dip_deg));
  m.origin += o;
}

void move_to_local_origin(FractureModel& m) {
  const Vec3 o = choose_local_origin(model_positions(m));
  if (o == Vec3::Zero()) return;
  m.domain.lo -= o, m.domain.hi -= o;
  if (m.domain_surface)
    for (Vec3& v : m.domain_surface->vertices) v -= o;
  for (Excavation3& e : m.excavations) {
    for (HalfSpace& h : e.region.half_spaces) h.offset -= h.normal.dot(o);
    if (e.surface)
      for (Vec3& v : e.surface->vertices) v -= o;
  }
  for (Fracture3& f : m.fractures) {
    f.centre -= o;
    for (Vec3& v : f.vertices) v -= o;
  }
  for (ModelPoint3& p : m.points) p.p -= o;
  shift_layers(m.layers, m.bed_normal.dot(o));
  m.origin += o;
}

}  // namespace dda
