#pragma once
// Empirical regressions for the Newmark (rigid-block) displacement, for
// comparison with the computed ones (docs/analytical.md, "Empirical
// regressions", gives each equation with its source). Every function returns
// the median displacement in cm (the unit of the regressions) and, through
// `sigma`, the standard deviation of its logarithm (log10 for Jibson, ln for
// the others). Outside a regression's domain (k_y >= PGA, a non-positive
// input) the displacement is 0 where the model says so and NaN otherwise, as
// each function states.
namespace dda::analysis {

struct Regression {
  double median_cm = 0.0;
  double sigma = 0.0;  // of log10 D (Jibson) or ln D (the others)
};

// Jibson (2007), Eng. Geol. 91, 209-218, the k_c/a_max model: log D = 0.215 + log[(1 - r)^2.341 r^-1.438],
// r = k_y / PGA (PGA in g); sigma 0.510 (log10). r >= 1: 0.
Regression jibson2007_ratio(double ky, double pga_g);
// Jibson (2007), the Arias intensity and k_c model: log D = 2.401 log Ia - 3.481 log k_y - 3.230, Ia in
// m/s; sigma 0.656 (log10).
Regression jibson2007_arias(double ky, double arias);
// Jibson (2007), the Arias intensity and k_c/a_max model: log D = 0.561 log Ia - 3.833 log(k_y / PGA) - 1.474;
// sigma 0.616 (log10). k_y >= PGA: 0.
Regression jibson2007_arias_ratio(double ky, double pga_g, double arias);
// Bray and Travasarou (2007), JGGE 133(4), 381-392, the median non-zero
// displacement: ln D = -1.10 - 2.83 ln k_y
// - 0.333 (ln k_y)^2 + 0.566 ln k_y ln Sa + 3.04 ln Sa - 0.244 (ln Sa)^2
// + 1.50 Ts + 0.278 (M - 7), Sa = Sa(1.5 Ts) in g (5 % damping); for
// Ts < 0.05 s the constant is -0.22 and the Ts term is dropped (Sa is then
// the PGA); sigma 0.66 (ln). The median of the non-zero part (the paper's
// probability of zero displacement is probability_zero_bt2007).
Regression bray_travasarou2007(double ky, double sa_g, double ts, double magnitude);
// Bray and Travasarou (2007), the probability of zero displacement: P(D = 0) = 1 - Phi(-1.76 - 3.22 ln k_y
// - 0.484 Ts ln k_y + 3.52 ln Sa), D "zero" meaning below 1 cm.
double probability_zero_bt2007(double ky, double sa_g, double ts);
// Saygili and Rathje (2008), JGGE 134(6), 790-803, the PGA-PGV model: ln D = -1.56
// - 4.58 r - 20.84 r^2 + 44.75 r^3 - 30.50 r^4 - 0.64 ln PGA + 1.55 ln PGV,
// r = k_y / PGA, PGA in g, PGV in cm/s; sigma 0.405 + 0.524 r (ln). r >= 1: 0.
Regression saygili_rathje2008(double ky, double pga_g, double pgv_cm_s);

}  // namespace dda::analysis
