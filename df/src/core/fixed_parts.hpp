#pragma once
// A sum over many terms, each adding into a few entries of a vector, made
// the same bit for bit on any number of threads: the terms are cut into a
// fixed number of parts, each part adds its terms in order into its own
// copy of the vector, and the copies are added entry by entry in part
// order. (The PCG products of the 3D solver: lower_block_csc.hpp and
// contact_coupling3d.hpp.)
//
// Internal to df/src.
#include <Eigen/Core>

namespace dda::df {

// y = (or, with `accumulate`, y +=) the sum of what body(part, y_part) adds
// into y_part, a zeroed vector of y's size, for part = 0 .. parts - 1.
// `partial` is scratch (n x parts), kept by the caller between calls.
template <class Body>
void sum_in_fixed_parts(int parts, Eigen::MatrixXd& partial, Eigen::VectorXd& y, bool accumulate, bool parallel,
                        Body&& body) {
  const Eigen::Index n = y.size();
  partial.resize(n, parts);
#pragma omp parallel for schedule(dynamic, 1) if (parallel)
  for (int part = 0; part < parts; ++part) {
    auto yp = partial.col(part);
    yp.setZero();
    body(part, yp);
  }
#pragma omp parallel for schedule(static) if (parallel)
  for (Eigen::Index i = 0; i < n; ++i) {
    double sum = 0;
    for (int part = 0; part < parts; ++part) sum += partial(i, part);
    y[i] = accumulate ? y[i] + sum : sum;
  }
}

}  // namespace dda::df
