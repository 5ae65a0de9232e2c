// 3D broad phase: the dimension-generic grid of broad_phase.cpp on Box3.
#include "dda/df/3d/broad_phase3d.hpp"

#include "dda/df/core/broad_phase.hpp"

namespace dda::df3 {

std::vector<std::pair<int, int>> broad_phase3(const std::vector<Box3>& boxes, double margin) {
  return df::grid_broad_phase(boxes, margin);
}

}  // namespace dda::df3
