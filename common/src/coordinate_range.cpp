#include "dda/common/coordinate_range.hpp"

#include <algorithm>
#include <cmath>

#include "dda/common/error.hpp"
#include "dda/common/short_number.hpp"

namespace dda {
namespace {

// A round shift that brings the model's centre near the origin: the centre
// to three significant digits.
std::string shift_of(const double* centre, int dims) {
  std::string out = "(";
  for (int k = 0; k < dims; ++k) out += (k ? ", " : "") + short_number(-centre[k]);
  return out + ")";
}

template <int Dims, class Point>
void check(const std::vector<Point>& points, const std::string& source) {
  if (points.empty()) return;
  double lo[Dims], hi[Dims], farthest = 0;
  for (int k = 0; k < Dims; ++k) lo[k] = 1e308, hi[k] = -1e308;
  for (const Point& p : points)
    for (int k = 0; k < Dims; ++k) {
      if (!std::isfinite(p[k])) throw InputError(source + ": has a coordinate that is not a finite number.");
      lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
      farthest = std::max(farthest, std::abs(p[k]));
    }
  double size2 = 0, centre[Dims];
  for (int k = 0; k < Dims; ++k) size2 += (hi[k] - lo[k]) * (hi[k] - lo[k]), centre[k] = 0.5 * (lo[k] + hi[k]);
  const double size = std::sqrt(size2);
  if (farthest > kFarthestCoordinate)
    throw InputError(source + ": has coordinates up to " + short_number(farthest) + " m, beyond the " +
                     short_number(kFarthestCoordinate) +
                     " m any model may reach (coordinates are metres); give them about a local origin near the model.");
  if (farthest > kFarthestInSizes * size)
    throw InputError(source + ": lies up to " + short_number(farthest) + " m from the origin and is only " +
                     short_number(size) + " m across; doubles there resolve " + short_number(farthest * 2.2e-16) +
                     " m, too coarse for its details; give its coordinates about a local origin near it (shift every "
                     "point by " +
                     shift_of(centre, Dims) + ").");
}

}  // namespace

void check_coordinate_range(const std::vector<Vec2>& points, const std::string& source) { check<2>(points, source); }
void check_coordinate_range(const std::vector<Vec3>& points, const std::string& source) { check<3>(points, source); }

void check_coordinate_range(const LineModel& model, const std::string& source) {
  std::vector<Vec2> all(model.domain.begin(), model.domain.end());
  for (const Polygon2& e : model.excavations) all.insert(all.end(), e.begin(), e.end());
  for (const JointLine& l : model.lines) all.push_back(l.a), all.push_back(l.b);
  for (const ModelPoint& p : model.points) all.push_back(p.p);
  check<2>(all, source);
}

void check_coordinate_range(const FractureModel& model, const std::string& source) {
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
  check<3>(all, source);
}

}  // namespace dda
