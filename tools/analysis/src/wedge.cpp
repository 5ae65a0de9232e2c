#include "dda/analysis/wedge.hpp"

#include <cmath>
#include <limits>

#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"

namespace dda::analysis {

namespace {

double cohesion_term(const WedgeSpec& s, int plane) {
  const double c = plane == 1 ? s.cohesion1_kpa : s.cohesion2_kpa;
  const double a = plane == 1 ? s.area1_m2 : s.area2_m2;
  if (c == 0.0 || a == 0.0) return 0.0;
  return c * a / s.weight_kn;
}

void check(const WedgeSpec& s) {
  for (double phi : {s.phi1_deg, s.phi2_deg})
    if (!(phi >= 0.0 && phi < 90.0)) throw InputError("Wedge: friction angles must lie in 0..90 degrees.");
  if (!(s.water1 >= 0.0 && s.water2 >= 0.0)) throw InputError("Wedge: water forces must be >= 0.");
  const bool cohesive = s.cohesion1_kpa * s.area1_m2 != 0.0 || s.cohesion2_kpa * s.area2_m2 != 0.0;
  if (cohesive && !(s.weight_kn > 0.0))
    throw InputError("Wedge: cohesion needs the weight of the wedge (kN) as well as the plane areas.");
}

}  // namespace

WedgeGeometry wedge_geometry(const WedgeSpec& spec) {
  const Vec3 n1 = spec.plane1.normal(), n2 = spec.plane2.normal();
  const Vec3 I = n1.cross(n2);
  if (I.norm() < 1e-9) throw InputError("Wedge: the two planes are parallel (no line of intersection).");
  WedgeGeometry g;
  g.line = I.normalized();
  if (g.line.z() > 0.0) g.line = -g.line;
  g.line_orientation = trend_plunge(g.line);
  const double I2 = I.squaredNorm();
  const Vec3 r(0.0, 0.0, -1.0);
  const double N1 = -r.cross(n2).dot(I) / I2, N2 = r.cross(n1).dot(I) / I2;
  g.wedge_factor = (N1 + N2) / std::cos(deg2rad(g.line_orientation.plunge_deg));
  return g;
}

WedgeEquilibrium wedge_equilibrium(const WedgeSpec& spec, const Vec3& r_dry) {
  check(spec);
  const Vec3 n1 = spec.plane1.normal(), n2 = spec.plane2.normal();
  const Vec3 r = r_dry + spec.water1 * n1 + spec.water2 * n2;
  const Vec3 I = n1.cross(n2);
  if (I.norm() < 1e-9) throw InputError("Wedge: the two planes are parallel (no line of intersection).");
  const double I2 = I.squaredNorm();
  const double mu1 = std::tan(deg2rad(spec.phi1_deg)), mu2 = std::tan(deg2rad(spec.phi2_deg));
  const double inf = std::numeric_limits<double>::infinity();
  WedgeEquilibrium out;
  auto finish = [&](double resist, const Vec3& drive) {
    out.driving = drive.norm();
    out.sliding_direction = out.driving > 0.0 ? Vec3(drive / out.driving) : Vec3::Zero();
    out.fs = out.driving > 0.0 ? resist / out.driving : inf;
    return out;
  };
  if (r.dot(n1) >= 0.0 && r.dot(n2) >= 0.0) {
    out.mode = "lifting";
    out.sliding_direction = r.normalized();
    return out;
  }
  const double N1 = -r.cross(n2).dot(I) / I2, N2 = r.cross(n1).dot(I) / I2;
  if (N1 >= 0.0 && N2 >= 0.0) {
    out.mode = "double-face";
    out.n1 = N1;
    out.n2 = N2;
    const Vec3 e = I / std::sqrt(I2);
    return finish(mu1 * N1 + mu2 * N2 + cohesion_term(spec, 1) + cohesion_term(spec, 2), r.dot(e) * e);
  }
  for (int k = 1; k <= 2; ++k) {
    const Vec3& n = k == 1 ? n1 : n2;
    const Vec3& other = k == 1 ? n2 : n1;
    const double N = -r.dot(n);
    if (N <= 0.0) continue;
    const Vec3 s = r + N * n;
    if (s.dot(other) < 0.0) continue;
    out.mode = k == 1 ? "single-face-1" : "single-face-2";
    (k == 1 ? out.n1 : out.n2) = N;
    return finish((k == 1 ? mu1 : mu2) * N + cohesion_term(spec, k), s);
  }
  out.mode = "lifting";
  out.sliding_direction = r.normalized();
  return out;
}

YieldResult wedge_yield(const WedgeSpec& spec, const Vec3& u, double k_max) {
  const Vec3 d = u.normalized();
  auto fs = [&](double k) { return wedge_equilibrium(spec, Vec3(0.0, 0.0, -1.0) + k * d); };
  YieldResult y;
  WedgeEquilibrium e0 = fs(0.0);
  if (e0.fs <= 1.0) {
    y.found = true;
    y.k = 0.0;
    y.mode = e0.mode;
    return y;
  }
  const int n = 20000;
  double lo = 0.0;
  for (int i = 1; i <= n; ++i) {
    const double k = k_max * i / n;
    if (fs(k).fs <= 1.0) {
      double hi = k;
      for (int it = 0; it < 80; ++it) {
        const double mid = 0.5 * (lo + hi);
        (fs(mid).fs <= 1.0 ? hi : lo) = mid;
      }
      y.found = true;
      y.k = hi;
      y.mode = fs(hi).mode;
      return y;
    }
    lo = k;
  }
  return y;
}

std::optional<double> wedge_critical_friction(const WedgeSpec& spec) {
  auto fs = [&](double phi) {
    WedgeSpec s = spec;
    s.phi1_deg = s.phi2_deg = phi;
    return wedge_equilibrium(s, Vec3(0.0, 0.0, -1.0)).fs;
  };
  double lo = 0.0, hi = 89.9;
  if (fs(lo) > 1.0 || fs(hi) < 1.0) return std::nullopt;
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    (fs(mid) < 1.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace dda::analysis
