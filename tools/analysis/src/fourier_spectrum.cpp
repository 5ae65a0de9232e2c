// Fourier amplitude spectrum (fourier_spectrum.hpp).
#include "dda/analysis/fourier_spectrum.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "dda/analysis/fft.hpp"
#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"

namespace dda::analysis {

Taper parse_taper(const std::string& text, const std::string& flag) {
  if (text == "none") return {TaperKind::none, 0.0};
  if (text == "hann") return {TaperKind::hann, 1.0};
  if (text == "tukey") return {TaperKind::tukey, 0.1};
  if (text.rfind("tukey:", 0) == 0) {
    double alpha = -1.0;
    const char* b = text.data() + 6;
    const char* e = text.data() + text.size();
    const auto r = std::from_chars(b, e, alpha);
    if (r.ec == std::errc() && r.ptr == e && alpha >= 0.0 && alpha <= 1.0) return {TaperKind::tukey, alpha};
    throw InputError(flag + ": '" + text + "' needs a tapered fraction between 0 and 1 after 'tukey:'.");
  }
  throw InputError(flag + ": '" + text + "' is not none, hann, tukey or tukey:FRACTION.");
}

std::string taper_name(const Taper& taper) {
  switch (taper.kind) {
    case TaperKind::none: return "none";
    case TaperKind::hann: return "hann";
    case TaperKind::tukey: break;
  }
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, taper.fraction);
  return "tukey:" + std::string(buf, r.ptr);
}

std::vector<double> taper_window(std::size_t n, const Taper& taper) {
  std::vector<double> w(n, 1.0);
  if (n < 2 || taper.kind == TaperKind::none) return w;
  const double alpha = taper.kind == TaperKind::hann ? 1.0 : taper.fraction;
  if (alpha <= 0.0) return w;
  const double span = static_cast<double>(n - 1);
  const double flank = 0.5 * alpha * span;  // length of each cosine flank, in samples
  for (std::size_t i = 0; i < n; ++i) {
    const double d = std::min(static_cast<double>(i), span - static_cast<double>(i));  // from the nearer end
    if (d < flank) w[i] = 0.5 * (1.0 - std::cos(kPi * d / flank));
  }
  return w;
}

AmplitudeScale parse_amplitude_scale(const std::string& text, const std::string& flag) {
  if (text == "fourier") return AmplitudeScale::fourier;
  if (text == "sine") return AmplitudeScale::sine;
  throw InputError(flag + ": '" + text + "' is not fourier or sine.");
}

std::vector<double> prepare_signal(const std::vector<double>& x, const SpectrumOptions& options) {
  const std::size_t n = x.size();
  std::vector<double> y(x);
  if (n == 0) return y;
  double mean = 0.0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(n);
  double slope = 0.0;
  const double mid = 0.5 * static_cast<double>(n - 1);
  if (options.detrend && n > 1) {  // least squares on the centred index: slope = sum (i - mid) x / sum (i - mid)^2
    double sxy = 0.0, sxx = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double c = static_cast<double>(i) - mid;
      sxy += c * x[i];
      sxx += c * c;
    }
    slope = sxy / sxx;
  }
  const std::vector<double> w = taper_window(n, options.taper);
  for (std::size_t i = 0; i < n; ++i) y[i] = (x[i] - mean - slope * (static_cast<double>(i) - mid)) * w[i];
  return y;
}

AmplitudeSpectrum amplitude_spectrum(const std::vector<double>& x, double dt, const SpectrumOptions& options) {
  const std::size_t n = x.size();
  if (n < 2 || !(dt > 0.0)) throw InternalError("amplitude_spectrum: needs two samples or more and a positive step");
  const std::vector<Complex> X = real_fft(prepare_signal(x, options));
  AmplitudeSpectrum s;
  s.df = 1.0 / (static_cast<double>(n) * dt);
  double wsum = 0.0;
  for (double w : taper_window(n, options.taper)) wsum += w;
  s.f.resize(X.size());
  s.amplitude.resize(X.size());
  for (std::size_t k = 0; k < X.size(); ++k) {
    s.f[k] = static_cast<double>(k) * s.df;
    const double mag = std::abs(X[k]);
    if (options.scale == AmplitudeScale::fourier) {
      s.amplitude[k] = dt * mag;
    } else {
      const bool edge = k == 0 || 2 * k == n;  // 0 Hz and, for even N, the Nyquist bin have no mirror image
      s.amplitude[k] = (edge ? 1.0 : 2.0) * mag / wsum;
    }
  }
  return s;
}

}  // namespace dda::analysis
