// Piecewise-linear time histories of point loads and moving fixed points.
#include <algorithm>

#include "dda/df/model.hpp"

namespace dda::df {
namespace {

// Integral of the table from its first time to `time` (the value before the
// first time and after the last is held constant).
Vec2 integral_to(const TimeHistory& h, double time) {
  const std::size_t n = h.t.size();
  if (time <= h.t[0]) return (time - h.t[0]) * h.value[0];
  Vec2 sum(0, 0);
  for (std::size_t k = 1; k < n; ++k) {
    if (time <= h.t[k]) {
      const double w = (time - h.t[k - 1]) / (h.t[k] - h.t[k - 1]);
      const Vec2 v = h.value[k - 1] + w * (h.value[k] - h.value[k - 1]);
      return sum + 0.5 * (time - h.t[k - 1]) * (h.value[k - 1] + v);
    }
    sum += 0.5 * (h.t[k] - h.t[k - 1]) * (h.value[k - 1] + h.value[k]);
  }
  return sum + (time - h.t[n - 1]) * h.value[n - 1];
}

}  // namespace

Vec2 TimeHistory::at(double time) const {
  if (time <= t.front()) return value.front();
  if (time >= t.back()) return value.back();
  const auto k = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), time) - t.begin());
  const double w = (time - t[k - 1]) / (t[k] - t[k - 1]);
  return value[k - 1] + w * (value[k] - value[k - 1]);
}

Vec2 TimeHistory::average(double t0, double t1) const {
  if (t1 <= t0) return at(t0);
  return (integral_to(*this, t1) - integral_to(*this, t0)) / (t1 - t0);
}

Vec2 fixed_point_target(const FixedPoint& f, const Vec2& anchor, double t) {
  return f.history ? anchor + f.history->at(t) : anchor;
}

Vec2 load_force(const PointLoad& l, double t0, double t1) { return l.history ? l.history->average(t0, t1) : l.force; }

}  // namespace dda::df
