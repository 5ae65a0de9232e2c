#include "distribution.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace dda::dc::detail {

using nlohmann::json;

namespace {

// Percentile p (0..100) of sorted values by linear interpolation between
// order statistics: h = (n-1) p/100, v[floor h] + (h - floor h)(v[floor h + 1]
// - v[floor h]) (Hyndman & Fan type 7, numpy's default "linear").
double percentile(const std::vector<double>& sorted, double p) {
  const std::size_t n = sorted.size();
  if (n == 1) return sorted[0];
  const double h = (static_cast<double>(n) - 1.0) * p / 100.0;
  const std::size_t lo = std::min(static_cast<std::size_t>(std::floor(h)), n - 1);
  if (lo + 1 >= n) return sorted[n - 1];
  const double frac = h - static_cast<double>(lo);
  return sorted[lo] + frac * (sorted[lo + 1] - sorted[lo]);
}

// Equal-width bins from min to max, the last bin closed (as numpy.histogram);
// when all values are equal the range is [v - 0.5, v + 0.5].
json histogram(const std::vector<double>& sorted, int bins) {
  double lo = sorted.front(), hi = sorted.back();
  if (!(hi > lo)) {
    lo -= 0.5;
    hi += 0.5;
  }
  std::vector<double> edges(static_cast<std::size_t>(bins) + 1);
  for (int i = 0; i <= bins; ++i) edges[static_cast<std::size_t>(i)] = lo + (hi - lo) * i / bins;
  edges.back() = hi;
  std::vector<long long> counts(static_cast<std::size_t>(bins), 0);
  for (double x : sorted) {
    long long k = static_cast<long long>(std::floor((x - lo) / (hi - lo) * bins));
    k = std::clamp<long long>(k, 0, bins - 1);
    // Agree with the edges as written, whatever the rounding above did.
    while (k > 0 && x < edges[static_cast<std::size_t>(k)]) --k;
    while (k < bins - 1 && x >= edges[static_cast<std::size_t>(k) + 1]) ++k;
    ++counts[static_cast<std::size_t>(k)];
  }
  return json{{"edges", edges}, {"counts", counts}};
}

}  // namespace

json distribution(std::vector<double> v, int bins) {
  if (v.empty()) return nullptr;
  std::sort(v.begin(), v.end());
  const double n = static_cast<double>(v.size());
  double sum = 0;
  for (double x : v) sum += x;
  const double mean = sum / n;
  double ss = 0;
  for (double x : v) ss += (x - mean) * (x - mean);
  json pct = json::object();
  static const std::pair<const char*, double> kPercentiles[] = {
      {"p5", 5}, {"p10", 10}, {"p25", 25}, {"p50", 50}, {"p75", 75}, {"p90", 90}, {"p95", 95}};
  for (const auto& [key, p] : kPercentiles) pct[key] = percentile(v, p);
  return json{{"min", v.front()},
              {"max", v.back()},
              {"mean", mean},
              {"std", std::sqrt(ss / n)},
              {"median", percentile(v, 50)},
              {"percentiles", pct},
              {"histogram", histogram(v, bins)}};
}

}  // namespace dda::dc::detail
