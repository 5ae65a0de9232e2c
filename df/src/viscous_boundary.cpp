// Lysmer-Kuhlemeyer dashpots and the incident-wave input (viscous_boundary.hpp).
#include "dda/df/viscous_boundary.hpp"

#include <array>
#include <cmath>

#include "dda/df/block_system.hpp"

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
  const double nu = m.poisson;
  const double modulus = m.plane == PlaneMode::Strain ? m.young * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
                                                      : m.young / (1 - nu * nu);
  return std::sqrt(modulus / m.density);
}

double s_wave_speed(const Material& m) { return std::sqrt(m.young / (2 * (1 + m.poisson) * m.density)); }

Matrix2d dashpot_matrix(const Material& m, const Vec2& n) {
  const Vec2 s(-n.y(), n.x());
  return m.density * (p_wave_speed(m) * n * n.transpose() + s_wave_speed(m) * s * s.transpose());
}

void add_viscous_edge_terms(int i, const Polygon2& v, const Vec2& c, int edge, const Matrix2d& dashpot,
                            const Vec2& v_in, double dt, BlockSystem& sys) {
  const Edge e = edge_of(v, edge);
  const Vec2 traction_in = 2.0 * dashpot * v_in;
  for (const double g : kGaussPoint) {
    const Matrix26d t = t_matrix(c, e.a + g * (e.b - e.a));
    const double w = 0.5 * e.length;  // weight of each point
    sys.diagonal(i) += (w / dt) * t.transpose() * dashpot * t;
    sys.rhs(i) += w * t.transpose() * traction_in;
  }
}

ViscousEdgeEnergy viscous_edge_energy(const Polygon2& v, const Vec2& c, int edge, const Matrix2d& dashpot,
                                      const Vec2& v_in, const Vector6d& di, double dt) {
  const Edge e = edge_of(v, edge);
  ViscousEdgeEnergy out;
  for (const double g : kGaussPoint) {
    const Vec2 u = t_matrix(c, e.a + g * (e.b - e.a)) * di;
    const double w = 0.5 * e.length;
    out.absorbed += w * u.dot(dashpot * u) / dt;
    out.input_work += w * (2.0 * dashpot * v_in).dot(u);
  }
  return out;
}

}  // namespace dda::df
