#pragma once
// The global system K d = F stored as 6x6 blocks.
//
// Only the lower block triangle is kept (K is symmetric). Every stored block
// is written out whole, zeros included, so the sparsity pattern depends only
// on which block pairs are coupled: the solver can reuse its symbolic
// analysis while the contact pairs stay the same.
#include <Eigen/SparseCore>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "dda/df/types.hpp"

namespace dda::df {

class BlockSystem {
 public:
  explicit BlockSystem(int blocks = 0);
  void reset(int blocks);  // zero everything, keep the size

  int blocks() const { return static_cast<int>(diag_.size()); }
  Matrix6d& diagonal(int i) { return diag_[i]; }
  // Adds K_ij (and implicitly K_ji = K_ij^T), i != j.
  void add_coupling(int i, int j, const Matrix6d& kij);
  auto rhs(int i) { return rhs_.segment<kDofs>(kDofs * i); }
  const Eigen::VectorXd& rhs() const { return rhs_; }

  // Lower triangle in compressed column form (for the solver).
  Eigen::SparseMatrix<double> lower() const;
  // Full symmetric matrix (tests, energy checks).
  Eigen::SparseMatrix<double> full() const;

 private:
  static std::uint64_t key(int i, int j) {
    return (static_cast<std::uint64_t>(i) << 32) | static_cast<std::uint32_t>(j);
  }
  std::vector<Matrix6d> diag_;
  std::unordered_map<std::uint64_t, Matrix6d> off_;  // (i, j) with i > j
  Eigen::VectorXd rhs_;
};

}  // namespace dda::df
