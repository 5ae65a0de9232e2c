#pragma once
// The near pairs of a moving model, kept from step to step (a Verlet list).
//
// Finding which vertex lies near which edge means a broad phase over all
// blocks and a scan of every vertex of a pair against every edge. Once a
// model rests on its contacts the answer hardly changes from one step to the
// next, yet the contact search (this scan its largest part) was a quarter
// to a third of a step on a 10k-block layered model at rest
// (docs/solver2d.md). So the near pairs are found with a reach of the search
// distance plus a skin, and kept until some vertex has moved more than half
// the skin from where it was then.
//
// Kept that long, they still hold every vertex-edge pair within the search
// distance: the distance from a point to a segment changes by at most the
// point's displacement plus the larger of the ends' displacements, so a pair
// within the search distance now was within search distance + skin then.
// The contacts found from them are therefore the same as from a fresh
// search, bit for bit (a test checks it); only the time differs.
#include <limits>
#include <vector>

#include "dda/common/geometry.hpp"
#include "dda/df/2d/contact_detection.hpp"

namespace dda::df {

class NearList {
 public:
  // skin_factor: the skin as a multiple of the search distance.
  explicit NearList(double skin_factor = 1.0) : skin_factor_(skin_factor) {}

  // Near pairs holding every vertex-edge pair of `blocks` within
  // `search_distance`: the kept ones, or found afresh when a vertex moved
  // more than half the skin since they were found, the blocks or their
  // vertices changed in number, or the search distance changed.
  //
  // `moved`, if the caller knows it, bounds how far any vertex has moved
  // since the last update() and promises that the blocks and their vertex
  // counts are the same. While the bounds summed since the pairs were last
  // checked stay well within half the skin, nothing is read: checking every
  // vertex against where it was cost 1 ms a step on a 50k-block model at
  // rest, where the pairs hold for thousands of steps. The pairs kept, or
  // found afresh, are the same as without the bound.
  const NearPairs& update(const std::vector<Polygon2>& blocks, double search_distance,
                          double moved = std::numeric_limits<double>::infinity());

  // How many times update() searched afresh, and how many times it read
  // every vertex to see whether the pairs still hold (benchmarks, tests).
  long searches() const { return searches_; }
  long checks() const { return checks_; }

 private:
  // The largest distance a vertex has moved since the pairs were found, or
  // infinity when they no longer hold (moved half the skin or more, other
  // blocks or vertex counts, another search distance).
  double drift(const std::vector<Polygon2>& blocks, double search_distance) const;

  double skin_factor_;
  double search_distance_ = -1;
  double drift_bound_ = 0;  // how far a vertex may have moved since the pairs were found
  std::vector<Polygon2> anchor_;  // the vertices when the pairs were found
  NearPairs near_;
  long searches_ = 0, checks_ = 0;
};

}  // namespace dda::df
