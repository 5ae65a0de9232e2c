#pragma once
// Conjugate gradients preconditioned by the inverse N x N diagonal blocks
// (block Jacobi), for the step systems of the 2D (N = 6) and 3D (N = 12)
// solvers. Internal to df/src: linear_solver_pcg.cpp wraps it into the
// LinearSolver choices.
//
// The operator is anything with
//   int blocks() const;
//   <N x N matrix> diagonal(int i) const;   // its lower triangle is read
//   void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y,
//                 const Eigen::Matrix<double, N, N>* symmetric_diagonal) const;
// (BlockSystem for 2D, LowerBlockCsc<12> for 3D), and optionally
//   void multiply_sweep(x, y, symmetric_diagonal, int first, int last, int chunk, done) const;
// the rows [first, last) of the product on the calling thread, calling
// done(lo, hi) on each chunk of rows once final (multiply_dot), and
//   <N-vector> multiply_row(int i, x, symmetric_diagonal) const;
// row i of the product alone (a trial solve's residual refreshed on the
// rows that changed, see Since).
//
// Determinism: every vector loop runs over fixed chunks of blocks; the dot
// products add the chunks' partial sums serially in chunk order, so the
// iterates are the same bit for bit with any number of OpenMP threads, as
// long as the operator's multiply is.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "dda/df/core/block_system.hpp"  // parallel_grain, thread_share
#include "core/spd_inverse.hpp"

namespace dda::df {

template <int N>
class BlockJacobiPcg {
 public:
  using Block = Eigen::Matrix<double, N, N>;
  using Segment = Eigen::Matrix<double, N, 1>;

  explicit BlockJacobiPcg(int max_iterations) : max_iterations_(max_iterations) {}

  long iterations() const { return iterations_; }
  // Solves that took the last one's residual over, and the rows they formed
  // afresh, summed (see Since).
  long residuals_kept() const { return residuals_kept_; }
  long rows_refreshed() const { return rows_refreshed_; }

  // What a solve may take over from the last one, when that one converged.
  // `changed` (one flag per block) marks the block rows in which the
  // operator and b may differ from the last solve's; in the others they
  // are the same, so the inverses of their diagonal blocks and their
  // terms of |b| are kept (bit for bit what they would be recomputed as).
  // With `residual` as well, x is the solution the last solve returned, and
  // the residual b - op x is formed afresh on the changed rows only and
  // taken over from the last solve's recursion on the others: no product
  // over the whole operator. The recursion drifts from b - op x by
  // rounding, so this is for trial solves (their tolerance is 1e-6). The
  // operator's pattern must be the last solve's (a BlockSystem with no
  // couplings added outside it since: the product sweeps it as it is).
  struct Since {
    const std::vector<std::uint8_t>* changed = nullptr;
    bool residual = false;
  };

