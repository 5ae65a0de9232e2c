// Blocks whose solution moved between open-close iterates (moved_blocks.hpp).
#include "dda/df/2d/moved_blocks.hpp"

#include <cmath>
#include <utility>

#include "dda/df/core/block_system.hpp"  // parallel_grain

namespace dda::df {

void MovedBlocks::start(std::vector<double> radii) {
  radii_ = std::move(radii);
  moved_.assign(radii_.size(), 1);
  reference_.resize(0);  // the first mark() takes every block
}

double MovedBlocks::point_bound(const Vector6d& change, double r) {
  const Vector6d a = change.cwiseAbs();
  return a[0] + a[1] + r * (2 * a[2] + a[3] + a[4] + a[5]);
}

void MovedBlocks::mark(const Eigen::VectorXd& d, double tolerance, bool all) {
  const int nb = static_cast<int>(radii_.size());
  if (reference_.size() != d.size()) {
    reference_ = d;
    moved_.assign(radii_.size(), 1);
    return;
  }
#pragma omp parallel for schedule(static) if (nb > parallel_grain())
  for (int i = 0; i < nb; ++i) {
    auto ref = reference_.segment<kDofs>(kDofs * i);
    const auto now = d.segment<kDofs>(kDofs * i);
    // A NaN change counts as moved: the contact update then sees it.
    const bool m = all || !(point_bound(now - ref, radii_[i]) <= tolerance);
    moved_[i] = m;
    if (m) ref = now;
  }
}

int MovedBlocks::moved_count() const {
  int n = 0;
  for (const std::uint8_t m : moved_) n += m;
  return n;
}

}  // namespace dda::df
