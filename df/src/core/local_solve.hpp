#pragma once
// Conjugate gradients on a few blocks of the step system, the others held
// where they are: K_RR x_R = r_R for a set R of blocks (the contact clusters
// of contact_clusters.hpp), in 2D (6 unknowns a block) and 3D (12).
// Internal to df/src.
//
// Requirements on `Rows` (BlockSystem in 2D, LowerBlockCsc<12> in 3D):
//   Eigen::Matrix<double, N, N> diagonal(int b)      block b's diagonal block
//                                                    (its lower triangle is read)
//   Eigen::Matrix<double, N, 1> multiply_row(int b, const Eigen::VectorXd& x)
//                                                    (K x) on block b
// `r` and `x` are full-length vectors (block b's unknowns at N b) read and
// written on the blocks of `region` only, and x is zero on the other blocks
// (it is the work vector of the products). Serial: a cluster is small, and
// the sums are then in one fixed order whatever the threads.
#include <vector>

#include <Eigen/Core>

#include "core/spd_inverse.hpp"

namespace dda::df {

struct LocalSolveResult {
  int iterations = 0;
  bool converged = false;
};

// Block-Jacobi preconditioned CG from x = 0 on the blocks of `region`,
// until the preconditioned residual norm falls to `tolerance` times its
// start. Leaves the solution in x on the region.
template <int N, class Rows>
LocalSolveResult solve_on_blocks(const Rows& rows, const std::vector<int>& region, const Eigen::VectorXd& r,
                                 Eigen::VectorXd& x, double tolerance, int max_iterations) {
  using Block = Eigen::Matrix<double, N, N>;
  using Segment = Eigen::Matrix<double, N, 1>;
  const std::size_t n = region.size();
  std::vector<Block> inverse(n);
  for (std::size_t k = 0; k < n; ++k)
    if (!spd_inverse<N>(rows.diagonal(region[k]), inverse[k])) return {};
  // The search direction lives in a full-length vector, zero off the
  // region, so that multiply_row reads K_RR p alone.
  Eigen::VectorXd p = Eigen::VectorXd::Zero(x.size());
  std::vector<Segment> res(n), z(n), q(n);
  double rz = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const int b = region[k];
    x.template segment<N>(N * b).setZero();
    res[k] = r.template segment<N>(N * b);
    z[k] = inverse[k].template selfadjointView<Eigen::Lower>() * res[k];
    p.template segment<N>(N * b) = z[k];
    rz += res[k].dot(z[k]);
  }
  LocalSolveResult out;
  const double stop = tolerance * tolerance * rz;
  if (!(rz > 0)) {
    out.converged = rz == 0;
    return out;
  }
  for (out.iterations = 0; out.iterations < max_iterations; ++out.iterations) {
    double pq = 0;
    for (std::size_t k = 0; k < n; ++k) {
      q[k] = rows.multiply_row(region[k], p);
      pq += p.template segment<N>(N * region[k]).dot(q[k]);
    }
    if (!(pq > 0)) return out;  // not positive definite on the region: leave it to the global solve
    const double alpha = rz / pq;
    double rz_next = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const int b = region[k];
      x.template segment<N>(N * b) += alpha * p.template segment<N>(N * b);
      res[k] -= alpha * q[k];
      z[k] = inverse[k].template selfadjointView<Eigen::Lower>() * res[k];
      rz_next += res[k].dot(z[k]);
    }
    if (rz_next <= stop) {
      ++out.iterations;
      out.converged = true;
      return out;
    }
    const double beta = rz_next / rz;
    rz = rz_next;
    for (std::size_t k = 0; k < n; ++k) {
      auto pk = p.template segment<N>(N * region[k]);
      pk = z[k] + beta * pk;
    }
  }
  return out;
}

}  // namespace dda::df
