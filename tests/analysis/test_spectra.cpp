// Fourier spectra, Konno-Ohmachi smoothing and spectral ratios
// (docs/analytical.md, "Spectra"): the transform against the DFT's
// definition, a sine's amplitude and Parseval's theorem, the smoothing
// window's known shape, and ratios of signals related by a known linear
// filter.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "dda/analysis/fft.hpp"
#include "dda/analysis/fourier_spectrum.hpp"
#include "dda/analysis/konno_ohmachi.hpp"
#include "dda/analysis/response_spectrum.hpp"
#include "dda/analysis/sampling.hpp"
#include "dda/analysis/spectral_ratio.hpp"
#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"

using namespace dda::analysis;
using dda::kPi;

namespace {

std::vector<double> white_noise(std::size_t n, unsigned seed) {
  std::mt19937 gen(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> x(n);
  for (double& v : x) v = normal(gen);
  return x;
}

// X_k by its definition, the angle reduced exactly: 2 pi ((k n) mod N) / N.
Complex direct_dft(const std::vector<Complex>& x, std::size_t k) {
  const std::size_t n = x.size();
  Complex sum(0.0, 0.0);
  for (std::size_t j = 0; j < n; ++j)
    sum += x[j] * std::polar(1.0, -2.0 * kPi * static_cast<double>((k * j) % n) / static_cast<double>(n));
  return sum;
}

double max_abs(const std::vector<Complex>& x) {
  double m = 0.0;
  for (const Complex& v : x) m = std::max(m, std::abs(v));
  return m;
}

SpectrumOptions untapered() {
  SpectrumOptions o;
  o.taper = {TaperKind::none, 0.0};
  return o;
}

}  // namespace

// The transform equals the definition X_k = sum x_n exp(-2 pi i k n / N) to
// 1e-10 of the largest term, for powers of two (radix 2) and other lengths
// (Bluestein: odd, even, prime), and the inverse gives the signal back.
TEST(Fft, MatchesDirectDftForAnyLength) {
  for (const std::size_t n : {1u, 2u, 3u, 8u, 7u, 15u, 100u, 1000u, 1001u, 1024u, 4099u}) {
    const std::vector<double> re = white_noise(n, 11 + static_cast<unsigned>(n));
    const std::vector<double> im = white_noise(n, 23 + static_cast<unsigned>(n));
    std::vector<Complex> x(n);
    for (std::size_t j = 0; j < n; ++j) x[j] = Complex(re[j], im[j]);
    const std::vector<Complex> fast = fft(x);
    std::vector<Complex> slow(n);
    for (std::size_t k = 0; k < n; ++k) slow[k] = direct_dft(x, k);
    const double scale = max_abs(slow);
    double err = 0.0;
    for (std::size_t k = 0; k < n; ++k) err = std::max(err, std::abs(fast[k] - slow[k]));
    EXPECT_LE(err, 1e-10 * scale) << "N = " << n;
    const std::vector<Complex> back = fft(fast, true);
    double back_err = 0.0;
    for (std::size_t j = 0; j < n; ++j) back_err = std::max(back_err, std::abs(back[j] - x[j]));
    EXPECT_LE(back_err, 1e-12 * max_abs(x)) << "N = " << n;
  }
}

// A long prime length (the worst case for Bluestein's chirp, n^2 up to 1e10)
// against the definition at a few frequencies; real_fft keeps k = 0 .. N/2.
TEST(Fft, LongPrimeLengthAndRealInput) {
  const std::size_t n = 100003;  // prime
  const std::vector<double> x = white_noise(n, 5);
  const std::vector<Complex> fast = real_fft(x);
  ASSERT_EQ(fast.size(), n / 2 + 1);
  const std::vector<Complex> xc(x.begin(), x.end());
  for (const std::size_t k : {0u, 1u, 777u, 31415u, 50001u}) {
    const Complex slow = direct_dft(xc, k);
    EXPECT_LE(std::abs(fast[k] - slow), 1e-10 * std::sqrt(static_cast<double>(n)) * 10.0) << "k = " << k;
  }
}

// A sine of amplitude a with an integer number m of cycles over T = N dt
// falls on bin m: sum_n a sin(2 pi m n / N + phi) exp(-2 pi i m n / N) has
// modulus a N / 2 exactly (the other terms cancel over whole cycles), so
// fourier: dt a N / 2 = a T / 2; sine: a. Every other bin is zero.
TEST(FourierSpectrum, SineOnABin) {
  const double a = 1.7, dt = 0.01, phi = 0.4;
  const std::size_t n = 1000, m = 37;  // f0 = 37 / 10 s = 3.7 Hz
  std::vector<double> x(n);
  for (std::size_t j = 0; j < n; ++j) x[j] = a * std::sin(2.0 * kPi * static_cast<double>(m * j) / n + phi);
  const AmplitudeSpectrum s = amplitude_spectrum(x, dt, untapered());
  ASSERT_EQ(s.f.size(), n / 2 + 1);
  EXPECT_NEAR(s.df, 0.1, 1e-15);
  EXPECT_NEAR(s.f[m], 3.7, 1e-12);
  EXPECT_NEAR(s.f.back(), 0.5 / dt, 1e-12);  // Nyquist
  EXPECT_NEAR(s.amplitude[m], a * n * dt / 2.0, 1e-10 * a * n * dt);
  for (std::size_t k = 0; k < s.f.size(); ++k) {
    if (k == m) continue;
    EXPECT_LE(s.amplitude[k], 1e-10 * s.amplitude[m]) << "bin " << k;
  }
  const SpectralPeak peak = find_peak(s.f, s.amplitude);
  EXPECT_NEAR(peak.frequency, 3.7, 1e-12);

  SpectrumOptions sine = untapered();
  sine.scale = AmplitudeScale::sine;
  EXPECT_NEAR(amplitude_spectrum(x, dt, sine).amplitude[m], a, 1e-12);
  // With a taper the sine scale divides by the taper's sum (coherent gain):
  // a Tukey taper (10 %) leaves the sine's amplitude within 0.5 % (its
  // flanks' own leakage into the bin, measured 0.003 %), although the taper
  // removes 5 % of the record's weight.
  sine.taper = {TaperKind::tukey, 0.1};
  EXPECT_NEAR(amplitude_spectrum(x, dt, sine).amplitude[m], a, 0.005 * a);
}

// Parseval's theorem for the one-sided fourier scale:
// sum (x_n w_n)^2 dt = df [A_0^2 + 2 sum A_k^2 + A_{N/2}^2 (even N)], on the
// prepared signal (mean removed, tapered), even and odd N, with and without
// taper and detrending.
TEST(FourierSpectrum, Parseval) {
  for (const std::size_t n : {1024u, 1023u, 999u}) {
    for (const bool taper : {false, true}) {
      SpectrumOptions o = untapered();
      if (taper) o.taper = {TaperKind::tukey, 0.2};
      o.detrend = taper;
      std::vector<double> x = white_noise(n, 3);
      for (std::size_t j = 0; j < n; ++j) x[j] += 2.0 + 0.01 * static_cast<double>(j);  // an offset and a trend
      const double dt = 0.004;
      const std::vector<double> y = prepare_signal(x, o);
      double energy = 0.0;
      for (double v : y) energy += v * v * dt;
      const AmplitudeSpectrum s = amplitude_spectrum(x, dt, o);
      double sum = 0.0;
      for (std::size_t k = 0; k < s.f.size(); ++k) {
        const bool single = k == 0 || 2 * k == n;
        sum += (single ? 1.0 : 2.0) * s.amplitude[k] * s.amplitude[k];
      }
      EXPECT_NEAR(sum * s.df, energy, 1e-12 * energy) << "N = " << n << ", taper " << taper;
      if (!taper) {
        EXPECT_LE(s.amplitude[0], 1e-12 * dt * static_cast<double>(n));  // the mean is gone
      }
    }
  }
}

// Detrending removes a straight line exactly; the taper has the stated shape.
TEST(FourierSpectrum, DetrendAndTaper) {
  SpectrumOptions o = untapered();
  o.detrend = true;
  std::vector<double> line(50);
  for (std::size_t j = 0; j < line.size(); ++j) line[j] = 3.0 - 0.7 * static_cast<double>(j);
  for (double v : prepare_signal(line, o)) EXPECT_NEAR(v, 0.0, 1e-12);
  const std::vector<double> hann = taper_window(101, parse_taper("hann", "--taper"));
  EXPECT_DOUBLE_EQ(hann.front(), 0.0);
  EXPECT_NEAR(hann[50], 1.0, 1e-15);
  EXPECT_NEAR(hann[25], 0.5, 1e-15);  // (1 - cos(pi/2)) / 2
  // Tukey 0.2 over 101 samples: flanks of 0.1 * 100 = 10 samples each side.
  const std::vector<double> tukey = taper_window(101, parse_taper("tukey:0.2", "--taper"));
  EXPECT_NEAR(tukey[5], 0.5, 1e-15);
  EXPECT_DOUBLE_EQ(tukey[10], 1.0);
  EXPECT_DOUBLE_EQ(tukey[90], 1.0);
  EXPECT_NEAR(tukey[95], 0.5, 1e-15);
  EXPECT_EQ(taper_name(parse_taper("tukey:0.05", "--taper")), "tukey:0.05");
  EXPECT_THROW(parse_taper("tukey:2", "--taper"), dda::InputError);
  EXPECT_THROW(parse_taper("cosine", "--taper"), dda::InputError);
}

// A flat spectrum stays flat: the window is normalised at every centre, so
// the weighted mean of a constant is the constant, here to round-off at
// every centre, the ends included.
TEST(KonnoOhmachi, FlatStaysFlat) {
  std::vector<double> f(20001), a(20001, 2.5);
  for (std::size_t k = 0; k < f.size(); ++k) f[k] = 0.005 * static_cast<double>(k);
  for (const double b : {10.0, 40.0, 100.0}) {
    const std::vector<double> centres = log_spaced(0.005, 100.0, 400);
    const std::vector<double> s = konno_ohmachi(f, a, centres, b);
    for (std::size_t c = 0; c < s.size(); ++c) EXPECT_NEAR(s[c], 2.5, 1e-12) << "b " << b << ", fc " << centres[c];
  }
}

// A spike of unit height at f_s on a grid of step df: S(fc) = W(f_s, fc) /
// sum_k W(f_k, fc). The sum is (1/df) times the window's integral,
// fc ln10 / b * int sinc^4(x) 10^(x/b) dx = fc ln10 / b * (2 pi / 3)
// (1 + 0.0012 for b = 40: the second-order term of 10^(x/b), using
// int x^2 sinc^4 = pi / 2), so
//   S(fc) = 3 b df / (2 pi ln10 fc) sinc^4(b log10(f_s / fc))
// within 0.2 %; the smoothed spike vanishes where f_s sits on the window's
// first zeros, fc = f_s 10^(-+pi/b), and beyond the ten lobes the window
// keeps.
TEST(KonnoOhmachi, SpikeSpreadsWithTheWindowWidth) {
  const double df = 0.01, fs = 10.0, b = 40.0;
  std::vector<double> f(5001), a(5001, 0.0);
  for (std::size_t k = 0; k < f.size(); ++k) f[k] = df * static_cast<double>(k);
  a[1000] = 1.0;  // 10 Hz
  const auto expected = [&](double x) {
    const double fc = fs * std::pow(10.0, -x / b);  // b log10(fs / fc) = x
    const double sinc = x == 0.0 ? 1.0 : std::sin(x) / x;
    return 3.0 * b * df / (2.0 * kPi * std::log(10.0) * fc) * std::pow(sinc, 4);
  };
  const double peak = expected(0.0);
  for (const double x : {-2.0, -1.0019, -0.5, 0.0, 0.5, 1.0019, 2.0}) {
    const double fc = fs * std::pow(10.0, -x / b);
    const double s = konno_ohmachi(f, a, {fc}, b)[0];
    EXPECT_NEAR(s, expected(x), 0.002 * peak) << "x = " << x;
  }
  // Half height (sinc^4 = 1/2 at x = 1.0019), up to the 1/fc of the normaliser.
  const double fc_half = fs * std::pow(10.0, -1.0019 / b);
  EXPECT_NEAR(konno_ohmachi(f, a, {fc_half}, b)[0] * fc_half / (peak * fs), 0.5, 0.002);
  for (const double x : {-kPi, kPi})
    EXPECT_LE(std::abs(konno_ohmachi(f, a, {fs * std::pow(10.0, -x / b)}, b)[0]), 1e-12 * peak) << "zero at " << x;
  EXPECT_EQ(konno_ohmachi(f, a, {fs * std::pow(10.0, -10.5 * kPi / b)}, b)[0], 0.0);  // outside the ten lobes
  EXPECT_DOUBLE_EQ(konno_ohmachi_window(fs, fs, b), 1.0);
  EXPECT_NEAR(konno_ohmachi_window(fs * std::pow(10.0, 1.0019 / b), fs, b), 0.5, 1e-4);
}

// The reported spectrum: unsmoothed on the transform's own frequencies
// inside [fmin, fmax]; smoothed on log-spaced centres; an empty range is an
// input error.
TEST(SpectralRatio, ReportedRange) {
  const std::vector<double> x = white_noise(1000, 9);
  const AmplitudeSpectrum s = amplitude_spectrum(x, 0.01, SpectrumOptions{});  // df 0.1 Hz, Nyquist 50 Hz
  SpectrumGrid raw;
  raw.smoothing = 0.0;
  raw.fmin = 1.0;
  raw.fmax = 2.0;
  const SampledSpectrum r = report_spectrum(s, raw);
  ASSERT_EQ(r.f.size(), 11u);
  EXPECT_NEAR(r.f.front(), 1.0, 1e-12);
  EXPECT_NEAR(r.f.back(), 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(r.amplitude[0], s.amplitude[10]);
  SpectrumGrid smooth;
  smooth.points = 50;
  const SampledSpectrum sm = report_spectrum(s, smooth);
  ASSERT_EQ(sm.f.size(), 50u);
  EXPECT_DOUBLE_EQ(sm.f.front(), 0.1);
  EXPECT_DOUBLE_EQ(sm.f.back(), 50.0);
  raw.fmin = 60.0;
  raw.fmax = 70.0;
  EXPECT_THROW(report_spectrum(s, raw), dda::InputError);
}

// A signal against itself times 3: the ratio of the smoothed spectra is 3
// at every frequency (the smoothing is linear); H/V of h = 3 v is 3, and
// with two horizontals 3 v and 4 v the quadratic mean gives
// sqrt((9 + 16) / 2) = 3.5355.
TEST(SpectralRatio, ScaledCopiesAndHv) {
  const std::vector<double> v = white_noise(4096, 17);
  std::vector<double> h1(v), h2(v);
  for (double& x : h1) x *= 3.0;
  for (double& x : h2) x *= 4.0;
  const double dt = 0.01;
  SpectrumGrid grid;
  grid.fmin = 0.2;
  grid.fmax = 40.0;
  const SampledSpectrum sv = report_spectrum(amplitude_spectrum(v, dt, {}), grid);
  const SampledSpectrum s1 = report_spectrum(amplitude_spectrum(h1, dt, {}), grid);
  const SampledSpectrum s2 = report_spectrum(amplitude_spectrum(h2, dt, {}), grid);
  for (const double r : spectral_ratio(s1.amplitude, sv.amplitude)) EXPECT_NEAR(r, 3.0, 1e-12);
  for (const double r : spectral_ratio(quadratic_mean(s1.amplitude, s2.amplitude), sv.amplitude))
    EXPECT_NEAR(r, std::sqrt(12.5), 1e-12);
  EXPECT_TRUE(std::isnan(spectral_ratio({1.0}, {0.0})[0]));
}

// Classical spectral ratio against a known linear filter: the absolute
// acceleration of a damped oscillator (T0 = 0.5 s, zeta = 0.2) on a base
// shaken by white noise, over the base motion. Its transfer function is
//   H(f) = (w0^2 + 2 i zeta w0 w) / (w0^2 - w^2 + 2 i zeta w0 w),
// and with the record linear between samples (the oscillator's exact step,
// response_spectrum.hpp) the sampled output sees
//   G(f) = sum_m H(f + m/dt) sinc^2(pi (f dt + m))
// (linear interpolation, then sampling: the m != 0 aliases reach 1.4 % of
// G at 20 Hz). The Konno-Ohmachi ratio (b = 40) follows |G| over
// 0.2 .. 20 Hz within 3 %: measured 2.3 % at most, at and beside the
// resonance, where the window (standard deviation 0.022 in log10 f, i.e.
// +-5 % in f) averages the peak's curvature (|H| falls by about
// (f/f0 - 1)^2 / (2 zeta^2) = 3 % at +-5 %). Against |G| smoothed by the same
// window (weighted by the base's spectrum, which is what the ratio of
// smoothed spectra is when the top's transform is exactly G X) it agrees
// within 0.5 % (measured 0.09 %: the record's ends, where the oscillator
// starts at rest and is cut off).
TEST(SpectralRatio, RecoversAnOscillatorTransferFunction) {
  const double dt = 0.01, t0 = 0.5, zeta = 0.2;
  const std::vector<double> base = white_noise(1 << 15, 29);  // 328 s
  const OscillatorHistory top = oscillator_response(base, dt, t0, zeta);
  SpectrumGrid grid;
  grid.fmin = 0.2;
  grid.fmax = 20.0;
  grid.points = 200;
  const SampledSpectrum sb = report_spectrum(amplitude_spectrum(base, dt, {}), grid);
  const SampledSpectrum st = report_spectrum(amplitude_spectrum(top.absolute_acceleration, dt, {}), grid);
  const std::vector<double> ratio = spectral_ratio(st.amplitude, sb.amplitude);
  const double w0 = 2.0 * kPi / t0;
  const auto h = [&](double f) {
    const double w = 2.0 * kPi * f;
    return Complex(w0 * w0, 2.0 * zeta * w0 * w) / Complex(w0 * w0 - w * w, 2.0 * zeta * w0 * w);
  };
  const auto g = [&](double f) {  // sum over the aliases f + m / dt of H sinc^2
    Complex sum(0.0, 0.0);
    for (int m = -20; m <= 20; ++m) {
      const double x = kPi * (f * dt + m);
      sum += h(f + m / dt) * std::pow(std::sin(x) / x, 2);
    }
    return std::abs(sum);
  };
  // The same window applied to |G| weighted by the base's own spectrum: what
  // the ratio of smoothed spectra is if the top's spectrum is exactly G X.
  const AmplitudeSpectrum raw = amplitude_spectrum(base, dt, {});
  std::vector<double> weighted(raw.f.size());
  for (std::size_t k = 0; k < raw.f.size(); ++k) weighted[k] = raw.amplitude[k] * g(raw.f[k]);
  const std::vector<double> smoothed_g =
      spectral_ratio(konno_ohmachi(raw.f, weighted, sb.f), konno_ohmachi(raw.f, raw.amplitude, sb.f));
  double worst = 0.0, worst_smoothed = 0.0;
  for (std::size_t i = 0; i < ratio.size(); ++i) {
    const double expected = g(sb.f[i]);
    worst = std::max(worst, std::abs(ratio[i] / expected - 1.0));
    worst_smoothed = std::max(worst_smoothed, std::abs(ratio[i] / smoothed_g[i] - 1.0));
    EXPECT_NEAR(ratio[i], expected, 0.03 * expected) << "f = " << sb.f[i];
    EXPECT_NEAR(ratio[i], smoothed_g[i], 0.005 * smoothed_g[i]) << "f = " << sb.f[i];
  }
  std::cout << "oscillator transfer function: worst relative error " << worst << " against |G|, "
            << worst_smoothed << " against the smoothed |G|\n";
  // The ratio peaks at the maximum of |H|, f = sqrt(sqrt(1 + 8 zeta^2) - 1) / (2 zeta T0) = 1.929 Hz,
  // within the grid's spacing (2.3 %).
  const SpectralPeak p = find_peak(sb.f, ratio);
  const double f_peak = std::sqrt(std::sqrt(1.0 + 8.0 * zeta * zeta) - 1.0) / (2.0 * zeta) / t0;
  EXPECT_NEAR(p.frequency, f_peak, 0.03 * f_peak);
}

// Resampling and differentiation for the DDA histories.
TEST(Sampling, ResampleAndDifferentiate) {
  const std::vector<double> t = {0.0, 0.1, 0.15, 0.3, 0.4};
  std::vector<double> x;
  for (double s : t) x.push_back(2.0 + 3.0 * s);  // a line is resampled exactly
  EXPECT_FALSE(is_uniform(t));
  EXPECT_NEAR(median_step(t), 0.1, 1e-15);  // steps 0.1, 0.05, 0.15, 0.1
  const UniformSeries u = resample_uniform(t, x, 0.05);
  ASSERT_EQ(u.x.size(), 9u);
  for (std::size_t i = 0; i < u.x.size(); ++i) EXPECT_NEAR(u.x[i], 2.0 + 3.0 * 0.05 * static_cast<double>(i), 1e-12);
  // Central differences are exact for a parabola inside and (second order) at the ends.
  std::vector<double> p;
  for (int i = 0; i < 6; ++i) p.push_back(0.5 * 0.1 * i * 0.1 * i);  // d/dt = t
  const std::vector<double> d = central_difference(p, 0.1);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(d[static_cast<std::size_t>(i)], 0.1 * i, 1e-12);
}
