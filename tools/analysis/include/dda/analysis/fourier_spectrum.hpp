#pragma once
// Fourier amplitude spectrum of a uniformly sampled signal x_n = x(n dt),
// n = 0 .. N-1 (docs/analytical.md, "Spectra").
//
// Preparation, in this order: the mean is removed (always; with `detrend`
// the least-squares straight line instead), then the taper w_n multiplies
// the signal:
//   none   w_n = 1
//   hann   w_n = (1 - cos(2 pi n / (N-1))) / 2
//   tukey  cosine flanks over the fraction alpha of the record (alpha/2 at
//          each end), 1 in between; alpha = 0 is no taper, alpha = 1 Hann.
// With X_k = sum_n x_n w_n exp(-2 pi i k n / N) (fft.hpp) at the frequencies
// f_k = k / (N dt), k = 0 .. floor(N/2) (0 to the Nyquist frequency), the
// one-sided amplitude is, by `scale`:
//   fourier  A(f_k) = dt |X_k|       (units of x times s: the continuous
//            Fourier transform's modulus; a sine of amplitude a and an
//            integer number of cycles over T = N dt gives a T / 2 at its
//            frequency, untapered; Parseval:
//            sum_n (x_n w_n)^2 dt = df [A_0^2 + 2 sum_{0<k<N/2} A_k^2 + A_{N/2}^2],
//            the last term for even N only, df = 1 / (N dt))
//   sine     A(f_k) = 2 |X_k| / sum_n w_n  (k = 0 and k = N/2: |X_k| / sum w):
//            the amplitude of a sinusoid on a bin, in the units of x,
//            corrected for the taper's coherent gain (sum w / N).
// The fourier scale is not corrected for the taper: it is the transform of
// the tapered record, which is what spectral ratios divide (the taper is the
// same on both signals and cancels).
#include <string>
#include <vector>

namespace dda::analysis {

enum class TaperKind { none, hann, tukey };

struct Taper {
  TaperKind kind = TaperKind::tukey;
  double fraction = 0.1;  // tukey: the tapered fraction alpha (0..1)
};
// "none", "hann", "tukey" (alpha 0.1) or "tukey:ALPHA"; InputError naming `flag`.
Taper parse_taper(const std::string& text, const std::string& flag);
std::string taper_name(const Taper& taper);  // as parse_taper reads it
std::vector<double> taper_window(std::size_t n, const Taper& taper);

enum class AmplitudeScale { fourier, sine };
AmplitudeScale parse_amplitude_scale(const std::string& text, const std::string& flag);

struct SpectrumOptions {
  bool detrend = false;
  Taper taper;
  AmplitudeScale scale = AmplitudeScale::fourier;
};

// The signal the transform sees: x without its mean (or trend), tapered.
std::vector<double> prepare_signal(const std::vector<double>& x, const SpectrumOptions& options);

struct AmplitudeSpectrum {
  std::vector<double> f;          // Hz, k / (N dt)
  std::vector<double> amplitude;  // as `scale` says
  double df = 0.0;                // 1 / (N dt)
};

// x at least two samples, dt > 0.
AmplitudeSpectrum amplitude_spectrum(const std::vector<double>& x, double dt, const SpectrumOptions& options);

}  // namespace dda::analysis
