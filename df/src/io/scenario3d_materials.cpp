// The `materials` section of a 3D scenario (scenario3d_detail.hpp; keys in
// docs/scenario.md, "The 3D forward run"): the default material and initial
// state, and zones that override them for the blocks they select (with the
// selection keys of `fixed`, scenario3d_select.cpp). As in 2D, the zones are
// checked in order and the first that holds a block wins; a zone's keys
// override the default's, not an earlier zone's.
#include <cmath>
#include <string>
#include <vector>

#include "dda/common/error.hpp"
#include "dda/df/3d/simulation3d.hpp"
#include "io/scenario3d_detail.hpp"

namespace dda::df3 {
namespace {

const std::vector<std::string> kMaterialKeys{"density", "young", "poisson", "initial_stress", "initial_velocity"};
// The selections of `fixed` that describe where a rock lies or which body
// it is; block-theory classes (`removability`) say how a body can move, not
// what it is made of, so a zone does not take them.
const std::vector<std::string> kZoneSelectionKeys{"blocks", "bodies", "below", "box", "outside"};

// Six finite numbers at `key`; `form` names them in the message.
Vector6d read_six(const YamlNode& n, const std::string& key, const std::string& form) {
  const YamlNode c = n.child(key);
  const std::vector<double> v = c.as_numbers();
  if (v.size() != 6) c.fail("must be " + form + " (six numbers), got " + std::to_string(v.size()));
  for (double x : v)
    if (!std::isfinite(x)) c.fail("must hold finite numbers");
  Vector6d out;
  out << v[0], v[1], v[2], v[3], v[4], v[5];
  return out;
}

// The 2D keys a 3D material or zone could be mistaken to take: one sentence
// saying why, rather than "unknown key".
void refuse_2d_keys(const YamlNode& n, bool zone) {
  if (!n.is_map()) return;  // allow() says what is wrong with it
  if (n.has("plane"))
    n.fail_key("plane", "is 2D only (plane stress or plane strain): a 3D block is a solid; leave it out");
  if (!zone) return;
  for (const char* key : {"layers", "polygon"})
    if (n.has(key))
      n.fail_key(key, "is a 2D zone selection; a 3D zone selects its blocks by blocks, bodies, below, box or outside");
}

// `n`'s material keys applied over `base`.
MaterialEntry3 read_entry(const YamlNode& n, const MaterialEntry3& base) {
  MaterialEntry3 e = base;
  e.material.density = n.number("density", base.material.density, Range::positive());
  e.material.young = n.number("young", base.material.young, Range::positive());
  e.material.poisson = n.number("poisson", base.material.poisson, Range{-1, 0.5, true, true});
  if (n.has("initial_stress")) {
    // Given as [sx, sy, sz, txy, tyz, tzx] (normal, then the shears in the
    // 2D order, txy first); Vector6d pairs the shears with the strains
    // [gyz, gzx, gxy], so txy goes last.
    const Vector6d s = read_six(n, "initial_stress", "[sx, sy, sz, txy, tyz, tzx]");
    e.stress << s[0], s[1], s[2], s[4], s[5], s[3];
  }
  if (n.has("initial_velocity")) {
    // The rigid-body part of the block unknowns' rates; no strain rates.
    e.velocity.setZero();
    e.velocity.head<6>() = read_six(n, "initial_velocity", "[vx, vy, vz, wx, wy, wz]");
  }
  return e;
}

}  // namespace

MaterialsSpec3 read_materials3(const YamlNode& root) {
  MaterialsSpec3 spec;
  const auto s = root.optional_child("materials");
  if (!s) return spec;
  s->allow({"default", "zones"});
  const YamlNode d = s->child("default");  // required when materials is given
  refuse_2d_keys(d, false);
  d.allow(kMaterialKeys);
  spec.base = read_entry(d, MaterialEntry3{});
  std::vector<std::string> zone_keys = kMaterialKeys;
  zone_keys.insert(zone_keys.end(), kZoneSelectionKeys.begin(), kZoneSelectionKeys.end());
  for (const YamlNode& z : s->list_or_empty("zones")) {
    refuse_2d_keys(z, true);
    z.allow(zone_keys);
    BlockSelection3 selection = read_block_selection(z);
    if (selection.empty()) z.fail("must select its blocks with at least one of blocks, bodies, below, box or outside");
    spec.zones.push_back({z, std::move(selection), read_entry(z, spec.base)});
  }
  return spec;
}

void assign_materials3(const MaterialsSpec3& spec, const PolyhedronModel& blocks, const std::string& blocks_path,
                       Model3& m) {
  const std::size_t n = blocks.blocks.size();
  // materials[0] is the default, materials[k + 1] zone k's.
  m.materials = {spec.base.material};
  std::vector<const MaterialEntry3*> entries{&spec.base};
  for (const MaterialsSpec3::Zone& z : spec.zones) {
    m.materials.push_back(z.entry.material);
    entries.push_back(&z.entry);
  }
  m.block_material.assign(n, 0);
  for (std::size_t k = 0; k < spec.zones.size(); ++k) {
    const MaterialsSpec3::Zone& zone = spec.zones[k];
    const std::vector<bool> selected = select_blocks(zone.selection, zone.node, blocks, blocks_path);
    int selected_count = 0, held = 0;
    for (std::size_t b = 0; b < n; ++b) {
      if (!selected[b]) continue;
      ++selected_count;
      if (m.block_material[b] != 0) continue;  // an earlier zone holds it
      m.block_material[b] = static_cast<int>(k + 1);
      ++held;
    }
    if (selected_count == 0) zone.node.fail("selects no block of " + blocks_path);
    if (held == 0)
      zone.node.fail("holds no block: every block it selects is in an earlier zone (the first zone that holds a "
                     "block wins)");
  }
  m.initial_stress.assign(n, Vector6d::Zero());
  m.initial_velocity.assign(n, Vector12d::Zero());
  for (std::size_t b = 0; b < n; ++b) {
    const MaterialEntry3& e = *entries[static_cast<std::size_t>(m.block_material[b])];
    m.initial_stress[b] = e.stress;
    // A fixed block has no unknowns: it stays at rest whatever its zone says.
    if (!m.fixed[b]) m.initial_velocity[b] = e.velocity;
  }
}

}  // namespace dda::df3
