#pragma once
// Measurement points the scenario places on a block: `points` items with a
// `block` key instead of (or besides) a position (docs/scenario.md,
// "points"). A block is named by its id in the blocks file or by a
// selection (the block containing a point; in 3D also a body, a level, a
// box or a block-theory class, as `fixed` selects), and the point starts at
// the block's centroid or at the item's `at`. Block ids exist only once DC
// has cut the blocks, so DF places these points on the blocks file it runs,
// in 2D and 3D alike, with this one reader. Private to DF.
#include <functional>
#include <string>
#include <vector>

#include "dda/common/yaml_reader.hpp"

namespace dda::df {

// A measurement point placed on a block.
template <class Vec>
struct BlockPoint {
  std::string name;
  int block = -1;  // index in the blocks file
  Vec position;    // where the material point starts (m)
};

// What placing a point needs to know of the blocks of one dimension.
template <class Vec>
struct BlockCatalogue {
  std::string path;        // the blocks file, for messages
  std::size_t count = 0;   // number of blocks
  // The blocks' local origin (coordinate_range.hpp): `at` and `containing`
  // are given in the user's coordinates, the blocks and the positions
  // placed are about this origin.
  Vec origin = Vec::Zero();
  std::function<Vec(std::size_t)> centroid;
  // Block b holds p: inside it or on its boundary (within the model's
  // rounding tolerance).
  std::function<bool(std::size_t, const Vec&)> contains;
  // Selection keys besides `containing` (3D: bodies, below, box, outside,
  // removability; 2D: none), and the blocks such a selection mapping picks.
  std::vector<std::string> selection_keys;
  std::function<std::vector<bool>(const YamlNode&)> select;
};

// The `block` and `at` keys of the items of `points` that have a `block`,
// without blocks (so that `dda run` refuses them before cutting):
// `selection_keys` as in BlockCatalogue, `check_selection` reads such a
// selection mapping's values.
void check_block_points(const YamlNode& root, int dimension, const std::vector<std::string>& selection_keys,
                        const std::function<void(const YamlNode&)>& check_selection);

// Every item of `points` that has a `block`, placed on `blocks`, in file
// order. An id that does not exist, a selection that picks no block or more
// than one, an `at` outside the block, or a name already in `taken` (the
// points of the blocks file) is an InputError naming the item's key.
template <class Vec>
std::vector<BlockPoint<Vec>> place_block_points(const YamlNode& root, const BlockCatalogue<Vec>& blocks,
                                                const std::vector<std::string>& taken);

}  // namespace dda::df
