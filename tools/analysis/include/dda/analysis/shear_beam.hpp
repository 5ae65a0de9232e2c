#pragma once
// The sliding mass as a one-dimensional shear beam, in its first mode
// (Rathje and Bray 2000, JGGE 126(1), 2000, "Nonlinear coupled seismic sliding
// analysis of earth structures"; the decoupled and coupled options of
// SLAMMER, Jibson et al. 2013). docs/analytical.md, "Newmark analyses of
// records", gives the derivation.
//
// A uniform beam of height H, shear-wave speed Vs and density rho, fixed at
// its base (the slip surface) and free at its top; z is the depth from the
// top. Its first mode phi(z) = cos(pi z / (2 H)) (1 at the top, 0 at the
// base) has the period Ts = 4 H / Vs. With the displacement relative to the
// base u(z, t) = phi(z) q(t), per unit mass of the beam M = rho H:
//   L / M     = int phi dm / M       = 2 / pi   (kMassFraction)
//   Gamma     = int phi dm / int phi^2 dm = 4 / pi (kParticipation)
//   M_phi / M = int phi^2 dm / M     = 1 / 2
// and, with a_b(t) the absolute acceleration of the base,
//   q'' + 2 xi omega q' + omega^2 q = -Gamma a_b,     omega = 2 pi / Ts.
// The average absolute acceleration of the mass (the HEA history, whose peak
// is k_max g) is a_b + (L / M) q''.
//
// Equivalent-linear properties (optional): the hyperbolic modulus reduction
// G / Gmax = 1 / (1 + gamma / gamma_ref) (Hardin and Drnevich 1972) and the
// damping xi = xi_min + (xi_max - xi_min) (1 - G / Gmax), at the effective
// strain gamma = 0.65 max |gamma(base)|, gamma(base) = (pi / (2 H)) q: the
// fixed point of Ts = Ts0 / sqrt(G / Gmax) and xi, iterated on the response
// of the beam fixed to the ground (no sliding), as SLAMMER does.
#include <vector>

namespace dda::analysis {

constexpr double kMassFraction = 0.63661977236758134;  // 2 / pi
constexpr double kParticipation = 1.2732395447351627;  // 4 / pi

struct ShearBeam {
  double period = 0.0;    // Ts (s); 0: rigid
  double damping = 0.05;  // xi
};

struct EquivalentLinearCurve {
  double reference_strain = 0.0;  // gamma_ref (> 0 to use the curve)
  double damping_max = 0.25;      // xi_max; xi_min is the beam's small-strain damping
};

struct EquivalentLinearResult {
  ShearBeam beam;                 // the strain-compatible period and damping
  double modulus_ratio = 1.0;     // G / Gmax
  double effective_strain = 0.0;  // gamma (-)
  int iterations = 0;
  bool converged = false;
};

// height > 0 (m) sets the strain; small_strain.period > 0.
EquivalentLinearResult equivalent_linear(const std::vector<double>& a, double dt, const ShearBeam& small_strain,
                                         double height, const EquivalentLinearCurve& curve);

// The average acceleration of the mass (HEA) at the samples of the base
// acceleration a (m/s^2), the beam fixed to its base; a itself for Ts = 0.
std::vector<double> average_acceleration(const std::vector<double>& a, double dt, const ShearBeam& beam);

}  // namespace dda::analysis
