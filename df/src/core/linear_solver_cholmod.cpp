// CHOLMOD Cholesky with the symbolic analysis kept while the pattern holds.
//
// Ordering: CHOLMOD's default (nmethods = 0): AMD, and METIS (linked into
// Debian's CHOLMOD) as well when AMD's fill is high, keeping the better.
// The matrix and right-hand side are handed to CHOLMOD without copies.
#include <cholmod.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "dda/common/error.hpp"
#include "dda/df/core/block_system.hpp"
#include "dda/df/core/linear_solver.hpp"

namespace dda::df {
namespace {

const char* ordering_name(int ordering) {
  switch (ordering) {
    case CHOLMOD_NATURAL: return "natural";
    case CHOLMOD_GIVEN: return "given";
    case CHOLMOD_AMD: return "AMD";
    case CHOLMOD_METIS: return "METIS";
    case CHOLMOD_NESDIS: return "NESDIS";
    case CHOLMOD_COLAMD: return "COLAMD";
    case CHOLMOD_POSTORDERED: return "postordered";
    default: return "?";
  }
}

class CholmodSolver final : public LinearSolver {
 public:
  CholmodSolver() {
    cholmod_start(&common_);
    common_.print = 0;     // the caller reports errors; CHOLMOD must not print
    common_.final_ll = 1;  // LL^T also in simplicial mode: a negative pivot fails instead of passing as LDL^T
  }
  ~CholmodSolver() override {
    if (factor_) cholmod_free_factor(&factor_, &common_);
    if (x_) cholmod_free_dense(&x_, &common_);
    if (y_) cholmod_free_dense(&y_, &common_);
    if (e_) cholmod_free_dense(&e_, &common_);
    cholmod_finish(&common_);
  }
  CholmodSolver(const CholmodSolver&) = delete;
  CholmodSolver& operator=(const CholmodSolver&) = delete;

  std::string name() const override { return "cholmod"; }
  int analyses() const override { return static_cast<int>(stats_.analyses); }
  SolverStats stats() const override { return stats_; }

  Eigen::VectorXd solve(const Eigen::SparseMatrix<double>& matrix, const Eigen::VectorXd& b) override {
    if (!matrix.isCompressed()) {
      Eigen::SparseMatrix<double> compressed = matrix;
      compressed.makeCompressed();
      return solve(compressed, b);
    }
    const Eigen::SparseMatrix<double>& lower = matrix;
    const auto n = static_cast<std::size_t>(lower.rows());
    const auto nnz = static_cast<std::size_t>(lower.nonZeros());
    const bool same = factor_ && pattern_outer_.size() == n + 1 &&
                      std::equal(pattern_outer_.begin(), pattern_outer_.end(), lower.outerIndexPtr()) &&
                      pattern_inner_.size() == nnz &&
                      std::equal(pattern_inner_.begin(), pattern_inner_.end(), lower.innerIndexPtr());
    if (!same) {
      pattern_outer_.assign(lower.outerIndexPtr(), lower.outerIndexPtr() + n + 1);
      pattern_inner_.assign(lower.innerIndexPtr(), lower.innerIndexPtr() + nnz);
    }
    pattern_id_ = 0;  // the generic path never matches a BlockSystem's pattern
    return factor_and_solve(lower, b, same);
  }

  Eigen::VectorXd solve_step(const BlockSystem& sys, double /*dt*/) override {
    const Eigen::SparseMatrix<double>& lower = sys.csc();
    const std::uint64_t id = sys.pattern_id();
    const bool same = factor_ && id == pattern_id_;
    pattern_id_ = id;
    pattern_outer_.clear();
    return factor_and_solve(lower, sys.rhs(), same);
  }

 private:
  Eigen::VectorXd factor_and_solve(const Eigen::SparseMatrix<double>& lower, const Eigen::VectorXd& b,
                                   bool same_pattern) {
    const auto n = static_cast<std::size_t>(lower.rows());
    if (n == 0) return {};
    ++stats_.solves;
    // stype -1: CHOLMOD reads the lower triangle as a symmetric matrix. The
    // header points at Eigen's arrays; CHOLMOD only reads them.
    cholmod_sparse a{};
    a.nrow = a.ncol = n;
    a.nzmax = static_cast<std::size_t>(lower.nonZeros());
    a.p = const_cast<int*>(lower.outerIndexPtr());
    a.i = const_cast<int*>(lower.innerIndexPtr());
    a.x = const_cast<double*>(lower.valuePtr());
    a.stype = -1;
    a.itype = CHOLMOD_INT;
    a.xtype = CHOLMOD_REAL;
    a.dtype = CHOLMOD_DOUBLE;
    a.sorted = 1;
    a.packed = 1;

    if (!same_pattern) {
      if (factor_) cholmod_free_factor(&factor_, &common_);
      factor_ = cholmod_analyze(&a, &common_);
      ++stats_.analyses;
      if (factor_) stats_.ordering = ordering_name(common_.method[common_.selected].ordering);
    }
    const int ok = factor_ ? cholmod_factorize(&a, factor_, &common_) : 0;
    if (!ok || common_.status != CHOLMOD_OK) {
      if (factor_) cholmod_free_factor(&factor_, &common_);  // analyse afresh next time
      throw InternalError("CHOLMOD could not factorise the step matrix (status " +
                          std::to_string(common_.status) + ")");
    }
    ++stats_.factorizations;

    cholmod_dense rhs{};
    rhs.nrow = n;
    rhs.ncol = 1;
    rhs.nzmax = n;
    rhs.d = n;
    rhs.x = const_cast<double*>(b.data());
    rhs.xtype = CHOLMOD_REAL;
    rhs.dtype = CHOLMOD_DOUBLE;
    if (!cholmod_solve2(CHOLMOD_A, factor_, &rhs, nullptr, &x_, nullptr, &y_, &e_, &common_) || !x_)
      throw InternalError("CHOLMOD could not solve the step system");
    Eigen::VectorXd out(static_cast<Eigen::Index>(n));
    std::memcpy(out.data(), x_->x, n * sizeof(double));
    return out;
  }

  cholmod_common common_{};
  cholmod_factor* factor_ = nullptr;
  cholmod_dense *x_ = nullptr, *y_ = nullptr, *e_ = nullptr;  // solve2 workspace, reused
  std::vector<int> pattern_outer_, pattern_inner_;
  std::uint64_t pattern_id_ = 0;
  SolverStats stats_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver() { return std::make_unique<CholmodSolver>(); }

}  // namespace dda::df
