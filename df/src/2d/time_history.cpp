// Time histories of point loads, moving fixed points and body accelerations:
// piecewise linear, or cubic Hermite with rates (model.hpp).
#include <algorithm>

#include "dda/df/2d/model.hpp"

namespace dda::df {
namespace {

// Where `time` falls: the row k with t[k-1] < time <= t[k], and the
// fraction u of that interval.
struct Place {
  std::size_t k;
  double h, u;
};
Place place(const TimeHistory& h, double time) {
  const auto k = static_cast<std::size_t>(std::upper_bound(h.t.begin(), h.t.end(), time) - h.t.begin());
  const std::size_t j = std::min(std::max<std::size_t>(k, 1), h.t.size() - 1);
  const double span = h.t[j] - h.t[j - 1];
  return {j, span, (time - h.t[j - 1]) / span};
}

// Integral over the first fraction u of interval k (rows k-1, k): linear,
// or the cubic Hermite curve through the values with the rates as slopes.
Vec2 interval_integral(const TimeHistory& h, std::size_t k, double span, double u) {
  const Vec2& p0 = h.value[k - 1];
  const Vec2& p1 = h.value[k];
  if (h.rate.empty()) return span * u * (p0 + 0.5 * u * (p1 - p0));
  const double u2 = u * u, u3 = u2 * u, u4 = u3 * u;
  return span * ((u - u3 + 0.5 * u4) * p0 + span * (0.5 * u2 - 2.0 / 3 * u3 + 0.25 * u4) * h.rate[k - 1] +
                 (u3 - 0.5 * u4) * p1 + span * (0.25 * u4 - u3 / 3) * h.rate[k]);
}

// Integral from a row to `dt` beyond it, outside the rows: the row's value
// held, or continued along its rate.
Vec2 beyond(const TimeHistory& h, std::size_t row, double dt) {
  const Vec2 held = dt * h.value[row];
  return h.rate.empty() ? held : Vec2(held + 0.5 * dt * dt * h.rate[row]);
}

// Integral of the table over [a, b], a <= b, visiting only the intervals
// that overlap it (an earthquake table has a row per step: a walk from the
// first row at every step would make a run quadratic in its length).
Vec2 integral_between(const TimeHistory& h, double a, double b) {
  const std::size_t n = h.t.size();
  Vec2 sum(0, 0);
  if (a < h.t[0]) {
    const double e = std::min(b, h.t[0]);
    sum += beyond(h, 0, e - h.t[0]) - beyond(h, 0, a - h.t[0]);
    a = e;
  }
  if (b > h.t[n - 1]) {
    const double s = std::max(a, h.t[n - 1]);
    sum += beyond(h, n - 1, b - h.t[n - 1]) - beyond(h, n - 1, s - h.t[n - 1]);
    b = s;
  }
  if (!(a < b)) return sum;
  auto k = static_cast<std::size_t>(std::upper_bound(h.t.begin(), h.t.end(), a) - h.t.begin());
  for (; k < n && h.t[k - 1] < b; ++k) {
    const double span = h.t[k] - h.t[k - 1];
    const double ua = std::max(0.0, (a - h.t[k - 1]) / span), ub = std::min(1.0, (b - h.t[k - 1]) / span);
    sum += interval_integral(h, k, span, ub) - interval_integral(h, k, span, ua);
  }
  return sum;
}

}  // namespace

Vec2 TimeHistory::at(double time) const {
  const bool smooth = !rate.empty();
  if (time <= t.front()) return smooth ? Vec2(value.front() + (time - t.front()) * rate.front()) : value.front();
  if (time >= t.back()) return smooth ? Vec2(value.back() + (time - t.back()) * rate.back()) : value.back();
  const Place p = place(*this, time);
  const Vec2& p0 = value[p.k - 1];
  const Vec2& p1 = value[p.k];
  const double u = p.u;
  if (!smooth) return p0 + u * (p1 - p0);
  const double u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * p0 + p.h * (u3 - 2 * u2 + u) * rate[p.k - 1] + (3 * u2 - 2 * u3) * p1 +
         p.h * (u3 - u2) * rate[p.k];
}

Vec2 TimeHistory::average(double t0, double t1) const {
  if (t1 <= t0) return at(t0);
  return integral_between(*this, t0, t1) / (t1 - t0);
}

Vec2 fixed_point_target(const FixedPoint& f, const Vec2& anchor, double t) {
  return f.history ? anchor + f.history->at(t) : anchor;
}

Vec2 load_force(const PointLoad& l, double t0, double t1) { return l.history ? l.history->average(t0, t1) : l.force; }

}  // namespace dda::df
