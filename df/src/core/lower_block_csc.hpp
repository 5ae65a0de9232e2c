#pragma once
// A view of a symmetric matrix of N x N blocks given by its lower triangle in
// compressed column form, laid out as the 3D solver assembles it
// (block_lower_pattern in simulation3d_assembly.hpp): the columns of block
// column b hold first the lower part of the diagonal block (column c: rows
// N b + c .. N b + N - 1), then, for each coupled block r > b in increasing
// order, its N rows N r .. N r + N - 1. Each column of an off-diagonal block
// is thus N contiguous values, which the product below reads as a fixed-size
// vector. The view gives block-Jacobi PCG (block_pcg.hpp) its operator
// without copying K into another format.
//
// Internal to df/src.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <algorithm>
#include <vector>

#include "dda/common/error.hpp"
#include "dda/df/core/block_system.hpp"  // parallel_grain
#include "core/fixed_parts.hpp"

namespace dda::df {

template <int N>
class LowerBlockCsc {
 public:
  using Block = Eigen::Matrix<double, N, N>;
  using Segment = Eigen::Matrix<double, N, 1>;

  // Reads `lower` from now on (it must outlive the calls); the index is
  // rebuilt only when its pattern differs from the last one bound. False if
  // the matrix does not have the layout above (the view is then unusable).
  // `coupling_blocks`: multiply() will read the blocks off the diagonal
  // (false: only multiply_diagonal() and diagonal() are used, and the scan
  // for all-zero blocks, a read of all of K, is skipped).
  bool bind(const Eigen::SparseMatrix<double>& lower, bool coupling_blocks = true) {
    matrix_ = &lower;
    if (!same_pattern(lower)) valid_ = build(lower);
    coupling_blocks_ready_ = false;
    if (valid_ && coupling_blocks) {
      find_nonzero_blocks();
      coupling_blocks_ready_ = true;
    }
    return valid_;
  }

  int blocks() const { return blocks_; }

  // The diagonal block of block i; its lower triangle (upper: zero).
  Block diagonal(int i) const {
    Block d = Block::Zero();
    const double* values = matrix_->valuePtr();
    const int* outer = matrix_->outerIndexPtr();
    for (int c = 0; c < N; ++c)
      for (int r = c; r < N; ++r) d(r, c) = values[outer[N * i + c] + r - c];
    return d;
  }

  // y = K x. `symmetric_diagonal`, if given, holds the diagonal blocks made
  // symmetric. Each stored block is read once, for both its product and its
  // transpose's: the product is bound by memory traffic, and K's blocks
  // (100 MB at 10,000 blocks) do not stay in cache from one half to the
  // other. The block columns are cut into kParts fixed ranges
  // (sum_in_fixed_parts), so the result does not depend on the number of
  // threads.
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y, const Block* symmetric_diagonal) const {
    if (!coupling_blocks_ready_) throw InternalError("LowerBlockCsc::multiply: bound without its coupling blocks");
    const double* values = matrix_->valuePtr();
    const int* outer = matrix_->outerIndexPtr();
    const int nb = blocks_;
    y.resize(static_cast<Eigen::Index>(N) * nb);
    sum_in_fixed_parts(kParts, partial_, y, /*accumulate=*/false, nb > parallel_grain(), [&](int part, auto yp) {
      for (int b = part_start_[part]; b < part_start_[part + 1]; ++b) {
        const auto xb = x.template segment<N>(N * b);
        Segment acc;
        // lazyProduct: unrolled; a plain 12x12 product goes through Eigen's
        // general matrix-vector kernel, whose set-up costs more than it.
        if (symmetric_diagonal) {
          acc.noalias() = symmetric_diagonal[b].lazyProduct(xb);
        } else {
          const Block d = diagonal(b).template selfadjointView<Eigen::Lower>();
          acc.noalias() = d.lazyProduct(xb);
        }
        for (int k = below_start_[b]; k < below_start_[b + 1]; ++k) {
          if (!nonzero_[k]) continue;
          const int r = below_row_[k], rank = k - below_start_[b];
          const auto xr = x.template segment<N>(N * r);
          Segment to_r = Segment::Zero();
          for (int c = 0; c < N; ++c) {
            const Eigen::Map<const Segment> column(values + outer[N * b + c] + (N - c) + N * rank);
            acc[c] += column.dot(xr);  // (B^T x_r)_c
            to_r.noalias() += xb[c] * column;  // B x_b
          }
          yp.template segment<N>(N * r) += to_r;
        }
        yp.template segment<N>(N * b) += acc;
      }
    });
  }

