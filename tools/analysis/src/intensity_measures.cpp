// Intensity measures of a record (intensity_measures.hpp).
#include "dda/analysis/intensity_measures.hpp"

#include <algorithm>
#include <cmath>

#include "dda/analysis/fourier_spectrum.hpp"
#include "dda/analysis/response_spectrum.hpp"
#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"
#include "dda/common/record.hpp"

namespace dda::analysis {

namespace {

constexpr double kMeanPeriodLow = 0.25, kMeanPeriodHigh = 20.0;  // Hz, Rathje et al. (1998)
constexpr double kPeriodMin = 0.05, kPeriodMax = 4.0;
constexpr int kPeriodCount = 80;

void check_record(const std::vector<double>& a, double dt) {
  if (a.size() < 2) throw InputError("Intensity measures: a record needs at least two samples.");
  if (!(dt > 0.0) || !std::isfinite(dt)) throw InputError("Intensity measures: the time step must be positive.");
}

// Cumulative int a^2 dt at the samples, exact for the linear segments.
std::vector<double> cumulative_square(const std::vector<double>& a, double dt) {
  std::vector<double> c(a.size(), 0.0);
  for (std::size_t i = 1; i < a.size(); ++i)
    c[i] = c[i - 1] + dt * (a[i - 1] * a[i - 1] + a[i - 1] * a[i] + a[i] * a[i]) / 3.0;
  return c;
}

// Time (from the first sample) at which the cumulative int a^2 dt, c at the
// samples, first reaches `target`: within the step from a0 to a1 it is
// c_i + a0^2 s + a0 k s^2 + k^2 s^3 / 3 (k the slope), rising in s, solved by
// bisection.
double time_at_level(const std::vector<double>& a, const std::vector<double>& c, double dt, double target) {
  for (std::size_t i = 1; i < c.size(); ++i) {
    if (c[i] < target) continue;
    const double a0 = a[i - 1], k = (a[i] - a[i - 1]) / dt;
    auto cumulative = [&](double s) { return c[i - 1] + a0 * a0 * s + a0 * k * s * s + k * k * s * s * s / 3.0; };
    double lo = 0.0, hi = dt;
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      (cumulative(mid) < target ? lo : hi) = mid;
    }
    return static_cast<double>(i - 1) * dt + 0.5 * (lo + hi);
  }
  return static_cast<double>(c.size() - 1) * dt;
}

}  // namespace

std::vector<double> predominant_periods() {
  std::vector<double> p(kPeriodCount);
  for (int i = 0; i < kPeriodCount; ++i)
    p[static_cast<std::size_t>(i)] =
        kPeriodMin * std::pow(kPeriodMax / kPeriodMin, static_cast<double>(i) / (kPeriodCount - 1));
  return p;
}

std::vector<double> husid(const std::vector<double>& a, double dt) {
  check_record(a, dt);
  std::vector<double> c = cumulative_square(a, dt);
  const double total = c.back();
  for (double& x : c) x = total > 0.0 ? x / total : 0.0;
  return c;
}

double mean_period(const std::vector<double>& a, double dt) {
  check_record(a, dt);
  SpectrumOptions options;
  options.taper.kind = TaperKind::none;
  const AmplitudeSpectrum s = amplitude_spectrum(a, dt, options);
  double weighted = 0.0, total = 0.0;
  for (std::size_t k = 0; k < s.f.size(); ++k) {
    if (s.f[k] < kMeanPeriodLow || s.f[k] > kMeanPeriodHigh) continue;
    const double c2 = s.amplitude[k] * s.amplitude[k];
    weighted += c2 / s.f[k];
    total += c2;
  }
  return total > 0.0 ? weighted / total : 0.0;
}

IntensityMeasures intensity_measures(const std::vector<double>& a, double dt) {
  check_record(a, dt);
  IntensityMeasures m;
  double v = 0.0, d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (i > 0) {
      const double v1 = v + 0.5 * dt * (a[i - 1] + a[i]);
      d += 0.5 * dt * (v + v1);
      v = v1;
    }
    m.pga = std::max(m.pga, std::abs(a[i]));
    m.pgv = std::max(m.pgv, std::abs(v));
    m.pgd = std::max(m.pgd, std::abs(d));
  }
  const std::vector<double> c = cumulative_square(a, dt);
  m.arias = kPi / (2.0 * kRecordGravity) * c.back();
  m.t5 = time_at_level(a, c, dt, 0.05 * c.back());
  m.t95 = time_at_level(a, c, dt, 0.95 * c.back());
  m.significant_duration = m.t95 - m.t5;
  m.mean_period = mean_period(a, dt);
  const std::vector<double> periods = predominant_periods();
  const ResponseSpectrum rs = response_spectrum(a, dt, periods);
  const auto peak = std::max_element(rs.psa.begin(), rs.psa.end());
  m.predominant_period = periods[static_cast<std::size_t>(peak - rs.psa.begin())];
  return m;
}

}  // namespace dda::analysis
