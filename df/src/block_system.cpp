// 6x6 block storage of K and its compressed-column form.
#include "dda/df/block_system.hpp"

#include <algorithm>

namespace dda::df {

BlockSystem::BlockSystem(int blocks) { reset(blocks); }

void BlockSystem::reset(int blocks) {
  diag_.assign(blocks, Matrix6d::Zero());
  off_.clear();
  rhs_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(kDofs) * blocks);
}

void BlockSystem::add_coupling(int i, int j, const Matrix6d& kij) {
  if (i > j) {
    auto [it, fresh] = off_.try_emplace(key(i, j), kij);
    if (!fresh) it->second += kij;
  } else {
    auto [it, fresh] = off_.try_emplace(key(j, i), kij.transpose());
    if (!fresh) it->second += kij.transpose();
  }
}

Eigen::SparseMatrix<double> BlockSystem::lower() const {
  // Block column j holds the lower half of the diagonal block and the full
  // blocks (i, j), i > j, in increasing i: the row indices of every column
  // come out sorted, so the arrays are written directly.
  const int nb = blocks();
  std::vector<std::vector<std::pair<int, const Matrix6d*>>> cols(nb);
  for (const auto& [k, m] : off_) cols[static_cast<int>(k & 0xffffffffu)].emplace_back(static_cast<int>(k >> 32), &m);
  std::size_t nnz = static_cast<std::size_t>(nb) * 21;
  for (auto& c : cols) {
    std::sort(c.begin(), c.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    nnz += c.size() * 36;
  }
  const int n = kDofs * nb;
  Eigen::SparseMatrix<double> a(n, n);
  a.resizeNonZeros(static_cast<Eigen::Index>(nnz));
  int* outer = a.outerIndexPtr();
  int* inner = a.innerIndexPtr();
  double* val = a.valuePtr();
  int pos = 0;
  for (int j = 0; j < nb; ++j) {
    for (int c = 0; c < kDofs; ++c) {
      outer[kDofs * j + c] = pos;
      for (int r = c; r < kDofs; ++r, ++pos) {
        inner[pos] = kDofs * j + r;
        val[pos] = diag_[j](r, c);
      }
      for (const auto& [i, m] : cols[j])
        for (int r = 0; r < kDofs; ++r, ++pos) {
          inner[pos] = kDofs * i + r;
          val[pos] = (*m)(r, c);
        }
    }
  }
  outer[n] = pos;
  return a;
}

Eigen::SparseMatrix<double> BlockSystem::full() const {
  const Eigen::SparseMatrix<double> l = lower();
  Eigen::SparseMatrix<double> f = l.selfadjointView<Eigen::Lower>();
  return f;
}

}  // namespace dda::df
