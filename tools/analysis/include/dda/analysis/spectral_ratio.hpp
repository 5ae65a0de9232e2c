#pragma once
// Spectra as reported (frequency range, smoothing) and their ratios: the
// classical site-to-reference spectral ratio and the H/V ratio of one
// receiver (docs/analytical.md, "Spectra").
//
//  * SSR (Borcherdt 1970): S_site(f) / S_reference(f), both amplitude
//    spectra of the same quantity and component, same sampling and
//    processing, each smoothed before dividing.
//  * H/V (Nakamura 1989; Lermo & Chavez-Garcia 1993 for earthquake records):
//    S_H(f) / S_V(f). In a 2D model there is one horizontal component, so
//    S_H is the smoothed |X_x|, S_V the smoothed |X_y| (y up). With two
//    horizontal components S_H is their quadratic mean
//    sqrt((S_H1^2 + S_H2^2) / 2) of the separately smoothed spectra (the
//    energy-average of the two directions: an isotropic motion of amplitude
//    A in both gives A).
// A ratio is NaN where its denominator is zero.
#include <vector>

#include "dda/analysis/fourier_spectrum.hpp"
#include "dda/analysis/konno_ohmachi.hpp"

namespace dda::analysis {

struct SpectrumGrid {
  double fmin = 0.0;  // Hz; 0 (or below it): the lowest nonzero frequency 1 / (N dt)
  double fmax = 0.0;  // Hz; 0 (or above it): the Nyquist frequency
  double smoothing = kKonnoOhmachiBandwidth;  // Konno-Ohmachi b; 0: none
  std::size_t points = 500;  // smoothed: this many centres evenly spaced in log f; 0: the transform's frequencies
};

struct SampledSpectrum {
  std::vector<double> f, amplitude;
};

// `s` over [fmin, fmax] clipped to [df, Nyquist]: unsmoothed at the
// transform's frequencies; smoothed at the log-spaced centres (or the
// transform's frequencies with points = 0; the cost then grows as the
// square of the record length). InputError when the range holds no
// frequency of the spectrum.
SampledSpectrum report_spectrum(const AmplitudeSpectrum& s, const SpectrumGrid& grid);

// num / den, NaN where den is zero or not finite.
std::vector<double> spectral_ratio(const std::vector<double>& num, const std::vector<double>& den);

// sqrt((h1^2 + h2^2) / 2), sample by sample.
std::vector<double> quadratic_mean(const std::vector<double>& h1, const std::vector<double>& h2);

struct SpectralPeak {
  double frequency = 0.0, value = 0.0;  // NaN when no value is finite
};
// The largest finite value and its frequency (the sample itself, no interpolation).
SpectralPeak find_peak(const std::vector<double>& f, const std::vector<double>& values);

}  // namespace dda::analysis
