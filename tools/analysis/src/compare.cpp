// A model history against a reference solution (compare.hpp).
#include "dda/analysis/compare.hpp"

#include <algorithm>
#include <cmath>

#include "dda/common/error.hpp"

namespace dda::analysis {

SeriesComparison compare_series(const std::vector<double>& model_t, const std::vector<double>& model_u,
                                const std::vector<double>& reference_t, const std::vector<double>& reference_u,
                                double floor) {
  SeriesComparison c;
  if (reference_t.empty() || model_t.empty()) throw InputError("There is nothing to compare (an empty history).");
  const double r0 = reference_t.front(), r1 = reference_t.back();
  const double tol = 1e-9 * std::max({1.0, std::abs(r0), std::abs(r1)});
  double umax = 0;
  for (const double u : reference_u) umax = std::max(umax, std::abs(u));
  c.floor = floor > 0 ? floor : 0.01 * umax;
  std::size_t j = 1;
  double sum2 = 0;
  for (std::size_t i = 0; i < model_t.size(); ++i) {
    const double t = model_t[i];
    if (t < r0 - tol || t > r1 + tol) continue;
    double ur = reference_u.front();
    if (reference_t.size() > 1) {
      const double tc = std::clamp(t, r0, r1);
      while (j + 1 < reference_t.size() && reference_t[j] < tc) ++j;
      const double w = (tc - reference_t[j - 1]) / (reference_t[j] - reference_t[j - 1]);
      ur = (1 - w) * reference_u[j - 1] + w * reference_u[j];
    }
    const double diff = model_u[i] - ur;
    c.t.push_back(t);
    c.model.push_back(model_u[i]);
    c.reference.push_back(ur);
    c.difference.push_back(diff);
    c.relative.push_back(c.floor > 0 ? diff / std::max(std::abs(ur), c.floor) : 0.0);
    c.max_abs_difference = std::max(c.max_abs_difference, std::abs(diff));
    sum2 += diff * diff;
  }
  if (c.t.empty())
    throw InputError("The model history (t = " + std::to_string(model_t.front()) + " to " +
                     std::to_string(model_t.back()) + " s) and the reference (t = " + std::to_string(r0) + " to " +
                     std::to_string(r1) + " s) share no time.");
  c.rms_difference = std::sqrt(sum2 / static_cast<double>(c.t.size()));
  c.final_relative = c.reference.back() != 0 ? c.difference.back() / std::abs(c.reference.back()) : 0.0;
  return c;
}

}  // namespace dda::analysis
