// Response spectra by the exact step of a piecewise-linear record (response_spectrum.hpp).
#include "dda/analysis/response_spectrum.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"

namespace dda::analysis {

namespace {

constexpr int kStepsPerPeriod = 50;
constexpr int kMaxSubsteps = 200;

void check_input(const std::vector<double>& a, double dt, double damping) {
  if (a.size() < 2 || !(dt > 0.0) || !std::isfinite(dt))
    throw InputError("A response spectrum needs two samples or more at a positive step.");
  if (!(damping >= 0.0 && damping < 1.0)) {
    std::ostringstream m;
    m << "The damping ratio " << damping << " is outside [0, 1).";
    throw InputError(m.str());
  }
}

// exp(M) of a 4x4 matrix: scaling to a norm below 1/2, Taylor series to
// round-off, squaring back.
Eigen::Matrix4d exponential(const Eigen::Matrix4d& m) {
  const double norm = m.cwiseAbs().colwise().sum().maxCoeff();
  int squarings = 0;
  if (norm > 0.5) squarings = static_cast<int>(std::ceil(std::log2(norm / 0.5)));
  const Eigen::Matrix4d b = m / std::ldexp(1.0, squarings);
  Eigen::Matrix4d sum = Eigen::Matrix4d::Identity(), term = Eigen::Matrix4d::Identity();
  for (int k = 1; k <= 30; ++k) {
    term = (term * b) / static_cast<double>(k);
    sum += term;
    if (term.cwiseAbs().maxCoeff() < 1e-18 * sum.cwiseAbs().maxCoeff()) break;
  }
  for (int i = 0; i < squarings; ++i) sum = sum * sum;
  return sum;
}

// Steps the oscillator through the record, calling visit(omega u, u', at_sample)
// after every sub-step (at_sample: the sub-step ends on a record sample).
template <class Visit>
void march(const std::vector<double>& a, double dt, double period, double damping, Visit&& visit) {
  const double omega = 2.0 * kPi / period;
  const int sub = std::clamp(static_cast<int>(std::ceil(kStepsPerPeriod * dt / period - 1e-9)), 1, kMaxSubsteps);
  const double h = dt / sub;
  // State (omega u, u', a_g, a_g'); the first two rows of exp(M h) advance it.
  Eigen::Matrix4d m;
  m << 0.0, omega, 0.0, 0.0,                   //
      -omega, -2.0 * damping * omega, -1.0, 0.0,  //
      0.0, 0.0, 0.0, 1.0,                      //
      0.0, 0.0, 0.0, 0.0;
  const Eigen::Matrix4d e = exponential(m * h);
  double wu = 0.0, v = 0.0;
  for (std::size_t i = 0; i + 1 < a.size(); ++i) {
    const double slope = (a[i + 1] - a[i]) / dt;
    for (int j = 0; j < sub; ++j) {
      const double p = j == 0 ? a[i] : a[i] + slope * (h * j);
      const double wu1 = e(0, 0) * wu + e(0, 1) * v + e(0, 2) * p + e(0, 3) * slope;
      const double v1 = e(1, 0) * wu + e(1, 1) * v + e(1, 2) * p + e(1, 3) * slope;
      wu = wu1;
      v = v1;
      visit(wu, v, j + 1 == sub);
    }
  }
}

}  // namespace

ResponseSpectrum response_spectrum(const std::vector<double>& a, double dt, const std::vector<double>& periods,
                                   double damping) {
  check_input(a, dt, damping);
  ResponseSpectrum r;
  r.damping = damping;
  for (double x : a) r.pga = std::max(r.pga, std::abs(x));
  for (double period : periods) {
    if (!(period >= 0.0) || !std::isfinite(period)) {
      std::ostringstream m;
      m << "The period " << period << " s is not zero or positive.";
      throw InputError(m.str());
    }
    double sd = 0.0, sv = 0.0, sa = r.pga;
    double omega = 0.0;
    if (period > 0.0) {
      omega = 2.0 * kPi / period;
      sa = 0.0;  // at rest at the start: no spring or damper force
      const double c = 2.0 * damping * omega;
      march(a, dt, period, damping, [&](double wu, double v, bool) {
        sd = std::max(sd, std::abs(wu));
        sv = std::max(sv, std::abs(v));
        sa = std::max(sa, std::abs(c * v + omega * wu));
      });
      sd /= omega;
    }
    r.period.push_back(period);
    r.sd.push_back(sd);
    r.sv.push_back(sv);
    r.psv.push_back(omega * sd);
    r.psa.push_back(period > 0.0 ? omega * omega * sd : r.pga);
    r.sa.push_back(sa);
  }
  return r;
}

OscillatorHistory oscillator_response(const std::vector<double>& a, double dt, double period, double damping) {
  check_input(a, dt, damping);
  if (!(period > 0.0) || !std::isfinite(period)) throw InputError("The oscillator's period must be positive.");
  const double omega = 2.0 * kPi / period, c = 2.0 * damping * omega;
  OscillatorHistory h;
  h.u.push_back(0.0);
  h.v.push_back(0.0);
  h.absolute_acceleration.push_back(0.0);
  march(a, dt, period, damping, [&](double wu, double v, bool sample) {
    if (!sample) return;
    h.u.push_back(wu / omega);
    h.v.push_back(v);
    h.absolute_acceleration.push_back(-(c * v + omega * wu));
  });
  return h;
}

}  // namespace dda::analysis