  // Solves op x = b starting from x, until the preconditioned residual norm
  // sqrt(r' M^-1 r) falls to `tolerance` times that of b; true on
  // convergence. False also when a diagonal block or the operator is not
  // positive definite (in floating point): a direct solver then decides.
  template <class Op>
  bool solve(const Op& op, const Eigen::VectorXd& b, Eigen::VectorXd& x, double tolerance, const Since& since = {}) {
    const int nb = op.blocks();
    const Eigen::Index n = x.size();
    const std::vector<std::uint8_t>* changed = kept_ && kept_size_ == n ? since.changed : nullptr;
    const bool reuse_residual = changed && since.residual && requires { op.multiply_row(0, x, diagonal_.data()); };
    kept_ = false;
    if (!precondition(op, changed)) return false;
    r_.resize(n);
    z_.resize(n);
    p_.resize(n);
    q_.resize(n);
    const int chunks = (nb + kChunkBlocks - 1) / kChunkBlocks;
    if (changed) {
      chunk_changed_.assign(static_cast<std::size_t>(chunks), 0);
      long rows = 0;
      for (int i = 0; i < nb; ++i)
        if ((*changed)[i]) {
          chunk_changed_[i / kChunkBlocks] = 1;
          ++rows;
        }
      if (reuse_residual) {
        ++residuals_kept_;
        rows_refreshed_ += rows;
      }
    }
    // |b|_M^-1, by chunks kept for the next solve (only those holding a
    // changed row are summed again), with q as scratch.
    const double bb = chunked(
        nb,
        [&](int lo, int hi) {
          double s = 0;
          for (int i = lo; i < hi; ++i) {
            apply(b, q_, i);
            s += b.template segment<N>(N * i).dot(q_.template segment<N>(N * i));
          }
          return s;
        },
        bb_partial_, changed ? &chunk_changed_ : nullptr);
    if (!(bb > 0)) {
      x.setZero();
      return std::isfinite(bb);
    }
    const double target = tolerance * tolerance * bb;
    // The starting residual r = b - op x and z = M^-1 r: from a product over
    // all of op, or taken over from the last solve, which left them for the
    // same x, and formed afresh on the changed rows only (on the others b,
    // op's row and M's block are those of then).
    if (!reuse_residual) op.multiply(x, q_, diagonal_.data());
    double rz = chunked(nb, [&](int lo, int hi) {
      double s = 0;
      for (int i = lo; i < hi; ++i) {
        const Eigen::Index a = N * i;
        if (!reuse_residual) {
          r_.template segment<N>(a) = b.template segment<N>(a) - q_.template segment<N>(a);
          apply(r_, z_, i);
        } else if ((*changed)[i]) {
          r_.template segment<N>(a) = b.template segment<N>(a) - row_product(op, i, x);
          apply(r_, z_, i);
        }
        p_.template segment<N>(a) = z_.template segment<N>(a);
        s += r_.template segment<N>(a).dot(z_.template segment<N>(a));
      }
      return s;
    });
    for (int it = 0;; ++it) {
      if (rz <= target) {
        kept_ = true;  // r = b - op x (by the recursion) and z = M^-1 r, for the next solve
        kept_size_ = n;
        return true;
      }
      if (!std::isfinite(rz) || it == max_iterations_) return false;
      const double pq = multiply_dot(op);
      if (!(pq > 0)) return false;  // breakdown: not SPD in floating point
      const double alpha = rz / pq;
      const double rz_new = chunked(nb, [&](int lo, int hi) {
        const Eigen::Index a = N * lo, len = N * (hi - lo);
        x.segment(a, len) += alpha * p_.segment(a, len);
        r_.segment(a, len) -= alpha * q_.segment(a, len);
        for (int i = lo; i < hi; ++i) apply(r_, z_, i);
        return r_.segment(a, len).dot(z_.segment(a, len));
      });
      const double beta = rz_new / rz;
      rz = rz_new;
      ++iterations_;
      chunked(nb, [&](int lo, int hi) {
        const Eigen::Index a = N * lo, len = N * (hi - lo);
        p_.segment(a, len) = z_.segment(a, len) + beta * p_.segment(a, len);
        return 0.0;
      });
    }
  }

 private:
  static constexpr int kChunkBlocks = 32;  // blocks per chunk of the vector loops (fixed: it sets the sum order)

  void apply(const Eigen::VectorXd& v, Eigen::VectorXd& out, int i) const {
    out.template segment<N>(N * i).noalias() = inverse_[i].lazyProduct(v.template segment<N>(N * i));  // unrolled
  }

  // Symmetric diagonal blocks and their inverses; false if one is not
  // positive definite. A block equal to the one of the last solve keeps its
  // inverse (most do from one open-close iterate to the next); with
  // `changed`, only the flagged blocks are compared (the others are the
  // last solve's).
  template <class Op>
  bool precondition(const Op& op, const std::vector<std::uint8_t>* changed) {
    const int nb = op.blocks();
    if (static_cast<int>(diagonal_.size()) != nb) {
      diagonal_.assign(nb, Block::Constant(std::numeric_limits<double>::quiet_NaN()));
      inverse_.resize(nb);
      changed = nullptr;
    }
    int bad = 0;
#pragma omp parallel for schedule(static) reduction(+ : bad) if (nb > parallel_grain())
    for (int i = 0; i < nb; ++i) {
      if (changed && !(*changed)[i]) continue;
      const Block d = Block(op.diagonal(i)).template selfadjointView<Eigen::Lower>();
      if (d == diagonal_[i]) continue;
      diagonal_[i] = d;
      if (!spd_inverse<N>(d, inverse_[i])) {
        ++bad;
        diagonal_[i].setConstant(std::numeric_limits<double>::quiet_NaN());  // never matches
        inverse_[i].setIdentity();
      }
    }
    return bad == 0;
  }

