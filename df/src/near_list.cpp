// Near pairs kept between steps while no vertex has moved half the skin.
#include "dda/df/near_list.hpp"

#include "dda/df/block_system.hpp"
#include "dda/df/broad_phase.hpp"

namespace dda::df {

bool NearList::still_valid(const std::vector<Polygon2>& blocks, double search_distance) const {
  if (search_distance != search_distance_ || blocks.size() != anchor_.size()) return false;
  const double half_skin = 0.5 * skin_factor_ * search_distance;
  const double limit = half_skin * half_skin;
  const int n = static_cast<int>(blocks.size());
  int moved = 0;  // blocks with a vertex past half the skin, or another vertex count
#pragma omp parallel for schedule(static) reduction(+ : moved) if (n > parallel_grain())
  for (int b = 0; b < n; ++b) {
    const Polygon2& now = blocks[b];
    const Polygon2& then = anchor_[b];
    if (now.size() != then.size()) {
      ++moved;
      continue;
    }
    for (std::size_t v = 0; v < now.size(); ++v)
      if ((now[v] - then[v]).squaredNorm() > limit) {
        ++moved;
        break;
      }
  }
  return moved == 0;
}

const NearPairs& NearList::update(const std::vector<Polygon2>& blocks, double search_distance) {
  if (still_valid(blocks, search_distance)) return near_;
  const double reach = (1 + skin_factor_) * search_distance;
  const int n = static_cast<int>(blocks.size());
  std::vector<Box2> boxes(blocks.size());
  anchor_.resize(blocks.size());
#pragma omp parallel for schedule(static) if (n > parallel_grain())
  for (int b = 0; b < n; ++b) {
    boxes[b] = bounding_box(blocks[b]);
    anchor_[b] = blocks[b];
  }
  // A vertex within reach of an edge of another block lies within reach of
  // that block's box: the boxes, each grown by half of it, overlap.
  near_ = near_pairs(blocks, boxes, broad_phase(boxes, 0.5 * reach), reach);
  search_distance_ = search_distance;
  ++searches_;
  return near_;
}

}  // namespace dda::df
