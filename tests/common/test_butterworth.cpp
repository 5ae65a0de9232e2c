// Zero-phase Butterworth filters: gain 1/2 at the cutoff (= (1/sqrt 2)^2 of
// the forward-backward pass), flat passband, stopband attenuation of the
// order, no phase shift. Expected numbers from the closed form in
// butterworth.hpp: |H|^2 = 1 / (1 + (tan(pi f/fs) / tan(pi fc/fs))^(2N)).
#include "dda/common/butterworth.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dda/common/error.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;

// Amplitude and phase of the response to a sinusoid of frequency f, measured
// by projecting the middle half of the output on sin and cos.
struct Response {
  double gain = 0, phase = 0;
};
Response measure(const dda::ButterworthSpec& spec, double f, double fs, double seconds) {
  const std::size_t n = static_cast<std::size_t>(seconds * fs);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = std::sin(2 * kPi * f * static_cast<double>(i) / fs);
  const std::vector<double> y = dda::zero_phase_filter(x, 1.0 / fs, spec);
  double s = 0, c = 0, norm = 0;
  // Whole periods in the middle half.
  const std::size_t per = static_cast<std::size_t>(std::llround(fs / f));
  const std::size_t i0 = n / 4, i1 = i0 + ((n / 2) / per) * per;
  for (std::size_t i = i0; i < i1; ++i) {
    const double t = 2 * kPi * f * static_cast<double>(i) / fs;
    s += y[i] * std::sin(t);
    c += y[i] * std::cos(t);
    norm += std::sin(t) * std::sin(t);
  }
  return {std::hypot(s, c) / norm, std::atan2(c, s)};
}

}  // namespace

TEST(Butterworth, LowPassGainAndPhase) {
  const double fs = 200.0;
  for (int order : {1, 2, 4, 5}) {
    dda::ButterworthSpec spec{dda::FilterKind::lowpass, order, 0.0, 2.5};
    const Response at_cut = measure(spec, 2.5, fs, 40);
    EXPECT_NEAR(at_cut.gain, 0.5, 0.005) << "order " << order;
    EXPECT_NEAR(at_cut.phase, 0.0, 1e-3) << "order " << order;
    // Passband, a decade below: 1 / (1 + 0.1^(2N)) (0.990 for N = 1).
    const Response pass = measure(spec, 0.25, fs, 80);
    EXPECT_NEAR(pass.gain, dda::zero_phase_gain(spec, 0.25, fs), 0.001) << "order " << order;
    if (order >= 2) {
      EXPECT_NEAR(pass.gain, 1.0, 0.001) << "order " << order;
    }
    EXPECT_NEAR(pass.phase, 0.0, 1e-3);
    // Stopband: one decade above the cutoff the gain is about 10^(-2N).
    const Response stop = measure(spec, 25.0, fs, 20);
    const double expected = dda::zero_phase_gain(spec, 25.0, fs);
    EXPECT_NEAR(stop.gain, expected, 0.02 * expected + 1e-9) << "order " << order;
    EXPECT_NEAR(std::log10(expected), -2.0 * order, 0.15 * order);
  }
}

TEST(Butterworth, HighAndBandPass) {
  const double fs = 100.0;
  dda::ButterworthSpec hp{dda::FilterKind::highpass, 4, 1.0, 0.0};
  EXPECT_NEAR(measure(hp, 1.0, fs, 100).gain, 0.5, 0.005);
  EXPECT_NEAR(measure(hp, 10.0, fs, 20).gain, 1.0, 0.005);
  EXPECT_NEAR(measure(hp, 0.25, fs, 200).gain, dda::zero_phase_gain(hp, 0.25, fs), 1e-4);
  EXPECT_NEAR(measure(hp, 10.0, fs, 20).phase, 0.0, 1e-3);
  dda::ButterworthSpec bp{dda::FilterKind::bandpass, 4, 0.5, 10.0};
  EXPECT_NEAR(measure(bp, 2.24, fs, 100).gain, 1.0, 0.005);  // geometric middle of the band
  EXPECT_NEAR(measure(bp, 10.0, fs, 40).gain, dda::zero_phase_gain(bp, 10.0, fs), 0.005);
  EXPECT_NEAR(dda::zero_phase_gain(bp, 10.0, fs), 0.5, 0.01);
}

TEST(Butterworth, ZeroPhaseKeepsPeakTime) {
  // A smooth pulse well inside the passband keeps its peak where it was.
  const double fs = 100.0;
  std::vector<double> x(2000);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double t = static_cast<double>(i) / fs - 10.0;
    x[i] = std::exp(-t * t / (2 * 0.5 * 0.5));
  }
  const auto y = dda::zero_phase_filter(x, 1.0 / fs, {dda::FilterKind::lowpass, 4, 0.0, 5.0});
  const auto peak = std::max_element(y.begin(), y.end()) - y.begin();
  EXPECT_EQ(peak, 1000);
  EXPECT_NEAR(y[1000], 1.0, 1e-3);
}

TEST(Butterworth, BadSpecs) {
  EXPECT_THROW(dda::butterworth_sections({dda::FilterKind::lowpass, 4, 0, 60}, 100), dda::InputError);
  EXPECT_THROW(dda::butterworth_sections({dda::FilterKind::lowpass, 0, 0, 2}, 100), dda::InputError);
  EXPECT_THROW(dda::butterworth_sections({dda::FilterKind::bandpass, 4, 5, 2}, 100), dda::InputError);
  EXPECT_THROW(dda::parse_filter_kind("notch", "--filter"), dda::InputError);
}
