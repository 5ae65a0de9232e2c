#pragma once
// The wave tests' input, in 2D and 3D (wave_test_models.hpp,
// wave_test_models3d.hpp): a sine of `amplitude` and angular frequency
// `omega` for `cycles` cycles, ramped in and out over one cycle each with a
// Hann taper (sin^2), sampled 80 times a cycle, then rest. `emit(t, value)`
// takes each sample.
#include <cmath>
#include <numbers>

namespace dda::wave_test {

template <class Emit>
void tapered_sine_samples(double amplitude, double omega, int cycles, Emit&& emit) {
  const double period = 2 * std::numbers::pi / omega, total = cycles * period;
  const int n = 80 * cycles;
  for (int k = 0; k <= n; ++k) {
    const double t = total * k / n;
    double taper = 1;
    if (t < period) taper = std::pow(std::sin(0.5 * std::numbers::pi * t / period), 2);
    if (t > total - period) taper = std::pow(std::sin(0.5 * std::numbers::pi * (total - t) / period), 2);
    emit(t, amplitude * taper * std::sin(omega * t));
  }
}

}  // namespace dda::wave_test