  // q = op p, and p . q (summed in chunk order). An operator that can
  // multiply a range of block rows on the calling thread (multiply_sweep:
  // BlockSystem) does both in one parallel region, each chunk's dot right
  // after its rows are final, while they are in cache: one pass over p and
  // q and one barrier fewer per iteration, with the same numbers. Each
  // thread takes a run of whole chunks, as a static schedule would. (solve()
  // calls op.multiply() once before, as multiply_sweep() asks.)
  template <class Op>
  double multiply_dot(const Op& op) {
    const int nb = op.blocks();
    auto dot = [&](int lo, int hi) {
      return p_.segment(N * lo, N * (hi - lo)).dot(q_.segment(N * lo, N * (hi - lo)));
    };
    if constexpr (requires { op.multiply_sweep(p_, q_, diagonal_.data(), 0, 0, 1, [](int, int) {}); }) {
      const int chunks = (nb + kChunkBlocks - 1) / kChunkBlocks;
      partial_.assign(static_cast<std::size_t>(chunks), 0.0);
#pragma omp parallel if (nb > parallel_grain() && chunks > 1)
      {
        const auto [c0, c1] = thread_share(chunks);
        op.multiply_sweep(p_, q_, diagonal_.data(), c0 * kChunkBlocks, std::min(nb, c1 * kChunkBlocks), kChunkBlocks,
                          [&](int lo, int hi) { partial_[lo / kChunkBlocks] = dot(lo, hi); });
      }
      double sum = 0;
      for (const double v : partial_) sum += v;
      return sum;
    } else {
      op.multiply(p_, q_, diagonal_.data());
      return chunked(nb, dot);
    }
  }

  // Runs body(lo, hi) over chunks of blocks in parallel and returns the sum
  // of its results, added in chunk order. Each chunk's result is left in
  // `partial`; with `only`, only the flagged chunks run and the others keep
  // the result they had.
  template <class Body>
  double chunked(int nb, Body&& body, std::vector<double>& partial, const std::vector<std::uint8_t>* only = nullptr) {
    const int chunks = (nb + kChunkBlocks - 1) / kChunkBlocks;
    partial.resize(static_cast<std::size_t>(chunks));
#pragma omp parallel for schedule(static) if (nb > parallel_grain() && chunks > 1)
    for (int c = 0; c < chunks; ++c)
      if (!only || (*only)[c]) partial[c] = body(c * kChunkBlocks, std::min(nb, (c + 1) * kChunkBlocks));
    double sum = 0;
    for (const double v : partial) sum += v;
    return sum;
  }
  template <class Body>
  double chunked(int nb, Body&& body) {
    return chunked(nb, std::forward<Body>(body), partial_);
  }

  // Row i of op x, for an operator that gives single rows (reuse_residual
  // is false for the others, so this is not reached for them).
  template <class Op>
  Segment row_product(const Op& op, int i, const Eigen::VectorXd& x) const {
    if constexpr (requires { op.multiply_row(i, x, diagonal_.data()); }) {
      return op.multiply_row(i, x, diagonal_.data());
    } else {
      return Segment::Constant(std::numeric_limits<double>::quiet_NaN());
    }
  }

  int max_iterations_;
  long iterations_ = 0, residuals_kept_ = 0, rows_refreshed_ = 0;
  std::vector<Block> diagonal_, inverse_;
  std::vector<double> partial_, bb_partial_;
  std::vector<std::uint8_t> chunk_changed_;
  bool kept_ = false;  // the last solve converged: r_, z_, bb_partial_ and the inverses are its own
  Eigen::Index kept_size_ = 0;
  Eigen::VectorXd r_, z_, p_, q_;
};

}  // namespace dda::df
