#pragma once
// Intensity measures of one component of an acceleration record
// (docs/analytical.md, "Record intensity measures").
//
// The record is a(t_0 + i dt), linear between samples (the record's own
// definition), in m/s^2; g = 9.81 m/s^2 (kRecordGravity).
//  * PGA = max |a|; PGV and PGD = max |v|, max |d| of the trapezoidal
//    integrals from rest (no baseline correction: a record with a drift has
//    a drifting PGD, so correct or filter it first).
//  * Arias intensity Ia = pi / (2 g) int a^2 dt (m/s), the integral exact for
//    the linear segments: dt (a_i^2 + a_i a_{i+1} + a_{i+1}^2) / 3 per step.
//  * Husid plot H(t) = int_0^t a^2 / int_0^T a^2 at the samples; the 5-95 %
//    significant duration D5-95 = t(H = 0.95) - t(H = 0.05), the two times
//    found within their steps on the exact (cubic) cumulative integral.
//  * Mean period (Rathje, Abrahamson and Bray 1998, JGGE 124(2), 150-159;
//    Rathje, Faraj, Russell and Bray 2004, Earthquake Spectra 20(1), 119-144):
//    Tm = sum C_i^2 / f_i / sum C_i^2 over the Fourier amplitudes C_i at the
//    frequencies 0.25 <= f_i <= 20 Hz (the DFT of the whole record, mean
//    removed, no taper; fourier_spectrum.hpp).
//  * Predominant period Tp: the period of the peak of the 5 %-damped
//    pseudo-acceleration spectrum (response_spectrum.hpp) over
//    kPredominantPeriods, 80 periods evenly spaced in log from 0.05 to 4 s
//    (neighbours 5.7 % apart).
#include <vector>

namespace dda::analysis {

struct IntensityMeasures {
  double pga = 0.0;                   // m/s^2
  double pgv = 0.0;                   // m/s
  double pgd = 0.0;                   // m
  double arias = 0.0;                 // m/s
  double t5 = 0.0, t95 = 0.0;         // s from the first sample: H = 0.05, 0.95
  double significant_duration = 0.0;  // s, t95 - t5
  double mean_period = 0.0;           // s; 0 when no energy lies in 0.25..20 Hz
  double predominant_period = 0.0;    // s
};

std::vector<double> predominant_periods();  // kPredominantPeriods, ascending

// a: two samples or more at the uniform step dt > 0 (InputError otherwise).
IntensityMeasures intensity_measures(const std::vector<double>& a, double dt);

// Normalised cumulative Arias intensity at the samples (0 .. 1; all zero for
// a record of zeros).
std::vector<double> husid(const std::vector<double>& a, double dt);

// Rathje et al.'s mean period from the record (0 when the band holds nothing).
double mean_period(const std::vector<double>& a, double dt);

}  // namespace dda::analysis
