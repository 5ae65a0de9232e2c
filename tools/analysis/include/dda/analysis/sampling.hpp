#pragma once
// Uniform sampling of histories for the spectra tools: a DDA run records its
// measurement points once per step, and with an adaptive step the times are
// not evenly spaced; a Fourier transform or a response-spectrum recursion
// needs them evenly spaced.
#include <string>
#include <vector>

namespace dda::analysis {

// A history sampled at t0, t0 + dt, ... (x.size() samples).
struct UniformSeries {
  double t0 = 0.0;
  double dt = 0.0;
  std::vector<double> x;
};

// Median of the steps t[i+1] - t[i] (t increasing, at least two samples):
// the default resampling step, robust to a few short steps (cut steps,
// output times) that a mean or minimum would follow.
double median_step(const std::vector<double>& t);

// True when every step equals (t.back() - t.front()) / (n - 1) to 1e-6
// relative (the test dda record uses for its filters).
bool is_uniform(const std::vector<double>& t);

// Linear interpolation at t0 + i dt, i = 0 .. floor((t.back() - t0) / dt),
// t0 = t.front(). `t` strictly increasing, dt > 0.
UniformSeries resample_uniform(const std::vector<double>& t, const std::vector<double>& x, double dt);

// Derivative by central differences, (x[i+1] - x[i-1]) / (2 dt), and the
// second-order one-sided formulas (-3 x0 + 4 x1 - x2) / (2 dt) at the ends
// (first-order with two samples). A central difference multiplies a
// sinusoid of frequency f by sin(2 pi f dt) / (2 pi f dt) relative to the
// exact derivative (0.90 at a tenth of the sampling rate, 0.64 at half the
// Nyquist frequency).
std::vector<double> central_difference(const std::vector<double>& x, double dt);

}  // namespace dda::analysis
