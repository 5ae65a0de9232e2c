#pragma once
// Zero-phase Butterworth filters of uniformly sampled signals.
//
// Design: the analog Butterworth prototype of order N, split into second-order
// sections (plus one first-order section for odd N), mapped to the z-plane by
// the bilinear transform with the cutoff prewarped, K = tan(pi fc / fs), so the
// digital response has exactly -3 dB at fc:
//   |H(f)|^2 = 1 / (1 + (tan(pi f / fs) / tan(pi fc / fs))^(2N))   (low-pass)
//   |H(f)|^2 = 1 / (1 + (tan(pi fc / fs) / tan(pi f / fs))^(2N))   (high-pass)
// A band-pass is the high-pass at f_low followed by the low-pass at f_high,
// both of order N.
//
// Zero phase: the cascade runs forward, then backward over the reversed
// output, so the total response is |H(f)|^2 with no phase shift (1/2 at the
// cutoff). To tame the start and end transients the signal is extended at
// both ends by its odd reflection (2 x0 - x[k]) over
// min(n - 1, max(6 N, 3 fs / fc_min)) samples, removed after filtering.
#include <string>
#include <vector>

namespace dda {

enum class FilterKind { lowpass, highpass, bandpass };

struct ButterworthSpec {
  FilterKind kind = FilterKind::lowpass;
  int order = 4;          // 1..12
  double f_low = 0.0;     // Hz: high-pass cutoff (highpass, bandpass)
  double f_high = 0.0;    // Hz: low-pass cutoff (lowpass, bandpass)
};

// "lowpass", "highpass", "bandpass" (also "low", "high", "band"); anything
// else is an InputError naming `what`.
FilterKind parse_filter_kind(const std::string& text, const std::string& what);

// One section: y[n] = b0 x[n] + b1 x[n-1] + b2 x[n-2] - a1 y[n-1] - a2 y[n-2]
// (a first-order section has b2 = a2 = 0).
struct Biquad {
  double b0 = 1, b1 = 0, b2 = 0, a1 = 0, a2 = 0;
};

// Sections of the (one-way) filter for sampling frequency fs. InputError if
// the order is out of range or a cutoff is not strictly between 0 and fs/2
// (or f_low >= f_high for a band-pass).
std::vector<Biquad> butterworth_sections(const ButterworthSpec& spec, double fs);

// Runs the cascade once, forward, from zero initial state.
std::vector<double> filter_forward(const std::vector<Biquad>& sections, const std::vector<double>& x);

// Zero-phase (forward-backward) filtering of samples taken every dt seconds.
std::vector<double> zero_phase_filter(const std::vector<double>& x, double dt, const ButterworthSpec& spec);

// The exact gain |H(f)|^2 of the zero-phase filter (formula above).
double zero_phase_gain(const ButterworthSpec& spec, double f, double fs);

}  // namespace dda
