#pragma once
// The inverse of a small symmetric positive definite matrix (the 6 x 6 and
// 12 x 12 diagonal blocks of the block-Jacobi preconditioner), through its
// Cholesky factor A = L L^T: W = L^-1 by forward substitution, then
// A^-1 = W^T W. Internal to df/src.
//
// Why not Eigen::LLT<Matrix<N, N>>::solve(Identity): for a matrix right-hand
// side Eigen takes its blocked triangular-solve kernels (packing, general
// loop bounds) even at fixed size 6, and refactoring every diagonal block
// that way was 5 % of a step on a 49k-block model at rest, where every
// block changes every step. Fixed-size loops here do the same arithmetic
// in a fraction of the time; the rounding differs from Eigen's.
#include <cmath>

#include <Eigen/Core>

namespace dda::df {

// The lower triangle of `a` is read. False, with `inverse` unspecified, when
// a pivot is not positive (or not a number): not positive definite in
// floating point.
template <int N>
bool spd_inverse(const Eigen::Matrix<double, N, N>& a, Eigen::Matrix<double, N, N>& inverse) {
  // Cholesky, column by column: l(j, j) = sqrt(a(j, j) - sum l(j, k)^2),
  // l(i, j) = (a(i, j) - sum l(i, k) l(j, k)) / l(j, j) for i > j.
  double l[N][N] = {};
  for (int j = 0; j < N; ++j) {
    double pivot = a(j, j);
    for (int k = 0; k < j; ++k) pivot -= l[j][k] * l[j][k];
    if (!(pivot > 0)) return false;
    const double ljj = std::sqrt(pivot);
    l[j][j] = ljj;
    for (int i = j + 1; i < N; ++i) {
      double s = a(i, j);
      for (int k = 0; k < j; ++k) s -= l[i][k] * l[j][k];
      l[i][j] = s / ljj;
    }
  }
  // W = L^-1, lower triangular: W(j, j) = 1 / l(j, j) and, below it,
  // W(i, j) = -(sum_{k = j}^{i - 1} l(i, k) W(k, j)) / l(i, i).
  double w[N][N] = {};
  for (int j = 0; j < N; ++j) {
    w[j][j] = 1 / l[j][j];
    for (int i = j + 1; i < N; ++i) {
      double s = 0;
      for (int k = j; k < i; ++k) s += l[i][k] * w[k][j];
      w[i][j] = -s / l[i][i];
    }
  }
  // A^-1 = W^T W: entry (i, j) = sum over k >= max(i, j) of W(k, i) W(k, j).
  for (int j = 0; j < N; ++j)
    for (int i = j; i < N; ++i) {
      double s = 0;
      for (int k = i; k < N; ++k) s += w[k][i] * w[k][j];
      inverse(i, j) = s;
      inverse(j, i) = s;
    }
  return true;
}

}  // namespace dda::df
