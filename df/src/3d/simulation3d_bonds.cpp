// Bonds of the 3D joints (bonds3d.hpp): where they are placed, the share of
// the patch each contact carries, and what a break releases; and the glue of
// DC's artificial cuts, a bond that never breaks, placed by the same rule.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "3d/bonds3d.hpp"
#include "3d/facing_patches3d.hpp"

namespace dda::df3 {

namespace {

std::uint64_t pair_key(int a, int b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
}

// The contact stands on the patch: its plane is the patch's (within 10
// degrees, as the faces), its point within `reach` of that plane and no
// further than `merge` outside the polygon (the corners of the overlap lie
// on its boundary, where round-off puts them either side).
bool on_patch(const Contact3& c, const df::FacingPatch3& p, double reach, double merge) {
  const Vec3& n = p.normal;
  if (std::abs(c.geo.normal.dot(n)) < std::cos(10.0 * M_PI / 180.0)) return false;
  const Vec3 x = 0.5 * (c.geo.point_i + c.geo.point_j);
  if (std::abs(n.dot(x - p.polygon.front())) > reach) return false;
  for (std::size_t e = 0; e < p.polygon.size(); ++e) {
    const Vec3& a = p.polygon[e];
    const Vec3 inward = n.cross(p.polygon[(e + 1) % p.polygon.size()] - a);
    if (inward.norm() == 0) continue;  // a repeated corner of the clipped polygon
    if (inward.normalized().dot(x - a) < -merge) return false;
  }
  return true;
}

}  // namespace

std::vector<double> bond_areas3(const std::vector<Polyhedron>& blocks, const std::vector<Contact3>& contacts,
                                double reach, double merge, const std::function<bool(const Contact3&)>& accept) {
  std::vector<double> area(contacts.size(), 0.0);
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> of_pair;
  for (std::size_t k = 0; k < contacts.size(); ++k)
    if (accept(contacts[k])) of_pair[pair_key(contacts[k].i, contacts[k].j)].push_back(k);
  for (const df::FacingPatch3& p : df::facing_patches3(blocks, contacts, reach, accept)) {
    const Contact3& finder = contacts[p.contact];
    std::vector<std::size_t> on;
    for (const std::size_t k : of_pair[pair_key(finder.i, finder.j)])
      if (area[k] == 0 && on_patch(contacts[k], p, reach, merge)) on.push_back(k);
    const double share = df::polygon_area3(p.polygon) / static_cast<double>(std::max<std::size_t>(on.size(), 1));
    for (const std::size_t k : on) area[k] = share;
  }
  return area;
}

double bond_tension3(const Contact3& c, const Model3& m) {
  return df::bond_tension_capacity(m.joint(c.joint).tensile_strength, c.bond_area, c.bonded);
}

void break_bond_in_tension3(Contact3& c, const Model3& m, const ContactSprings3& springs,
                            const Eigen::Vector2d& shear) {
  const double pull = bond_tension3(c, m);
  c.bond_released = springs.normal_energy(-pull) + shear.squaredNorm() / (2 * springs.ps);
  c.bonded = false;
}

namespace {

// Bonded and glued faces start closed (as in 2D), so that they hold a block
// that would fall away from them; the shear spring starts unloaded.
void close_held(Contact3& c, const ContactSprings3& springs) {
  if (c.state != ContactState3::Open) return;
  c.state = ContactState3::Locked;
  const df::NormalSpring normal = springs.normal_spring(c.geo.dn0);
  c.normal_force = -normal.k * normal.s0;  // -pn dn0 for the linear penalty
}

}  // namespace

void Simulation3::place_glue() {
  if (bonds_placed_) return;
  for (Contact3& c : contacts_) {
    if (c.glued || !df::in_touch_at_start(c.geo.dn0, model_.contact_reach)) continue;
    if (!on_artificial_cut3(model_.blocks, c)) continue;
    c.glued = true;
    c.joint = model_.glue_joint();
    close_held(c, springs_of(c));
  }
}

void Simulation3::place_bonds() {
  if (!bonds_used_ || bonds_placed_) return;
  auto bondable = [&](const Contact3& c) {
    const df::JointProperties& j = model_.joint(c.joint);
    return !c.glued && df::forms_bonds(j) && df::in_touch_at_start(c.geo.dn0, model_.contact_reach);
  };
  const std::vector<double> area =
      bond_areas3(model_.blocks, contacts_, model_.contact_reach, model_.contact_merge, bondable);
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    Contact3& c = contacts_[k];
    if (c.bonded || area[k] <= 0) continue;
    c.bonded = true;
    c.bond_area = area[k];
    close_held(c, springs_of(c));
  }
}

}  // namespace dda::df3