  // (K x) on block i alone: its diagonal block, the blocks below it in its
  // block column (transposed) and the blocks left of it in its block row
  // (stored in the columns of the blocks above it, found through the row
  // index built with the pattern). For the solves on contact clusters
  // (local_solve.hpp), which read a few rows of K.
  Segment multiply_row(int i, const Eigen::VectorXd& x) const {
    const double* values = matrix_->valuePtr();
    const int* outer = matrix_->outerIndexPtr();
    const Block d = diagonal(i).template selfadjointView<Eigen::Lower>();
    Segment acc = d.lazyProduct(x.template segment<N>(N * i));
    for (int k = below_start_[i]; k < below_start_[i + 1]; ++k) {
      const auto xr = x.template segment<N>(N * below_row_[k]);
      const int rank = k - below_start_[i];
      for (int c = 0; c < N; ++c)
        acc[c] += Eigen::Map<const Segment>(values + outer[N * i + c] + (N - c) + N * rank).dot(xr);
    }
    for (int k = left_start_[i]; k < left_start_[i + 1]; ++k) {
      const int j = left_column_[k], rank = left_rank_[k];
      const auto xj = x.template segment<N>(N * j);
      for (int c = 0; c < N; ++c)
        acc.noalias() += xj[c] * Eigen::Map<const Segment>(values + outer[N * j + c] + (N - c) + N * rank);
    }
    return acc;
  }

  // y = D x, D the block diagonal (symmetric_diagonal: as in multiply).
  void multiply_diagonal(const Eigen::VectorXd& x, Eigen::VectorXd& y, const Block* symmetric_diagonal) const {
    const int nb = blocks_;
    y.resize(static_cast<Eigen::Index>(N) * nb);
#pragma omp parallel for schedule(static) if (nb > parallel_grain())
    for (int b = 0; b < nb; ++b) {
      const auto xb = x.template segment<N>(N * b);
      if (symmetric_diagonal) {
        y.template segment<N>(N * b).noalias() = symmetric_diagonal[b].lazyProduct(xb);
      } else {
        const Block d = diagonal(b).template selfadjointView<Eigen::Lower>();
        y.template segment<N>(N * b).noalias() = d.lazyProduct(xb);
      }
    }
  }

 private:
  // Which coupled blocks hold a value other than zero. The pattern keeps the
  // pairs of open contacts too (so that CHOLMOD keeps its analysis), whose
  // blocks are zero: the product skips them, which saves reading them on
  // every iteration for one read here. (Skipping exact zeros changes no
  // sum, as long as x is finite.)
  void find_nonzero_blocks() {
    const double* values = matrix_->valuePtr();
    const int* outer = matrix_->outerIndexPtr();
    nonzero_.resize(below_row_.size());
#pragma omp parallel for schedule(static) if (blocks_ > parallel_grain())
    for (int b = 0; b < blocks_; ++b)
      for (int k = below_start_[b]; k < below_start_[b + 1]; ++k) {
        const int rank = k - below_start_[b];
        bool any = false;
        for (int c = 0; c < N && !any; ++c)
          any = (Eigen::Map<const Segment>(values + outer[N * b + c] + (N - c) + N * rank).array() != 0).any();
        nonzero_[k] = any;
      }
  }

  // Same outer array and the same coupled blocks in every block column.
  bool same_pattern(const Eigen::SparseMatrix<double>& m) const {
    if (!valid_ || !m.isCompressed() || m.rows() != static_cast<Eigen::Index>(N) * blocks_ ||
        m.cols() != m.rows() || m.nonZeros() != nonzeros_)
      return false;
    const int* outer = m.outerIndexPtr();
    if (!std::equal(outer, outer + m.cols() + 1, outer_.begin())) return false;
    const int* inner = m.innerIndexPtr();
    for (int b = 0; b < blocks_; ++b)
      for (int k = below_start_[b]; k < below_start_[b + 1]; ++k)
        if (inner[outer[N * b] + N + N * (k - below_start_[b])] != N * below_row_[k]) return false;
    return true;
  }

