// Uniform sampling of histories (sampling.hpp).
#include "dda/analysis/sampling.hpp"

#include <algorithm>
#include <cmath>

#include "dda/common/error.hpp"

namespace dda::analysis {

double median_step(const std::vector<double>& t) {
  if (t.size() < 2) throw InternalError("median_step: fewer than two samples");
  std::vector<double> steps(t.size() - 1);
  for (std::size_t i = 1; i < t.size(); ++i) steps[i - 1] = t[i] - t[i - 1];
  const std::size_t mid = steps.size() / 2;
  std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(mid), steps.end());
  if (steps.size() % 2 == 1) return steps[mid];
  const double upper = steps[mid];
  const double lower = *std::max_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(mid));
  return 0.5 * (lower + upper);
}

bool is_uniform(const std::vector<double>& t) {
  if (t.size() < 2) return true;
  const double dt = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  for (std::size_t i = 1; i < t.size(); ++i)
    if (std::abs(t[i] - t[i - 1] - dt) > 1e-6 * dt) return false;
  return true;
}

UniformSeries resample_uniform(const std::vector<double>& t, const std::vector<double>& x, double dt) {
  if (t.size() < 2 || t.size() != x.size() || !(dt > 0.0))
    throw InternalError("resample_uniform: needs two samples or more and a positive step");
  UniformSeries out;
  out.t0 = t.front();
  out.dt = dt;
  // The 1e-12 keeps the last sample when the duration is a whole number of steps up to round-off.
  const std::size_t n = static_cast<std::size_t>(std::floor((t.back() - t.front()) / dt * (1.0 + 1e-12))) + 1;
  out.x.resize(n);
  std::size_t j = 1;
  for (std::size_t i = 0; i < n; ++i) {
    const double time = std::min(out.t0 + static_cast<double>(i) * dt, t.back());
    while (j + 1 < t.size() && t[j] < time) ++j;
    const double w = (time - t[j - 1]) / (t[j] - t[j - 1]);
    out.x[i] = (1.0 - w) * x[j - 1] + w * x[j];
  }
  return out;
}

std::vector<double> central_difference(const std::vector<double>& x, double dt) {
  const std::size_t n = x.size();
  std::vector<double> d(n, 0.0);
  if (n < 2) return d;
  if (n == 2) {
    d[0] = d[1] = (x[1] - x[0]) / dt;
    return d;
  }
  for (std::size_t i = 1; i + 1 < n; ++i) d[i] = (x[i + 1] - x[i - 1]) / (2.0 * dt);
  d[0] = (-3.0 * x[0] + 4.0 * x[1] - x[2]) / (2.0 * dt);
  d[n - 1] = (3.0 * x[n - 1] - 4.0 * x[n - 2] + x[n - 3]) / (2.0 * dt);
  return d;
}

}  // namespace dda::analysis
