// Empirical Newmark-displacement regressions (displacement_regressions.hpp).
#include "dda/analysis/displacement_regressions.hpp"

#include <cmath>
#include <limits>

namespace dda::analysis {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
bool positive(double x) { return x > 0.0 && std::isfinite(x); }
}  // namespace

Regression jibson2007_ratio(double ky, double pga_g) {
  if (!positive(ky) || !positive(pga_g)) return {kNaN, 0.510};
  const double r = ky / pga_g;
  if (r >= 1.0) return {0.0, 0.510};
  return {std::pow(10.0, 0.215) * std::pow(1.0 - r, 2.341) * std::pow(r, -1.438), 0.510};
}

Regression jibson2007_arias(double ky, double arias) {
  if (!positive(ky) || !positive(arias)) return {kNaN, 0.656};
  return {std::pow(10.0, 2.401 * std::log10(arias) - 3.481 * std::log10(ky) - 3.230), 0.656};
}

Regression jibson2007_arias_ratio(double ky, double pga_g, double arias) {
  if (!positive(ky) || !positive(pga_g) || !positive(arias)) return {kNaN, 0.616};
  const double r = ky / pga_g;
  if (r >= 1.0) return {0.0, 0.616};
  return {std::pow(10.0, 0.561 * std::log10(arias) - 3.833 * std::log10(r) - 1.474), 0.616};
}

Regression bray_travasarou2007(double ky, double sa_g, double ts, double magnitude) {
  if (!positive(ky) || !positive(sa_g) || !(ts >= 0.0) || !std::isfinite(magnitude)) return {kNaN, 0.66};
  const double lk = std::log(ky), ls = std::log(sa_g);
  const bool stiff = ts < 0.05;
  const double ln_d = (stiff ? -0.22 : -1.10) - 2.83 * lk - 0.333 * lk * lk + 0.566 * lk * ls + 3.04 * ls -
                      0.244 * ls * ls + (stiff ? 0.0 : 1.50 * ts) + 0.278 * (magnitude - 7.0);
  return {std::exp(ln_d), 0.66};
}

double probability_zero_bt2007(double ky, double sa_g, double ts) {
  if (!positive(ky) || !positive(sa_g) || !(ts >= 0.0)) return kNaN;
  const double lk = std::log(ky);
  const double x = -1.76 - 3.22 * lk - 0.484 * ts * lk + 3.52 * std::log(sa_g);
  return 1.0 - 0.5 * std::erfc(-x / std::sqrt(2.0));
}

Regression saygili_rathje2008(double ky, double pga_g, double pgv_cm_s) {
  if (!positive(ky) || !positive(pga_g) || !positive(pgv_cm_s)) return {kNaN, 0.0};
  const double r = ky / pga_g;
  const double sigma = 0.405 + 0.524 * r;
  if (r >= 1.0) return {0.0, sigma};
  const double ln_d = -1.56 - 4.58 * r - 20.84 * r * r + 44.75 * r * r * r - 30.50 * r * r * r * r -
                      0.64 * std::log(pga_g) + 1.55 * std::log(pgv_cm_s);
  return {std::exp(ln_d), sigma};
}

}  // namespace dda::analysis
