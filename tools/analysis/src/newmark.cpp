#include "dda/analysis/newmark.hpp"

#include <cmath>

#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"

namespace dda::analysis {

namespace {

struct Loads {
  double driving = 0.0;  // downslope
  double normal = 0.0;   // pressing onto the plane
};

// The water force on the plane per unit mass, g ru / cos(alpha) (newmark.hpp).
double g_water_per_mass(const NewmarkInput& in, double alpha) { return in.gravity * in.ru / std::cos(alpha); }

}  // namespace

NewmarkResult run_newmark(const NewmarkInput& in, const Excitation& excitation) {
  if (!(in.dt > 0.0)) throw InputError("Newmark: the time step must be positive.");
  if (!(in.duration > 0.0)) throw InputError("Newmark: the duration must be positive.");
  if (in.dip_deg < 0.0 || in.dip_deg >= 90.0) throw InputError("Newmark: the dip must lie in 0..90 degrees.");
  if (in.phi_deg < 0.0 || in.phi_deg >= 90.0)
    throw InputError("Newmark: the friction angle must lie in 0..90 degrees.");
  if (!(in.ru >= 0.0 && in.ru < 1.0)) throw InputError("Newmark: the pore-pressure ratio ru must lie in [0, 1).");
  const double alpha = deg2rad(in.dip_deg);
  const double water = g_water_per_mass(in, alpha);
  const double mu = std::tan(deg2rad(in.phi_deg));
  const double g = in.gravity;
  const Vec3 h = horizontal(in.dip_direction_deg);
  auto loads = [&](double t) {
    const Vec3 b = excitation.body(t);
    const double bh = b.dot(h), bv = b.z();
    return Loads{bh * std::cos(alpha) + (g - bv) * std::sin(alpha),
                 (g - bv) * std::cos(alpha) - bh * std::sin(alpha) - water};
  };
  // Relative acceleration for the friction state given by velocity v.
  auto accel = [&](const Loads& l, double v) {
    const double resist = mu * l.normal;
    if (v > 0.0) return l.driving - resist;
    if (v < 0.0) return l.driving + resist;
    if (l.driving > resist) return l.driving - resist;
    if (in.two_way && l.driving < -resist) return l.driving + resist;
    return 0.0;
  };

  NewmarkResult r;
  if (in.ru == 0.0) {
    r.yield_down = g * std::tan(deg2rad(in.phi_deg - in.dip_deg));
    r.yield_up = -g * std::tan(deg2rad(in.phi_deg + in.dip_deg));
  } else {
    const double c = std::cos(alpha), sn = std::sin(alpha);
    r.yield_down = g * (mu * c - sn - mu * in.ru / c) / (c + mu * sn);
    r.yield_up = -g * (sn + mu * c - mu * in.ru / c) / (c - mu * sn);
  }
  const auto steps = static_cast<long>(std::ceil(in.duration / in.dt - 1e-9));
  double s = 0.0, v = 0.0;
  Loads l0 = loads(0.0);
  r.t.push_back(0.0);
  r.s.push_back(0.0);
  r.v.push_back(0.0);
  r.a.push_back(accel(l0, 0.0));
  bool sliding = false;
  for (long i = 0; i < steps; ++i) {
    const double t0 = static_cast<double>(i) * in.dt;
    const double t1 = std::min(in.duration, static_cast<double>(i + 1) * in.dt);
    const double h1 = t1 - t0;
    const Loads l1 = loads(t1);
    if (l1.normal <= 0.0) {
      r.lift_off = true;
      r.lift_off_time = t1;
      break;
    }
    const double a0 = accel(l0, v), a1 = accel(l1, v);
    const double S = 0.5 * (a0 + a1);
    const double vn = v + S * h1;
    if (v != 0.0 && vn * v <= 0.0) {
      const double tau = -v / S;  // time to stop within the step
      s += 0.5 * v * tau;
      v = 0.0;
    } else {
      s += v * h1 + 0.5 * S * h1 * h1;
      v = vn;
    }
    if (v != 0.0 && !sliding) ++r.slip_episodes;
    sliding = v != 0.0;
    r.t.push_back(t1);
    r.s.push_back(s);
    r.v.push_back(v);
    r.a.push_back(accel(l1, v));
    l0 = l1;
  }
  return r;
}

}  // namespace dda::analysis
