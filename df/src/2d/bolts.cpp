// Rock bolts: terms of the step system and update after a step.
#include "dda/df/2d/bolts.hpp"

#include "dda/df/2d/block_kinematics.hpp"
#include "dda/df/core/block_system.hpp"

namespace dda::df {

BoltState initial_bolt_state(const Bolt& bolt) { return initial_bolt_state(bolt, bolt.anchor, bolt.head); }

void add_bolt_terms(const Bolt& bolt, const BoltState& s, const Vec2& ca, const Vec2& ch, BlockSystem& sys) {
  if (s.broken) return;
  const Vec2 u = (s.head - s.anchor).normalized();
  const Vector6d ea = -t_matrix(ca, s.anchor).transpose() * u;
  const Vector6d eh = t_matrix(ch, s.head).transpose() * u;
  const int a = bolt.anchor_block, h = bolt.head_block;
  const double k = bolt.stiffness;
  sys.diagonal(a) += k * ea * ea.transpose();
  sys.diagonal(h) += k * eh * eh.transpose();
  sys.add_coupling(a, h, k * ea * eh.transpose());
  // Energy T dL: the force T pulls the anchor toward the head and back.
  sys.rhs(a) -= s.force * ea;
  sys.rhs(h) -= s.force * eh;
}

double advance_bolt(const Bolt& bolt, BoltState& s, const Vec2& ca, const Vector6d& da, const Vec2& ch,
                    const Vector6d& dh) {
  s.anchor = move_point(ca, da, s.anchor);
  s.head = move_point(ch, dh, s.head);
  return update_bolt_force(bolt, s);
}

}  // namespace dda::df
