#pragma once
// Candidate pairs of 3D blocks for contact detection: those whose bounding
// boxes, each grown by a margin, overlap. The uniform grid of the 2D broad
// phase (broad_phase.hpp) in three dimensions: linear in the number of
// blocks for blocks of similar size, and a large block (a base) just covers
// many cells.
#include <utility>
#include <vector>

#include "dda/common/geometry3d.hpp"

namespace dda::df3 {

// Pairs (i, j), i < j, sorted, whose boxes overlap after each box is grown by
// `margin` on every side. The same for any number of OpenMP threads.
std::vector<std::pair<int, int>> broad_phase3(const std::vector<Box3>& boxes, double margin);

}  // namespace dda::df3
