// Contact springs, friction forces and the open / sliding / locked decision.
#include "dda/df/2d/contact.hpp"

#include <algorithm>
#include <cmath>

#include "dda/df/core/block_system.hpp"
#include "dda/df/core/bond.hpp"

namespace dda::df {

const char* to_string(ContactState s) {
  switch (s) {
    case ContactState::Open: return "open";
    case ContactState::Sliding: return "sliding";
    case ContactState::Locked: return "locked";
  }
  return "?";
}

ContactGeometry contact_geometry(const Polygon2& vi, const Vec2& ci, const Polygon2& vj, const Vec2& cj, int vertex,
                                 int edge, double ref_ratio) {
  const Vec2& p = vi[vertex];
  const Vec2& a = vj[edge];
  const Vec2& b = vj[edge + 1 == static_cast<int>(vj.size()) ? 0 : edge + 1];  // no division: once per contact per step
  const Vec2 e = b - a;
  ContactGeometry g;
  g.length = e.norm();
  g.tangent = e / g.length;

  // dn * l = cross(P - A, B - A) is bilinear in the three points; its
  // gradients with respect to P, A and B (they sum to zero: a rigid
  // translation changes nothing) give the first-order change of dn.
  g.dn0 = cross(p - a, e) / g.length;
  const Vec2 grad_p(e.y(), -e.x());
  const Vec2 grad_a(p.y() - b.y(), b.x() - p.x());
  const Vec2 grad_b(a.y() - p.y(), p.x() - a.x());
  g.en = t_transpose_times(ci, p, grad_p) / g.length;
  g.arm_p = p - ci;
  g.gn = (t_transpose_times(cj, a, grad_a) + t_transpose_times(cj, b, grad_b)) / g.length;

  // Shear: offset of P along the (fixed) tangent from the reference point
  // P0, which moves with block j. The edge's own rotation changes ds only to
  // second order while P stays near P0.
  g.ratio0 = (p - a).dot(e) / (g.length * g.length);
  const Vec2 p0 = a + ref_ratio * e;
  g.ds0 = (p - p0).dot(g.tangent);
  g.arm_ref = p0 - cj;
  g.arm_proj = Vec2(a + g.ratio0 * e) - cj;
  return g;
}

bool on_artificial_cut(const Block& vblock, int vertex, const Block& eblock, int edge) {
  const int n = static_cast<int>(vblock.edge_set.size());
  if (eblock.edge_set[edge] != kArtificialSet) return false;
  return vblock.edge_set[vertex] == kArtificialSet || vblock.edge_set[(vertex + n - 1) % n] == kArtificialSet;
}

double tributary_length(const Polygon2& vi, int vertex, const Vec2& edge_tangent) {
  constexpr double kSinTol = 0.173648;  // sin(10 degrees)
  const int n = static_cast<int>(vi.size());
  double len = 0;
  for (const int other : {vertex == 0 ? n - 1 : vertex - 1, vertex + 1 == n ? 0 : vertex + 1}) {
    const Vec2 side = vi[other] - vi[vertex];
    const double l = side.norm();
    if (l > 0 && std::abs(cross(side / l, edge_tangent)) <= kSinTol) len += 0.5 * l;
  }
  return len;
}

namespace {

// The penalty energy p/2 (s0 + a.di + b.dj)^2 of one spring: its stiffness
// into K (a negative p takes out one added before), or its force into F.
// The diagonal blocks get their lower triangle only (all that is read of
// them, see block_system.hpp).
void add_spring_matrix(BlockSystem& sys, int i, int j, double p, const Vector6d& a, const Vector6d& b) {
  const Vector6d pa = p * a, pb = p * b;
  Matrix6d& di = sys.diagonal(i);
  Matrix6d& dj = sys.diagonal(j);
  for (int col = 0; col < kDofs; ++col)
    for (int row = col; row < kDofs; ++row) {
      di(row, col) += pa[row] * a[col];
      dj(row, col) += pb[row] * b[col];
    }
  sys.add_coupling(i, j, pa * b.transpose());
}

// Both springs of a locked contact, p/2 (a.di + b.dj)^2 + q/2 (c.di + e.dj)^2,
// in one pass over each block: one lookup of the coupling block and one
// write of it instead of two.
void add_spring_pair_matrix(BlockSystem& sys, int i, int j, double p, const Vector6d& a, const Vector6d& b, double q,
                            const Vector6d& c, const Vector6d& e) {
  const Vector6d pa = p * a, pb = p * b, qc = q * c, qe = q * e;
  Matrix6d& di = sys.diagonal(i);
  Matrix6d& dj = sys.diagonal(j);
  for (int col = 0; col < kDofs; ++col)
    for (int row = col; row < kDofs; ++row) {
      di(row, col) += pa[row] * a[col] + qc[row] * c[col];
      dj(row, col) += pb[row] * b[col] + qe[row] * e[col];
    }
  sys.add_coupling(i, j, pa * b.transpose() + qc * e.transpose());
}

void add_spring_force(BlockSystem& sys, int i, int j, double p, double s0, const Vector6d& a, const Vector6d& b) {
  sys.rhs(i) -= p * s0 * a;
  sys.rhs(j) -= p * s0 * b;
}

// The normal spring of a closed contact over the step (the joint's normal
// law, linearised as normal_law.hpp says). Glued contacts (DC's cuts inside
// one piece of rock) keep pn.
NormalSpring normal_spring(const Contact& c, const ContactLaw& law) {
  return normal_spring_over_step(c.glued ? nullptr : law.normal, law.pn, c.geo.dn0);
}

FrictionInput friction_input(const Contact& c, double dt) {
  return {c.normal_force, c.slip_velocity, c.length, dt, c.bonded};
}

}  // namespace

void add_contact_springs(const Contact& c, const ContactLaw& law, double weight, BlockSystem& sys) {
  if (c.state == ContactState::Open) return;
  const ContactGeometry& g = c.geo;
  if (c.state == ContactState::Locked) {
    add_spring_pair_matrix(sys, c.vblock, c.eblock, weight * normal_spring(c, law).k, g.en, g.gn, weight * law.ps,
                           g.es(), g.gs());
  } else {
    add_spring_matrix(sys, c.vblock, c.eblock, weight * normal_spring(c, law).k, g.en, g.gn);
  }
}

double friction_force(const Contact& c, const ContactLaw& law, double dt) {
  if (c.state != ContactState::Sliding) return 0.0;
  return c.slip_sign * law.friction->strength(friction_input(c, dt), c.friction);
}

void add_contact_forces(const Contact& c, const ContactLaw& law, double friction, double weight, BlockSystem& sys) {
  if (c.state == ContactState::Open) return;
  const ContactGeometry& g = c.geo;
  const NormalSpring normal = normal_spring(c, law);
  add_spring_force(sys, c.vblock, c.eblock, weight * normal.k, normal.s0, g.en, g.gn);
  if (c.state == ContactState::Locked) {
    add_spring_force(sys, c.vblock, c.eblock, weight * law.ps, g.ds0, g.es(), g.gs());
  } else {
    // Sliding: friction from the normal force of the previous iterate, on P
    // against its slip and the reverse on the edge under P.
    add_friction_change(c, weight * friction, sys);
  }
}

void add_friction_change(const Contact& c, double change, BlockSystem& sys) {
  sys.rhs(c.vblock) -= change * c.geo.es();  // es = T_i(P)^T t
  sys.rhs(c.eblock) -= change * c.geo.gc();  // gc = -T_j(Pc)^T t
}

void add_contact_forces(const Contact& c, const ContactLaw& law, double dt, BlockSystem& sys) {
  add_contact_forces(c, law, friction_force(c, law, dt), 1.0, sys);
}

void add_contact_terms(const Contact& c, const ContactLaw& law, double dt, BlockSystem& sys) {
  add_contact_springs(c, law, 1.0, sys);
  add_contact_forces(c, law, dt, sys);
}

ContactState update_contact(Contact& c, const ContactLaw& law, double dt, const Vector6d& di, const Vector6d& dj,
                            bool hold) {
  ContactGeometry& g = c.geo;
  const double dn = g.dn0 + g.en.dot(di) + g.gn.dot(dj);  // the gap (penetration negative): decides closing
  const NormalSpring spring = normal_spring(c, law);
  // The spring's force; for the penalty (s0 = dn0) the very numbers of -pn dn.
  const double n = -spring.k * (spring.s0 + g.en.dot(di) + g.gn.dot(dj));
  const ContactState old = c.state;
  const double friction_used =
      old == ContactState::Sliding ? law.friction->strength(friction_input(c, dt), c.friction) : 0.0;
  c.friction_settled = true;
  auto lock = [&]() {
    if (old == ContactState::Open) {  // a fresh contact: the shear spring starts unloaded at P
      c.ref_ratio = g.ratio0;
      g.ds0 = 0;
      g.reference_at_projection();
    } else if (old == ContactState::Sliding) {
      // A sliding contact that sticks keeps the friction force it carried:
      // the spring starts stretched by F / ps (elastic-plastic shear spring),
      // so the shear force is continuous. Restarting it unloaded dropped the
      // friction to nothing for the steps the spring took to reload, which
      // with soft penalties and short steps fed the rocking mode (V1 at
      // E = 1 GPa, dt = 0.2 ms overshot by 12 %).
      g.ds0 = c.slip_sign * friction_used / law.ps;
      c.ref_ratio = g.ratio0 - g.ds0 / g.length;
      g.reference_at_projection();  // the reference moved by F/ps, far below the step's size
    }
    return ContactState::Locked;
  };
  c.broke = false;
  c.shear_force = 0;
  c.slip_velocity = 0;

  if (c.glued) {  // never opens, never slides: both springs stay on
    c.normal_force = n;
    c.shear_force = -law.ps * (g.ds0 + g.es().dot(di) + g.gs().dot(dj));
    if (old != ContactState::Locked) lock();
    return ContactState::Locked;
  }

  const double eps = law.tolerance;
  if (old == ContactState::Open) {
    if (dn < -eps) {
      c.normal_force = n;
      return lock();
    }
    c.normal_force = 0;
    return ContactState::Open;
  }

  // A closed contact within the band keeps its spring (a pull of at most pn eps).
  const double tension_cap = bond_tension_capacity(law.tensile_strength, c.length, c.bonded) + law.pn * eps;
  if (n < -tension_cap && !hold) {
    c.broke = c.bonded;
    c.bonded = false;
    c.normal_force = 0;
    return ContactState::Open;
  }
  c.normal_force = n;
  const Vector6d es = g.es();
  const double slip = es.dot(di) + g.gc().dot(dj);  // P relative to the edge point under it
  c.slip_velocity = std::abs(slip) / dt;

  if (old == ContactState::Locked) {
    const double ds = g.ds0 + es.dot(di) + g.gs().dot(dj);
    const double fs = -law.ps * ds;
    if (std::abs(fs) > law.friction->strength(friction_input(c, dt), c.friction) + law.ps * eps) {
      c.broke = c.bonded;
      c.bonded = false;
      c.slip_sign = ds > 0 ? 1 : -1;
      c.shear_force = -c.slip_sign * law.friction->strength(friction_input(c, dt), c.friction);
      return ContactState::Sliding;
    }
    c.shear_force = fs;
    return ContactState::Locked;
  }

  // Sliding: it locks when P moves back against the assumed slip direction.
  if (slip * c.slip_sign < -eps && !hold) return lock();
  const double friction_now = law.friction->strength(friction_input(c, dt), c.friction);
  const double floor = 1e-10 * law.pn * g.length;  // the force of a 1e-10 l penetration
  c.friction_settled = std::abs(friction_now - friction_used) <= 1e-3 * std::abs(friction_now) + floor;
  c.shear_force = -c.slip_sign * friction_now;
  return ContactState::Sliding;
}

AssembledSprings assembled_springs(const Contact& c) { return {c.state, c.geo.ds0, c.geo.arm_ref}; }

Contact as_assembled(Contact c, const AssembledSprings& s) {
  c.state = s.state;
  c.geo.ds0 = s.ds0;
  c.geo.arm_ref = s.arm_ref;
  return c;
}

ContactIterationState iteration_state(const Contact& c) {
  ContactIterationState s;
  s.state = c.state;
  s.slip_sign = c.slip_sign;
  s.friction_settled = c.friction_settled;
  s.bonded = c.bonded;
  s.broke = c.broke;
  s.ref_ratio = c.ref_ratio;
  s.normal_force = c.normal_force;
  s.shear_force = c.shear_force;
  s.slip_velocity = c.slip_velocity;
  s.ds0 = c.geo.ds0;
  s.arm_ref = c.geo.arm_ref;
  return s;
}

void restore_iteration_state(Contact& c, const ContactIterationState& s) {
  c.state = s.state;
  c.slip_sign = s.slip_sign;
  c.friction_settled = s.friction_settled;
  c.bonded = s.bonded;
  c.broke = s.broke;
  c.ref_ratio = s.ref_ratio;
  c.normal_force = s.normal_force;
  c.shear_force = s.shear_force;
  c.slip_velocity = s.slip_velocity;
  c.geo.ds0 = s.ds0;
  c.geo.arm_ref = s.arm_ref;
}

}  // namespace dda::df
