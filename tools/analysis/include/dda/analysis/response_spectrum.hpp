#pragma once
// Response spectra of an acceleration record (docs/analytical.md, "Spectra").
//
// A linear oscillator of natural period T (omega = 2 pi / T) and damping
// ratio zeta on a base moving with the record a_g(t):
//   u'' + 2 zeta omega u' + omega^2 u = -a_g(t),
// u the displacement relative to the base, at rest at the first sample.
// Spectral values over the record's duration (no free-vibration tail):
//   SD  = max |u|           PSV = omega SD       PSA = omega^2 SD
//   SV  = max |u'|          SA  = max |u'' + a_g| = max |2 zeta omega u' + omega^2 u|
// (SA is the absolute acceleration; PSA = SA when zeta = 0). T = 0 is the
// rigid oscillator: SD = SV = PSV = 0, PSA = SA = PGA = max |a_g|.
//
// Method (Nigam & Jennings 1969, BSSA 59(2), 909-922): a_g is linear between
// samples (the record's own definition), and the step solution is exact,
//   [u, u']_{i+1} = A [u, u']_i + B [a_i, a_{i+1}],
// A and B depending on omega, zeta and the step only. We evaluate the same
// exact step as the exponential of the augmented system matrix, state
// (omega u, u', a_g, a_g') with a_g' constant over the step (scaling and
// squaring of a Taylor series, to round-off), rather than from Nigam and
// Jennings's closed-form coefficients: those subtract terms of order
// a / (omega^3 dt) to obtain a change of order a dt^2 and lose about
// (omega dt)^-3 in relative accuracy (ten digits at T = 10 s with dt = 1 ms).
//
// Peaks fall between samples: each step is split into ceil(50 dt / T) equal
// sub-steps (still exact for the linear segment), at most 200, so a peak is
// sampled at 50 points a period or more and read within 1 - cos(pi/50) =
// 0.2 %. Below T = dt / 4 the cap applies; the oscillator there all but
// follows the ground (omega^2 u = -a_g) and PSA tends to the PGA.
#include <vector>

namespace dda::analysis {

constexpr double kResponseDamping = 0.05;

struct ResponseSpectrum {
  std::vector<double> period;               // s
  std::vector<double> sd, sv, psv, psa, sa; // units of a times s^2, s, s, 1, 1
  double damping = kResponseDamping;
  double pga = 0.0;                          // max |a_g|
};

// a: the record at t0 + i dt (uniform step dt > 0, two samples or more);
// periods >= 0; 0 <= damping < 1 (InputError otherwise).
ResponseSpectrum response_spectrum(const std::vector<double>& a, double dt, const std::vector<double>& periods,
                                   double damping = kResponseDamping);

// The oscillator's history at the record's samples: u, u' and the absolute
// acceleration u'' + a_g (period > 0).
struct OscillatorHistory {
  std::vector<double> u, v, absolute_acceleration;
};
OscillatorHistory oscillator_response(const std::vector<double>& a, double dt, double period,
                                      double damping = kResponseDamping);

}  // namespace dda::analysis
