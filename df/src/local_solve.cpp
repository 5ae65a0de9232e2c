// Conjugate gradients on a cluster of blocks (local_solve.hpp).
#include "local_solve.hpp"

#include <cmath>

#include "spd_inverse.hpp"

namespace dda::df {

LocalSolveResult solve_on_blocks(const BlockSystem& sys, const std::vector<int>& region, const Eigen::VectorXd& r,
                                 Eigen::VectorXd& x, double tolerance, int max_iterations) {
  const std::size_t n = region.size();
  std::vector<Matrix6d> inverse(n);
  for (std::size_t k = 0; k < n; ++k)
    if (!spd_inverse<kDofs>(sys.diagonal(region[k]), inverse[k])) return {};
  // The search direction lives in a full-length vector, zero off the
  // region, so that BlockSystem::multiply_row reads K_RR p alone.
  Eigen::VectorXd p = Eigen::VectorXd::Zero(x.size());
  std::vector<Vector6d> res(n), z(n), q(n);
  double rz = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const int b = region[k];
    x.segment<kDofs>(kDofs * b).setZero();
    res[k] = r.segment<kDofs>(kDofs * b);
    z[k] = inverse[k].selfadjointView<Eigen::Lower>() * res[k];
    p.segment<kDofs>(kDofs * b) = z[k];
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
      q[k] = sys.multiply_row(region[k], p);
      pq += p.segment<kDofs>(kDofs * region[k]).dot(q[k]);
    }
    if (!(pq > 0)) return out;  // not positive definite on the region: leave it to the global solve
    const double alpha = rz / pq;
    double rz_next = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const int b = region[k];
      x.segment<kDofs>(kDofs * b) += alpha * p.segment<kDofs>(kDofs * b);
      res[k] -= alpha * q[k];
      z[k] = inverse[k].selfadjointView<Eigen::Lower>() * res[k];
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
      auto pk = p.segment<kDofs>(kDofs * region[k]);
      pk = z[k] + beta * pk;
    }
  }
  return out;
}

}  // namespace dda::df
