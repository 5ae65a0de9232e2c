// Lysmer-Kuhlemeyer dashpots and the incident-wave input (viscous_boundary.hpp).
#include "dda/df/2d/viscous_boundary.hpp"

#include <array>
#include <cmath>

#include "dda/df/core/block_system.hpp"
#include "dda/df/core/lysmer_dashpot.hpp"
#include "dda/df/core/time_step.hpp"

namespace dda::df {
namespace {

// Two-point Gauss rule on [0, 1]: exact for the quadratic integrands here.
constexpr std::array<double, 2> kGaussPoint{0.2113248654051871, 0.7886751345948129};  // (1 -+ 1/sqrt3) / 2

struct Edge {
  Vec2 a, b;
  double length;
  Vec2 outward;  // unit
};

Edge edge_of(const Polygon2& v, int edge) {
  const Vec2 a = v[edge];
  const Vec2 b = v[(edge + 1) % v.size()];
  const Vec2 t = b - a;
  const double l = t.norm();
  // Counter-clockwise polygon: the outside is to the right of a -> b.
  return {a, b, l, Vec2(t.y(), -t.x()) / l};
}

}  // namespace

double p_wave_speed(const Material& m) {
  return p_wave_speed(m.young, m.poisson, m.density, m.plane != PlaneMode::Strain);
}

double s_wave_speed(const Material& m) { return shear_wave_speed(m.young, m.poisson, m.density); }

Matrix2d dashpot_matrix(const Material& m, const Vec2& n) {
  return lysmer_dashpot<2>(m.density, p_wave_speed(m), s_wave_speed(m), n);
}

FreeField free_field(const TimeHistory& incident, const Material& m, double y, double y_base, double y_surface,
                     double t0, double t1) {
  return free_field_motion<2>(incident, s_wave_speed(m), p_wave_speed(m), y, y_base, y_surface, t0, t1);
}

Vec2 free_field_traction(const FreeField& ff, const Material& m, const Matrix2d& dashpot, const Vec2& n) {
  // No strain out of the plane in plane strain, no stress in plane stress.
  const double lateral = m.plane == PlaneMode::Strain ? m.poisson / (1 - m.poisson) : m.poisson;
  return dashpot * ff.velocity + free_field_stress(ff, m.density, s_wave_speed(m), p_wave_speed(m), lateral) * n;
}

void add_viscous_edge_terms(int i, const Polygon2& v, const Vec2& c, int edge, const Matrix2d& dashpot,
                            const EdgeTraction& traction, double dt, BlockSystem& sys) {
  const Edge e = edge_of(v, edge);
  for (const double g : kGaussPoint) {
    const Vec2 p = e.a + g * (e.b - e.a);
    const Matrix26d t = t_matrix(c, p);
    const double w = 0.5 * e.length;  // weight of each point
    sys.diagonal(i) += (w / dt) * t.transpose() * dashpot * t;
    if (traction) sys.rhs(i) += w * t.transpose() * traction(p);
  }
}

ViscousEdgeEnergy viscous_edge_energy(const Polygon2& v, const Vec2& c, int edge, const Matrix2d& dashpot,
                                      const EdgeTraction& traction, const Vector6d& di, double dt) {
  const Edge e = edge_of(v, edge);
  ViscousEdgeEnergy out;
  for (const double g : kGaussPoint) {
    const Vec2 p = e.a + g * (e.b - e.a);
    const Vec2 u = t_matrix(c, p) * di;
    const double w = 0.5 * e.length;
    out.absorbed += w * u.dot(dashpot * u) / dt;
    if (traction) out.input_work += w * traction(p).dot(u);
  }
  return out;
}

}  // namespace dda::df
