// Time tables of the 3D points (points3d.hpp).
#include <cmath>

#include "dda/common/error.hpp"
#include "dda/df/3d/points3d.hpp"

namespace dda::df3 {

void TimeHistory3::check(const std::string& what) const {
  if (t.empty() || t.size() != value.size()) throw InputError(what + ": give one value per time, at least one.");
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (!std::isfinite(t[k]) || !value[k].allFinite())
      throw InputError(what + ": row " + std::to_string(k + 1) + " is not a finite number.");
    if (k > 0 && !(t[k] > t[k - 1]))
      throw InputError(what + ": times must increase strictly (row " + std::to_string(k + 1) + ").");
  }
}

Vec3 TimeHistory3::at(double time) const {
  if (time <= t.front()) return value.front();
  if (time >= t.back()) return value.back();
  std::size_t k = 0;
  while (t[k + 1] < time) ++k;
  const double s = (time - t[k]) / (t[k + 1] - t[k]);
  return (1 - s) * value[k] + s * value[k + 1];
}

Vec3 TimeHistory3::average(double t0, double t1) const {
  if (!(t1 > t0)) return at(t0);
  // Trapezoids between t0, every table time inside (t0, t1), and t1: exact
  // for a piecewise-linear table.
  Vec3 sum(0, 0, 0);
  double a = t0;
  Vec3 va = at(t0);
  for (std::size_t k = 0; k <= t.size(); ++k) {
    const double b = k < t.size() ? t[k] : t1;
    if (b <= a) continue;
    const double e = std::min(b, t1);
    const Vec3 ve = at(e);
    sum += 0.5 * (e - a) * (va + ve);
    a = e;
    va = ve;
    if (a >= t1) break;
  }
  return sum / (t1 - t0);
}

}  // namespace dda::df3
