// Konno-Ohmachi smoothing (konno_ohmachi.hpp).
#include "dda/analysis/konno_ohmachi.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"

namespace dda::analysis {

namespace {

constexpr double kWindowLimit = 10.0 * kPi;  // |b log10(f/fc)| of the window's end: ten lobes

// W as a function of x = b log10(f/fc), inside the limited window.
double window_of(double x) {
  if (std::abs(x) > kWindowLimit) return 0.0;
  if (std::abs(x) < 1e-4) return 1.0 - (2.0 / 3.0) * x * x;  // sinc^4 = 1 - 2x^2/3 + O(x^4): no 0/0 at fc
  const double s = std::sin(x) / x;
  return (s * s) * (s * s);
}

}  // namespace

double konno_ohmachi_window(double f, double fc, double b) {
  if (!(f > 0.0) || !(fc > 0.0)) return 0.0;
  return window_of(b * std::log10(f / fc));
}

std::vector<double> konno_ohmachi(const std::vector<double>& f, const std::vector<double>& a,
                                  const std::vector<double>& centres, double b) {
  if (f.size() != a.size() || !(b > 0.0)) throw InternalError("konno_ohmachi: sizes differ or b <= 0");
  // log10 f once for all centres (the 0 Hz sample, if any, is skipped).
  const std::size_t first = (!f.empty() && f.front() <= 0.0) ? 1 : 0;
  std::vector<double> lf(f.size(), 0.0);
  for (std::size_t k = first; k < f.size(); ++k) lf[k] = std::log10(f[k]);
  const double reach = kWindowLimit / b;  // half-width of the window in log10 f
  std::vector<double> out(centres.size());
  for (std::size_t c = 0; c < centres.size(); ++c) {
    const double fc = centres[c];
    if (!(fc > 0.0)) throw InternalError("konno_ohmachi: centre frequencies must be positive");
    const double lfc = std::log10(fc);
    const auto begin = f.begin() + static_cast<std::ptrdiff_t>(first);
    const auto lo = std::lower_bound(begin, f.end(), fc * std::pow(10.0, -reach));
    const auto hi = std::upper_bound(lo, f.end(), fc * std::pow(10.0, reach));
    double sw = 0.0, swa = 0.0;
    for (auto it = lo; it != hi; ++it) {
      const std::size_t k = static_cast<std::size_t>(it - f.begin());
      const double w = window_of(b * (lf[k] - lfc));
      sw += w;
      swa += w * a[k];
    }
    out[c] = sw > 0.0 ? swa / sw : std::numeric_limits<double>::quiet_NaN();
  }
  return out;
}

std::vector<double> log_spaced(double lo, double hi, std::size_t n) {
  if (!(lo > 0.0) || !(hi >= lo)) throw InternalError("log_spaced: needs 0 < lo <= hi");
  if (n == 0) return {};
  if (n == 1) return {lo};
  std::vector<double> out(n);
  const double a = std::log10(lo), step = (std::log10(hi) - a) / static_cast<double>(n - 1);
  for (std::size_t i = 0; i < n; ++i) out[i] = std::pow(10.0, a + step * static_cast<double>(i));
  out.front() = lo;  // exact ends, whatever pow's round-off
  out.back() = hi;
  return out;
}

}  // namespace dda::analysis
