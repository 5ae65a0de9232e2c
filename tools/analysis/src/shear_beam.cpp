// First-mode shear beam: its average acceleration and equivalent-linear
// properties (shear_beam.hpp).
#include "dda/analysis/shear_beam.hpp"

#include <algorithm>
#include <cmath>

#include "dda/analysis/response_spectrum.hpp"
#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"

namespace dda::analysis {

namespace {

void check_beam(const ShearBeam& beam) {
  if (!(beam.period >= 0.0) || !std::isfinite(beam.period))
    throw InputError("Shear beam: the period Ts must be zero or positive.");
  if (!(beam.damping >= 0.0 && beam.damping < 1.0)) throw InputError("Shear beam: the damping ratio must lie in 0..1.");
}

}  // namespace

std::vector<double> average_acceleration(const std::vector<double>& a, double dt, const ShearBeam& beam) {
  check_beam(beam);
  if (beam.period == 0.0) return a;
  // The oscillator u'' + 2 xi omega u' + omega^2 u = -a gives q = Gamma u and
  // q'' = Gamma (u'' + a - a) = Gamma (absolute - a).
  const OscillatorHistory h = oscillator_response(a, dt, beam.period, beam.damping);
  std::vector<double> hea(a.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    hea[i] = a[i] + kMassFraction * kParticipation * (h.absolute_acceleration[i] - a[i]);
  return hea;
}

EquivalentLinearResult equivalent_linear(const std::vector<double>& a, double dt, const ShearBeam& small_strain,
                                         double height, const EquivalentLinearCurve& curve) {
  check_beam(small_strain);
  if (!(small_strain.period > 0.0)) throw InputError("Equivalent-linear: the period Ts must be positive.");
  if (!(height > 0.0) || !std::isfinite(height)) throw InputError("Equivalent-linear: the height must be positive.");
  if (!(curve.reference_strain > 0.0)) throw InputError("Equivalent-linear: the reference strain must be positive.");
  if (!(curve.damping_max >= small_strain.damping && curve.damping_max < 1.0))
    throw InputError("Equivalent-linear: the largest damping must lie between the small-strain damping and 1.");
  EquivalentLinearResult r;
  r.beam = small_strain;
  constexpr int kMaxIterations = 50;
  constexpr double kTolerance = 1e-4;  // on G / Gmax
  for (r.iterations = 1; r.iterations <= kMaxIterations; ++r.iterations) {
    const OscillatorHistory h = oscillator_response(a, dt, r.beam.period, r.beam.damping);
    double umax = 0.0;
    for (double u : h.u) umax = std::max(umax, std::abs(u));
    // gamma(base) = (pi / (2 H)) q, q = Gamma u = (4 / pi) u: 2 u / H.
    r.effective_strain = 0.65 * 2.0 * umax / height;
    const double ratio = 1.0 / (1.0 + r.effective_strain / curve.reference_strain);
    const double change = std::abs(ratio - r.modulus_ratio);
    r.modulus_ratio = ratio;
    r.beam.period = small_strain.period / std::sqrt(ratio);
    r.beam.damping = small_strain.damping + (curve.damping_max - small_strain.damping) * (1.0 - ratio);
    if (change < kTolerance) {
      r.converged = true;
      break;
    }
  }
  r.iterations = std::min(r.iterations, kMaxIterations);
  return r;
}

}  // namespace dda::analysis
