#pragma once
// Pieces of the 3D scenario reader (scenario3d.hpp) shared by its files;
// private to DF.
#include <optional>
#include <string>
#include <vector>

#include "dda/common/polyhedron_model.hpp"
#include "dda/common/yaml_reader.hpp"
#include "dda/df/3d/block3d.hpp"
#include "dda/df/3d/points3d.hpp"

namespace dda::df3 {

struct Model3;

// The `bolts` section (scenario3d_bolts.cpp) into m.bolts, needs m.fixed;
// an end outside every block, two ends in one block or in two fixed blocks
// is an error naming the key. `tolerance` (m): how far outside a block an
// end may lie.
void add_bolts3(const YamlNode& root, const std::vector<Polyhedron>& blocks, double tolerance, Model3& m);

// [x, y, z], finite.
Vec3 read_vec3(const YamlNode& n, const std::string& key);
// [[t, x, y, z], ...], at least one row, t strictly increasing.
TimeHistory3 read_history3(const YamlNode& n, const std::string& key);

// Blocks chosen by id, body, level, box or block-theory class
// (scenario3d_select.cpp): the `fixed` section and each item of
// `materials.zones` select blocks with these keys. A block is selected if
// any of the selections given holds it.
struct BlockSelection3 {
  std::vector<std::pair<YamlNode, long long>> blocks;  // `blocks` items: ids in the blocks file
  std::vector<std::pair<YamlNode, long long>> bodies;  // `bodies` items: every part of these bodies
  std::optional<double> below;                       // m: centroid z below this
  std::optional<Box3> box;                           // centroid inside
  std::optional<Box3> outside;                       // centroid outside
  std::vector<std::pair<YamlNode, Removability>> removability;  // bodies of these classes
  bool empty() const {
    return blocks.empty() && bodies.empty() && !below && !box && !outside && removability.empty();
  }
};

// Reads whichever selection keys (blocks, bodies, below, box, outside,
// removability) mapping `n` has; the caller's allow() decides which of them
// it accepts.
BlockSelection3 read_block_selection(const YamlNode& n);

// One flag per block of `blocks`: held by the selection `s` read from `n`.
// An id that does not exist, or a level, box or class that selects no
// block, is an error naming the key of `n`.
std::vector<bool> select_blocks(const BlockSelection3& s, const YamlNode& n, const PolyhedronModel& blocks,
                                const std::string& blocks_path);

// The `fixed` section: which blocks are held (a union of selections, each
// of which must select something) and settings of named fixed points.
struct FixedSpec3 {
  std::optional<YamlNode> node;                      // `fixed`, if given
  BlockSelection3 selection;
  struct Point {
    YamlNode node;
    std::string point;
    double penalty = 0;  // 0: the default
    std::optional<TimeHistory3> displacement;
  };
  std::vector<Point> points;
};

FixedSpec3 read_fixed3(const YamlNode& root);

// One flag per block of `blocks`: held fixed. A selection that selects no
// block, an id that does not exist, or fixing every block is an error
// naming the key.
std::vector<bool> select_fixed_blocks(const FixedSpec3& spec, const PolyhedronModel& blocks,
                                      const std::string& blocks_path);

// The `materials` section (scenario3d_materials.cpp): `default`, and
// `zones` that override it for the blocks they select, the first zone that
// holds a block winning.
struct MaterialEntry3 {
  Material3 material;
  Vector6d stress = Vector6d::Zero();    // Pa, in Vector6d's order [sx sy sz tyz tzx txy]
  Vector12d velocity = Vector12d::Zero();  // rates of the block unknowns: [vx vy vz wx wy wz], no strain rates
};
struct MaterialsSpec3 {
  MaterialEntry3 base;  // materials.default (or the built-in defaults)
  struct Zone {
    YamlNode node;              // the materials.zones item
    BlockSelection3 selection;
    MaterialEntry3 entry;       // base with the zone's keys applied
  };
  std::vector<Zone> zones;
};

MaterialsSpec3 read_materials3(const YamlNode& root);

// Gives every block of `m` its material, initial stress and (free blocks
// only: a fixed block has no unknowns and stays at rest) initial velocity.
// Needs m.fixed. A zone that ends up holding no block is an error naming it.
void assign_materials3(const MaterialsSpec3& spec, const PolyhedronModel& blocks, const std::string& blocks_path,
                       Model3& m);

// boundaries.viscous and boundaries.free_field (scenario3d_waves.cpp): the
// sides, checked; then their faces into m.viscous, with the earthquake's
// incident wave when its mode is incident (needs m.earthquake and
// m.control.dt).
struct BoundarySides3 {
  std::vector<std::string> viscous, free_field;
};
BoundarySides3 read_viscous_sides3(const YamlNode& root);
void add_viscous_boundary3(const YamlNode& root, const PolyhedronModel& blocks, const std::string& blocks_path,
                           Model3& m);

}  // namespace dda::df3
