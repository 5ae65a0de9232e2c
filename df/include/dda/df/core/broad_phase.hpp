#pragma once
// Candidate block pairs whose bounding boxes, enlarged by a margin, overlap.
//
// A uniform grid with one cell about the size of a typical enlarged box keeps
// the work linear in the number of blocks for blocks of similar size; very
// large blocks (a base, a plane) simply cover several cells.
#include <utility>
#include <vector>

#include "dda/common/geometry.hpp"

namespace dda::df {

// Pairs (i, j), i < j, sorted, whose boxes overlap after each box is grown by
// `margin` on every side.
std::vector<std::pair<int, int>> broad_phase(const std::vector<Box2>& boxes, double margin);

// The same grid in any dimension: Box has Eigen vectors `lo` and `hi`.
// Instantiated for Box2 (above) and Box3 (df3::broad_phase3, broad_phase3d.hpp).
template <class Box>
std::vector<std::pair<int, int>> grid_broad_phase(const std::vector<Box>& boxes, double margin);

}  // namespace dda::df
