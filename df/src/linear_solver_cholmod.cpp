// CHOLMOD Cholesky with the symbolic analysis kept while the pattern holds.
#include <cholmod.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "dda/common/error.hpp"
#include "dda/df/linear_solver.hpp"

namespace dda::df {
namespace {

class CholmodSolver final : public LinearSolver {
 public:
  CholmodSolver() {
    cholmod_start(&common_);
    common_.print = 0;     // the caller reports errors; CHOLMOD must not print
    common_.final_ll = 1;  // LL^T also in simplicial mode: a negative pivot fails instead of passing as LDL^T
  }
  ~CholmodSolver() override {
    if (factor_) cholmod_free_factor(&factor_, &common_);
    cholmod_finish(&common_);
  }
  CholmodSolver(const CholmodSolver&) = delete;
  CholmodSolver& operator=(const CholmodSolver&) = delete;

  std::string name() const override { return "cholmod"; }
  int analyses() const override { return analyses_; }

  Eigen::VectorXd solve(const Eigen::SparseMatrix<double>& lower, const Eigen::VectorXd& b) override {
    const auto n = static_cast<std::size_t>(lower.rows());
    const auto nnz = static_cast<std::size_t>(lower.nonZeros());
    if (n == 0) return {};
    // stype -1: CHOLMOD reads the lower triangle as a symmetric matrix.
    cholmod_sparse* a = cholmod_allocate_sparse(n, n, nnz, 1, 1, -1, CHOLMOD_REAL, &common_);
    if (!a) throw InternalError("CHOLMOD could not allocate the step matrix");
    std::memcpy(a->p, lower.outerIndexPtr(), (n + 1) * sizeof(int));
    std::memcpy(a->i, lower.innerIndexPtr(), nnz * sizeof(int));
    std::memcpy(a->x, lower.valuePtr(), nnz * sizeof(double));

    const bool same = factor_ && pattern_outer_.size() == n + 1 &&
                      std::equal(pattern_outer_.begin(), pattern_outer_.end(), lower.outerIndexPtr()) &&
                      pattern_inner_.size() == nnz &&
                      std::equal(pattern_inner_.begin(), pattern_inner_.end(), lower.innerIndexPtr());
    if (!same) {
      if (factor_) cholmod_free_factor(&factor_, &common_);
      factor_ = cholmod_analyze(a, &common_);
      ++analyses_;
      pattern_outer_.assign(lower.outerIndexPtr(), lower.outerIndexPtr() + n + 1);
      pattern_inner_.assign(lower.innerIndexPtr(), lower.innerIndexPtr() + nnz);
    }
    const int ok = factor_ ? cholmod_factorize(a, factor_, &common_) : 0;
    cholmod_free_sparse(&a, &common_);
    if (!ok || common_.status != CHOLMOD_OK) {
      pattern_outer_.clear();  // analyse afresh next time
      throw InternalError("CHOLMOD could not factorise the step matrix (status " +
                          std::to_string(common_.status) + ")");
    }

    cholmod_dense* rhs = cholmod_allocate_dense(n, 1, n, CHOLMOD_REAL, &common_);
    std::memcpy(rhs->x, b.data(), n * sizeof(double));
    cholmod_dense* x = cholmod_solve(CHOLMOD_A, factor_, rhs, &common_);
    cholmod_free_dense(&rhs, &common_);
    if (!x) throw InternalError("CHOLMOD could not solve the step system");
    Eigen::VectorXd out(static_cast<Eigen::Index>(n));
    std::memcpy(out.data(), x->x, n * sizeof(double));
    cholmod_free_dense(&x, &common_);
    return out;
  }

 private:
  cholmod_common common_{};
  cholmod_factor* factor_ = nullptr;
  std::vector<int> pattern_outer_, pattern_inner_;
  int analyses_ = 0;
};

}  // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver() { return std::make_unique<CholmodSolver>(); }

}  // namespace dda::df