  bool build(const Eigen::SparseMatrix<double>& m) {
    blocks_ = 0;
    if (!m.isCompressed() || m.rows() != m.cols() || m.rows() % N != 0) return false;
    const int nb = static_cast<int>(m.rows() / N);
    const int* outer = m.outerIndexPtr();
    const int* inner = m.innerIndexPtr();
    below_start_.assign(1, 0);
    below_row_.clear();
    for (int b = 0; b < nb; ++b) {
      const int first = outer[N * b];
      const int count = outer[N * b + 1] - first - N;  // rows below the diagonal block
      if (count < 0 || count % N != 0) return false;
      const int neighbours = count / N;
      for (int c = 0; c < N; ++c) {
        const int start = outer[N * b + c];
        if (outer[N * b + c + 1] - start != (N - c) + count) return false;
        for (int r = c; r < N; ++r)
          if (inner[start + r - c] != N * b + r) return false;
        for (int k = 0; k < neighbours; ++k) {
          const int* rows = inner + start + (N - c) + N * k;
          if (rows[0] % N != 0 || rows[0] <= N * b || (k > 0 && rows[0] <= rows[-N])) return false;
          if (c > 0 && rows[0] != inner[first + N + N * k]) return false;
          for (int r = 1; r < N; ++r)
            if (rows[r] != rows[0] + r) return false;
        }
      }
      for (int k = 0; k < neighbours; ++k) below_row_.push_back(inner[first + N + N * k] / N);
      below_start_.push_back(static_cast<int>(below_row_.size()));
    }
    // The row index: for each block row, the block columns left of the
    // diagonal that store a block of it, and that block's rank there.
    left_start_.assign(static_cast<std::size_t>(nb) + 1, 0);
    for (const int r : below_row_) ++left_start_[r + 1];
    for (int b = 0; b < nb; ++b) left_start_[b + 1] += left_start_[b];
    left_column_.resize(below_row_.size());
    left_rank_.resize(below_row_.size());
    {
      std::vector<int> at(left_start_.begin(), left_start_.end() - 1);
      for (int b = 0; b < nb; ++b)
        for (int k = below_start_[b]; k < below_start_[b + 1]; ++k) {
          const int slot = at[below_row_[k]]++;
          left_column_[slot] = b;
          left_rank_[slot] = k - below_start_[b];
        }
    }
    // Parts of about equal stored blocks (the diagonal ones counted too).
    part_start_.assign(1, 0);
    const double per_part = static_cast<double>(nb + below_row_.size()) / kParts;
    for (int b = 0, part = 1; b < nb && part < kParts; ++b)
      if (static_cast<double>(b + 1 + below_start_[b + 1]) >= per_part * part) {
        part_start_.push_back(b + 1);
        ++part;
      }
    while (static_cast<int>(part_start_.size()) <= kParts) part_start_.push_back(nb);
    outer_.assign(outer, outer + m.cols() + 1);
    nonzeros_ = m.nonZeros();
    blocks_ = nb;
    return true;
  }

  static constexpr int kParts = 8;  // fixed: it sets the summation order
  const Eigen::SparseMatrix<double>* matrix_ = nullptr;
  bool valid_ = false;
  bool coupling_blocks_ready_ = false;  // bound for multiply(): nonzero_ is current
  int blocks_ = 0;
  Eigen::Index nonzeros_ = 0;
  std::vector<int> outer_;
  std::vector<int> below_start_{0}, below_row_;         // per block column: coupled blocks below
  std::vector<int> left_start_{0}, left_column_, left_rank_;  // per block row: coupled blocks left of it
  std::vector<char> nonzero_;                            // per coupled block: not all zero (find_nonzero_blocks)
  std::vector<int> part_start_;                          // kParts + 1 block columns
  mutable Eigen::MatrixXd partial_;                      // y of each part
};

}  // namespace dda::df
