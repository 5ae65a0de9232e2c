#include "dda/common/origin_h5.hpp"

#include <cmath>

#include "dda/common/coordinate_range.hpp"

namespace dda::io {
namespace {

constexpr const char* kAxes[3] = {"origin_x", "origin_y", "origin_z"};

template <class Point>
void write(h5::Writer& w, hid_t obj, const Point& origin) {
  if (origin == Point::Zero()) return;
  for (int k = 0; k < origin.size(); ++k) w.attr_f64(obj, kAxes[k], origin[k]);
}

template <class Point>
Point read(const h5::Reader& r, hid_t obj, const std::string& where) {
  Point origin = Point::Zero();
  for (int k = 0; k < origin.size(); ++k) {
    origin[k] = r.attr_f64(obj, kAxes[k], where).value_or(0.0);
    if (!std::isfinite(origin[k]) || std::abs(origin[k]) > kFarthestCoordinate)
      r.fail(std::string("attribute ") + kAxes[k] + " of " + where + " is not a finite coordinate within 1e+15 m");
  }
  return origin;
}

}  // namespace

void write_origin(h5::Writer& w, hid_t obj, const Vec2& origin) { write(w, obj, origin); }
void write_origin(h5::Writer& w, hid_t obj, const Vec3& origin) { write(w, obj, origin); }
Vec2 read_origin2(const h5::Reader& r, hid_t obj, const std::string& where) { return read<Vec2>(r, obj, where); }
Vec3 read_origin3(const h5::Reader& r, hid_t obj, const std::string& where) { return read<Vec3>(r, obj, where); }

}  // namespace dda::io
