// Near pairs kept between steps while no vertex has moved half the skin.
#include "dda/df/2d/near_list.hpp"

#include "dda/df/core/block_system.hpp"
#include "dda/df/core/broad_phase.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dda::df {

double NearList::drift(const std::vector<Polygon2>& blocks, double search_distance) const {
  constexpr double kInvalid = std::numeric_limits<double>::infinity();
  if (search_distance != search_distance_ || blocks.size() != anchor_.size()) return kInvalid;
  const double half_skin = 0.5 * skin_factor_ * search_distance;
  const int n = static_cast<int>(blocks.size());
  double worst = 0;  // squared; a changed vertex count counts as infinite
#pragma omp parallel for schedule(static) reduction(max : worst) if (n > parallel_grain())
  for (int b = 0; b < n; ++b) {
    const Polygon2& now = blocks[b];
    const Polygon2& then = anchor_[b];
    if (now.size() != then.size()) {
      worst = kInvalid;
      continue;
    }
    for (std::size_t v = 0; v < now.size(); ++v) worst = std::max(worst, (now[v] - then[v]).squaredNorm());
  }
  return worst > half_skin * half_skin ? kInvalid : std::sqrt(worst);
}

const NearPairs& NearList::update(const std::vector<Polygon2>& blocks, double search_distance, double moved) {
  // The bounds add up (a vertex's distance from where it was is at most the
  // sum of its moves); kept a percent short of half the skin, so rounding
  // in the bounds cannot matter, and past that the vertices decide.
  const double half_skin = 0.5 * skin_factor_ * search_distance;
  if (search_distance == search_distance_ && blocks.size() == anchor_.size() && drift_bound_ + moved < 0.99 * half_skin) {
    drift_bound_ += moved;
    return near_;
  }
  drift_bound_ = drift(blocks, search_distance);
  ++checks_;
  if (drift_bound_ <= half_skin) return near_;
  drift_bound_ = 0;
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
