// Record intensity measures against closed forms (docs/analytical.md,
// "Record intensity measures").
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dda/analysis/intensity_measures.hpp"
#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"

using namespace dda::analysis;
using dda::kPi;

namespace {
constexpr double kG = 9.81;

std::vector<double> sine(double amplitude, double freq, double dt, std::size_t n) {
  std::vector<double> a(n);
  for (std::size_t i = 0; i < n; ++i) a[i] = amplitude * std::sin(2.0 * kPi * freq * static_cast<double>(i) * dt);
  return a;
}
}  // namespace

// A constant acceleration c over T = (n - 1) dt: v = c t and d = c t^2 / 2 are
// integrated exactly by the trapezoidal rule (v is linear), so PGV = c T and
// PGD = c T^2 / 2; a^2 is constant, so the Husid plot is t / T and
// D5-95 = 0.9 T, t5 = 0.05 T; Ia = pi / (2 g) c^2 T.
TEST(IntensityMeasures, ConstantAcceleration) {
  const double c = 0.5, dt = 0.01;
  const std::vector<double> a(1001, c);  // T = 10 s
  const IntensityMeasures m = intensity_measures(a, dt);
  EXPECT_DOUBLE_EQ(m.pga, 0.5);
  EXPECT_NEAR(m.pgv, 5.0, 1e-12);
  EXPECT_NEAR(m.pgd, 25.0, 1e-10);
  EXPECT_NEAR(m.arias, kPi / (2.0 * kG) * 0.25 * 10.0, 1e-13);
  EXPECT_NEAR(m.t5, 0.5, 1e-10);
  EXPECT_NEAR(m.t95, 9.5, 1e-10);
  EXPECT_NEAR(m.significant_duration, 9.0, 1e-10);
  const std::vector<double> h = husid(a, dt);
  EXPECT_NEAR(h[500], 0.5, 1e-13);
  EXPECT_DOUBLE_EQ(h.back(), 1.0);
}

// A triangle 0, 2, 0 m/s^2 at dt = 1 s is linear between the samples, so
// int a^2 dt = 2 int_0^1 (2 t)^2 dt = 8/3 exactly and Ia = pi / (2 g) 8/3.
// Its Husid plot at t = 1 s is 1/2 (symmetry); on the rise H(t) = (4 t^3 / 3)
// / (8 / 3) = t^3 / 2, so H = 0.05 at t5 = 0.1^(1/3) = 0.4641589 s, and by
// symmetry t95 = 2 - t5, D5-95 = 2 - 2 (0.4641589) = 1.0716822 s.
TEST(IntensityMeasures, TriangleIsExact) {
  const std::vector<double> a{0.0, 2.0, 0.0};
  const IntensityMeasures m = intensity_measures(a, 1.0);
  EXPECT_NEAR(m.arias, kPi / (2.0 * kG) * 8.0 / 3.0, 1e-15);
  EXPECT_NEAR(husid(a, 1.0)[1], 0.5, 1e-15);
  EXPECT_NEAR(m.t5, std::cbrt(0.1), 1e-12);
  EXPECT_NEAR(m.t95, 2.0 - std::cbrt(0.1), 1e-12);
  EXPECT_NEAR(m.significant_duration, 1.0716822, 1e-7);
}

// A sine A sin(2 pi f t) over whole cycles: int a^2 dt = A^2 T / 2, so
// Ia = pi A^2 T / (4 g). Between samples the record is linear: a step from
// a0 to a1 holds dt (a0^2 + a0 a1 + a1^2) / 3, which over whole cycles sums
// to A^2 T / 2 times (2 + cos th) / 3, th = 2 pi f dt (a factor 1 - 2.6e-5 here).
// PGV: the velocity A / (2 pi f) (1 - cos) from rest peaks at 2 A / (2 pi f)
// after each half cycle; the trapezoidal rule over a half cycle of sine gives
// it times (th / 2) / tan(th / 2) (a factor 1 - 1.3e-5).
TEST(IntensityMeasures, SineAriasAndPeaks) {
  const double A = 0.3 * kG, f = 2.0, dt = 0.001;
  const std::vector<double> a = sine(A, f, dt, 10001);  // 10 s, 20 cycles
  const IntensityMeasures m = intensity_measures(a, dt);
  const double th = 2.0 * kPi * f * dt;
  EXPECT_NEAR(m.arias, kPi * A * A * 10.0 / (4.0 * kG) * (2.0 + std::cos(th)) / 3.0, 1e-11 * m.arias);
  EXPECT_NEAR(m.pga, A, 1e-12 * A);
  EXPECT_NEAR(m.pgv, 2.0 * A / (2.0 * kPi * f) * (0.5 * th) / std::tan(0.5 * th), 1e-11 * m.pgv);
  // The energy is spread evenly: D5-95 = 0.9 T within a quarter cycle.
  EXPECT_NEAR(m.significant_duration, 9.0, 0.125);
}

// Mean period: a sine with whole cycles in the record falls on one DFT bin,
// so Tm = 1 / f. Two sines of amplitudes 1 and 0.5 at 1 and 4 Hz give
// Tm = (1 / 1 + 0.25 / 4) / (1 + 0.25) = 0.85 s; a third at 30 Hz lies
// outside 0.25..20 Hz and changes nothing.
TEST(IntensityMeasures, MeanPeriod) {
  const double dt = 0.005;
  const std::size_t n = 2000;  // 10 s: whole cycles of 1, 2, 4 and 30 Hz
  EXPECT_NEAR(mean_period(sine(1.0, 2.0, dt, n), dt), 0.5, 1e-12);
  std::vector<double> a = sine(1.0, 1.0, dt, n);
  const std::vector<double> b = sine(0.5, 4.0, dt, n), c = sine(0.3, 30.0, dt, n);
  for (std::size_t i = 0; i < n; ++i) a[i] += b[i] + c[i];
  EXPECT_NEAR(mean_period(a, dt), 0.85, 1e-12);
}

// Predominant period: a long sine at the period of a grid point resonates the
// 5 %-damped oscillator of that period most (the peak of PSA for a harmonic
// input lies within xi^2 = 0.25 % of the forcing period, well inside the
// 5.7 % grid spacing).
TEST(IntensityMeasures, PredominantPeriod) {
  const std::vector<double> periods = predominant_periods();
  ASSERT_EQ(periods.size(), 80u);
  EXPECT_NEAR(periods.front(), 0.05, 1e-15);
  EXPECT_NEAR(periods.back(), 4.0, 1e-12);
  const double T = periods[40], dt = 0.005;
  const std::vector<double> a = sine(1.0, 1.0 / T, dt, static_cast<std::size_t>(60.0 * T / dt));
  EXPECT_DOUBLE_EQ(intensity_measures(a, dt).predominant_period, T);
}

TEST(IntensityMeasures, RejectsTooShortRecords) {
  EXPECT_THROW(intensity_measures({1.0}, 0.01), dda::InputError);
  EXPECT_THROW(intensity_measures({1.0, 2.0}, 0.0), dda::InputError);
}
