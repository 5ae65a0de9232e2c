// Contact bookkeeping of the 3D step: detection with state carried over, and
// the open / sliding / locked rule (the 2D rules of df/src/contact.cpp with a
// 2-component shear).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "dda/df/simulation3d.hpp"
#include "simulation3d_assembly.hpp"

namespace dda::df3 {

namespace {

struct Box {
  Vec3 lo, hi;
};

Box bounds(const Polyhedron& p) {
  Box b{p.vertices.front(), p.vertices.front()};
  for (const auto& v : p.vertices) {
    b.lo = b.lo.cwiseMin(v);
    b.hi = b.hi.cwiseMax(v);
  }
  return b;
}

bool within(const Box& a, const Box& b, double reach) {
  for (int k = 0; k < 3; ++k)
    if (a.lo[k] > b.hi[k] + reach || b.lo[k] > a.hi[k] + reach) return false;
  return true;
}

bool same_key(const Contact3& a, const Contact3& b) {
  return a.i == b.i && a.j == b.j && a.kind == b.kind && std::equal(a.ids, a.ids + 4, b.ids);
}

Eigen::Matrix<double, 3, 2> tangents(const ContactGeometry3& g) {
  Eigen::Matrix<double, 3, 2> t;
  t << g.t1, g.t2;
  return t;
}

}  // namespace

std::vector<Contact3> detect_contacts3(const std::vector<Polyhedron>& blocks, const std::vector<Contact3>& previous,
                                       double reach) {
  Contact3Options opt;
  opt.reach = reach;
  std::vector<Box> box;
  for (const auto& b : blocks) box.push_back(bounds(b));
  std::vector<Contact3> out;
  const int n = static_cast<int>(blocks.size());
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      if (!within(box[a], box[b], reach)) continue;
      for (const auto& cand : find_contacts3(blocks[a], blocks[b], opt)) {
        Contact3 c;
        c.i = cand.a_is_i ? a : b;
        c.j = cand.a_is_i ? b : a;
        c.kind = cand.kind;
        if (cand.kind == ContactKind3::VertexFace) {
          c.ids[0] = cand.vertex;
          c.ids[1] = cand.face;
        } else {
          c.ids[0] = cand.edge_i[0];
          c.ids[1] = cand.edge_i[1];
          c.ids[2] = cand.edge_j[0];
          c.ids[3] = cand.edge_j[1];
        }
        c.geo = cand.geo;
        c.ref_j = cand.geo.point_j;
        for (const auto& old : previous) {
          if (!same_key(old, c)) continue;
          c.state = old.state;
          c.ref_j = old.ref_j;  // moved with block j at the end of the last step
          // The slip direction in the new tangent frame (t1, t2 may turn).
          const Eigen::Vector2d dir = tangents(c.geo).transpose() * (tangents(old.geo) * old.slip_dir);
          if (dir.norm() > 1e-12) c.slip_dir = dir.normalized();
          c.normal_force = old.normal_force;
          c.shear_force = old.shear_force;
          break;
        }
        if (c.state == ContactState3::Open) c.normal_force = 0;
        out.push_back(c);
      }
    }
  }
  return out;
}

void add_contact_terms(const Contact3& c, const Model3& m, Assembly3& sys) {
  if (c.state == ContactState3::Open) return;
  const ContactGeometry3& g = c.geo;
  // Normal spring: K += p [en; gn][en; gn]^T, F -= p dn0 [en; gn].
  sys.add_spring<1>(c.i, c.j, m.normal_penalty, Eigen::Matrix<double, 1, 1>(g.dn0), g.en.transpose(),
                    g.gn.transpose());
  if (c.state == ContactState3::Locked) {
    sys.add_spring<2>(c.i, c.j, m.shear_penalty, shear_offset(c), g.es, g.gs);
    return;
  }
  // Sliding: mu N against the slip, on P of block i and the reverse on Q of
  // block j (es = [t1 t2]^T T_i(P), gs = -[t1 t2]^T T_j(Q)).
  const double f = std::tan(m.friction_deg * std::numbers::pi / 180) * c.normal_force;
  sys.add_f(c.i, -f * g.es.transpose() * c.slip_dir);
  sys.add_f(c.j, -f * g.gs.transpose() * c.slip_dir);
}

Eigen::Vector2d shear_offset(const Contact3& c) { return tangents(c.geo).transpose() * (c.geo.point_i - c.ref_j); }

ContactState3 update_contact3(Contact3& c, const Model3& m, const Vector12d& di, const Vector12d& dj, bool hold,
                              bool& settled) {
  const ContactGeometry3& g = c.geo;
  const double eps = m.tolerance, pn = m.normal_penalty, ps = m.shear_penalty;
  const double mu = std::tan(m.friction_deg * std::numbers::pi / 180);
  const double dn = g.dn0 + g.en.dot(di) + g.gn.dot(dj);
  const ContactState3 old = c.state;
  const double friction_used = old == ContactState3::Sliding ? mu * c.normal_force : 0.0;

  // Closing or sticking: the shear spring's anchor. A fresh contact starts
  // unloaded at the foot Q; a sliding contact that sticks keeps the friction
  // force it carried (spring stretched by F / ps along the slip, as in 2D).
  auto lock = [&]() {
    c.ref_j = g.point_i - (g.point_i - g.point_j).dot(g.normal) * g.normal;  // tangential offset 0
    if (old == ContactState3::Sliding) c.ref_j -= tangents(g) * c.slip_dir * (friction_used / ps);
    return ContactState3::Locked;
  };
  c.shear_force.setZero();
  c.slip.setZero();

  if (old == ContactState3::Open) {
    if (dn < -eps) {
      c.normal_force = -pn * dn;
      return lock();
    }
    c.normal_force = 0;
    return ContactState3::Open;
  }

  const double n = -pn * dn;
  if (n < -pn * eps && !hold) {  // tension beyond the band: the contact opens
    c.normal_force = 0;
    return ContactState3::Open;
  }
  c.normal_force = n;
  const double strength = mu * std::max(n, 0.0);

  if (old == ContactState3::Locked) {
    const Eigen::Vector2d ds = shear_offset(c) + g.es * di + g.gs * dj;
    const Eigen::Vector2d fs = -ps * ds;
    if (fs.norm() > strength + ps * eps) {
      c.slip_dir = ds.normalized();
      c.shear_force = -strength * c.slip_dir;
      return ContactState3::Sliding;
    }
    c.shear_force = fs;
    return ContactState3::Locked;
  }

  // Sliding: slip of P relative to the point of j under it in this iterate.
  const Eigen::Vector2d slip = g.es * di + g.gs * dj;
  c.slip = slip;
  if (slip.dot(c.slip_dir) < -eps && !hold) return lock();
  // The friction direction stays fixed within the step: when the block is
  // nearly stuck the iterate's slip is a tiny residual whose direction
  // swings from one iterate to the next (following it diverged in a test).
  // finish_step turns it to the step's slip.
  const double floor = 1e-10 * pn;  // the force of a 1e-10 m penetration
  if (std::abs(strength - friction_used) > 1e-3 * strength + floor) settled = false;
  c.shear_force = -strength * c.slip_dir;
  return ContactState3::Sliding;
}

}  // namespace dda::df3
