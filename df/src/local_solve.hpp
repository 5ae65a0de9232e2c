#pragma once
// Conjugate gradients on a few blocks of the step system, the others held
// where they are: K_RR x_R = r_R for a set R of blocks (the contact clusters
// of contact_clusters.cpp). Internal to df/src.
//
// Requirements: `sys` holds the current K (the lower triangle, as
// BlockSystem keeps it; multiply() has been called on it since its last
// reset, as every global solve does); `r` and `x` are full-length vectors
// read and written on the blocks of `region` only, and x is zero on the
// other blocks (it is the work vector of the products). Serial: a cluster is
// small, and the sums are then in one fixed order whatever the threads.
#include <vector>

#include <Eigen/Core>

#include "dda/df/block_system.hpp"

namespace dda::df {

struct LocalSolveResult {
  int iterations = 0;
  bool converged = false;
};

// Block-Jacobi preconditioned CG from x = 0 on the blocks of `region`,
// until the preconditioned residual norm falls to `tolerance` times its
// start. Leaves the solution in x on the region.
LocalSolveResult solve_on_blocks(const BlockSystem& sys, const std::vector<int>& region, const Eigen::VectorXd& r,
                                 Eigen::VectorXd& x, double tolerance, int max_iterations);

}  // namespace dda::df
