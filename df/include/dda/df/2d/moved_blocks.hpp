#pragma once
// Which blocks' solutions moved between the open-close iterates of a step,
// so that a trial iterate updates only the contacts that can have changed.
//
// Why: after the first iterates of a transient step only a few hundred of
// tens of thousands of contacts change state, and a trial solve moves most
// blocks by far less than the open-close dead band (on the 10k-block
// layered model, 64-95 % of the blocks by less than 1e-13 m from one trial
// iterate to the next). Updating every contact after every solve was a
// sixth of the step.
//
// The test: a block counts as moved when some point within its radius R
// (the farthest vertex from its centroid) may have moved more than
// `tolerance` since the block was last marked moved. With the 2D DDA
// displacement field, a point at arm (x, y) moves by
//   u = d1 - y d3 + x d4 + y d6 / 2,  v = d2 + x d3 + y d5 + x d6 / 2,
// so |du| + |dv| <= |dd1| + |dd2| + R (2 |dd3| + |dd4| + |dd5| + |dd6|)
// bounds the change of every point of the block, and a contact's distances
// change by at most a few times the changes of its two blocks. A block not
// marked keeps its reference, so the change is measured against the
// solution its contacts were last updated with and cannot creep past the
// tolerance in many small steps.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "dda/df/core/types.hpp"

namespace dda::df {

class MovedBlocks {
 public:
  // A new step or attempt: the blocks' radii (m), one per block; every
  // block counts as moved until the first mark().
  void start(std::vector<double> radii);
  // Compares the solution d (6 per block) with each block's reference. With
  // `all`, or for a block whose change may exceed `tolerance` (m), the
  // block is marked moved and its reference becomes d; the others are
  // unmarked and keep their reference.
  void mark(const Eigen::VectorXd& d, double tolerance, bool all);
  bool moved(int block) const { return moved_[static_cast<std::size_t>(block)] != 0; }
  int moved_count() const;

  // The bound above on how far any point of a block of radius r moves
  // under the change `change` of its six unknowns.
  static double point_bound(const Vector6d& change, double r);

 private:
  std::vector<double> radii_;
  std::vector<std::uint8_t> moved_;
  Eigen::VectorXd reference_;
};

}  // namespace dda::df
