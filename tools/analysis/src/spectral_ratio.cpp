// Reported spectra and spectral ratios (spectral_ratio.hpp).
#include "dda/analysis/spectral_ratio.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "dda/common/error.hpp"

namespace dda::analysis {

SampledSpectrum report_spectrum(const AmplitudeSpectrum& s, const SpectrumGrid& grid) {
  if (s.f.size() < 2) throw InternalError("report_spectrum: a spectrum of fewer than two frequencies");
  const double lo = std::max(grid.fmin, s.f[1]);
  const double hi = grid.fmax > 0.0 ? std::min(grid.fmax, s.f.back()) : s.f.back();
  // A limit given as a bin frequency keeps that bin despite round-off.
  const double slack = 1e-9 * s.df;
  SampledSpectrum out;
  if (grid.smoothing > 0.0 && grid.points > 0 && lo <= hi) {
    out.f = log_spaced(lo, hi, lo < hi ? grid.points : 1);
  } else {
    for (double f : s.f)
      if (f >= lo - slack && f <= hi + slack) out.f.push_back(f);
  }
  if (out.f.empty()) {
    std::ostringstream m;
    m << "No frequency of the spectrum (" << s.f[1] << " to " << s.f.back() << " Hz, step " << s.df
      << " Hz) lies between --fmin " << (grid.fmin > 0.0 ? grid.fmin : s.f[1]) << " and --fmax "
      << (grid.fmax > 0.0 ? grid.fmax : s.f.back()) << " Hz.";
    throw InputError(m.str());
  }
  if (grid.smoothing > 0.0) {
    out.amplitude = konno_ohmachi(s.f, s.amplitude, out.f, grid.smoothing);
  } else {
    const std::size_t first = static_cast<std::size_t>(std::llround(out.f.front() / s.df));
    out.amplitude.assign(s.amplitude.begin() + static_cast<std::ptrdiff_t>(first),
                         s.amplitude.begin() + static_cast<std::ptrdiff_t>(first + out.f.size()));
  }
  return out;
}

std::vector<double> spectral_ratio(const std::vector<double>& num, const std::vector<double>& den) {
  if (num.size() != den.size()) throw InternalError("spectral_ratio: sizes differ");
  std::vector<double> r(num.size());
  for (std::size_t i = 0; i < num.size(); ++i)
    r[i] = (den[i] != 0.0 && std::isfinite(den[i])) ? num[i] / den[i] : std::numeric_limits<double>::quiet_NaN();
  return r;
}

std::vector<double> quadratic_mean(const std::vector<double>& h1, const std::vector<double>& h2) {
  if (h1.size() != h2.size()) throw InternalError("quadratic_mean: sizes differ");
  std::vector<double> h(h1.size());
  for (std::size_t i = 0; i < h1.size(); ++i) h[i] = std::sqrt(0.5 * (h1[i] * h1[i] + h2[i] * h2[i]));
  return h;
}

SpectralPeak find_peak(const std::vector<double>& f, const std::vector<double>& values) {
  SpectralPeak p{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  for (std::size_t i = 0; i < values.size() && i < f.size(); ++i)
    if (std::isfinite(values[i]) && !(values[i] <= p.value)) p = {f[i], values[i]};
  return p;
}

}  // namespace dda::analysis
