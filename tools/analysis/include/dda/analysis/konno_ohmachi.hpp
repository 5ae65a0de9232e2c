#pragma once
// Konno-Ohmachi smoothing of amplitude spectra (Konno & Ohmachi 1998, BSSA
// 88(1), 228-241): a window of constant width on a logarithmic frequency
// axis, so a resonance is smoothed alike at 0.5 Hz and at 20 Hz,
//   W(f, fc) = [sin(b log10(f/fc)) / (b log10(f/fc))]^4,   W(fc, fc) = 1,
// and the smoothed spectrum at the centre frequency fc is the weighted mean
//   S(fc) = sum_k W(f_k, fc) A(f_k) / sum_k W(f_k, fc)
// (normalised at every fc, so a flat spectrum stays flat). b = 40 is the
// usual bandwidth (larger b: narrower); the main lobe ends where
// b |log10(f/fc)| = pi, i.e. at fc 10^(+-pi/b), and W = 1/2 at
// b |log10(f/fc)| = 1.0019 (sinc^4 = 1/2).
//
// The window is limited to its first ten lobes on each side,
// b |log10(f/fc)| <= 10 pi, where it is exactly zero and its envelope
// (b log10(f/fc))^-4 is 1e-6; the cost of one centre is then the number of
// samples in [fc 10^(-10 pi/b), fc 10^(10 pi/b)] (0.16 fc .. 6.1 fc for
// b = 40), not the whole spectrum. The far lobes left out matter only for a
// spectrum rising steeply with frequency, where the full window lets the
// many high-frequency samples leak into the low-frequency centres; the
// limited window is the more local of the two.
#include <vector>

namespace dda::analysis {

constexpr double kKonnoOhmachiBandwidth = 40.0;

// W(f, fc) for f, fc > 0 (0 outside the limited window and for f <= 0).
double konno_ohmachi_window(double f, double fc, double b);

// S at each of `centres` (> 0) from the amplitudes `a` at the increasing
// frequencies `f` (f >= 0; a 0 Hz sample has no weight). A centre whose
// window holds no sample gets NaN.
std::vector<double> konno_ohmachi(const std::vector<double>& f, const std::vector<double>& a,
                                  const std::vector<double>& centres, double b = kKonnoOhmachiBandwidth);

// n frequencies from lo to hi (both included), evenly spaced in log f.
std::vector<double> log_spaced(double lo, double hi, std::size_t n);

}  // namespace dda::analysis
