#pragma once
// Pieces of the 3D scenario reader (scenario3d.hpp) shared by its files;
// private to DF.
#include <optional>
#include <string>
#include <vector>

#include "dda/common/polyhedron_model.hpp"
#include "dda/common/yaml_reader.hpp"
#include "dda/df/points3d.hpp"

namespace dda::df3 {

// [x, y, z], finite.
Vec3 read_vec3(const YamlNode& n, const std::string& key);
// [[t, x, y, z], ...], at least one row, t strictly increasing.
History3 read_history3(const YamlNode& n, const std::string& key);

// The `fixed` section: which blocks are held (a union of selections, each
// of which must select something) and settings of named fixed points.
struct FixedSpec3 {
  std::optional<YamlNode> node;                      // `fixed`, if given
  std::vector<std::pair<YamlNode, long long>> blocks;  // fixed.blocks items
  std::vector<std::pair<YamlNode, long long>> bodies;  // fixed.bodies items
  std::optional<double> below;                       // m: centroid z below this
  std::optional<Box3> box;                           // centroid inside
  std::optional<Box3> outside;                       // centroid outside
  std::vector<std::pair<YamlNode, Removability>> removability;  // bodies of these classes
  struct Point {
    YamlNode node;
    std::string point;
    double penalty = 0;  // 0: the default
    std::optional<History3> displacement;
  };
  std::vector<Point> points;
};

FixedSpec3 read_fixed3(const YamlNode& root);

// One flag per block of `blocks`: held fixed. A selection that selects no
// block, an id that does not exist, or fixing every block is an error
// naming the key.
std::vector<bool> select_fixed_blocks(const FixedSpec3& spec, const PolyhedronModel& blocks,
                                      const std::string& blocks_path);

}  // namespace dda::df3
