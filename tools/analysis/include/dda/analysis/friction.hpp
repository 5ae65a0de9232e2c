#pragma once
// Friction laws of the analytical sliding solutions (per plane).
//  * constant: mu = tan(phi).
//  * table: phi(t) piecewise linear between (t_k, phi_k); constant before the
//    first and after the last point; a repeated time makes a step (the later
//    value holds from that time on).
//  * log_velocity: mu = a + b ln(max(v, v_min) / v_ref), v the sliding speed
//    (m/s), never below zero. v_ref = 1 m/s by default (0.001 to read v in
//    mm/s as in the seed report's fits).
#include <string>
#include <vector>

namespace dda::analysis {

struct FrictionLaw {
  enum class Kind { constant, table, log_velocity };
  Kind kind = Kind::constant;
  double phi_deg = 30.0;
  std::vector<double> times, phis_deg;
  double a = 0.6, b = 0.0, v_ref = 1.0, v_min = 1e-6;

  static FrictionLaw constant_angle(double phi_deg);
  static FrictionLaw log_velocity(double a, double b, double v_ref = 1.0, double v_min = 1e-6);
  // Validates the table (sorted times, finite angles 0..89.9); InputError
  // naming `what` otherwise.
  static FrictionLaw table(std::vector<double> times, std::vector<double> phis_deg, const std::string& what);

  // Friction coefficient at time t for sliding speed v (m/s).
  double mu(double t, double speed) const;
  std::string describe() const;
};

}  // namespace dda::analysis
