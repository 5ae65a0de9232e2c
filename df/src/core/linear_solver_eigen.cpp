// Eigen's simplicial LDL^T: reference solver without external libraries.
#include <Eigen/SparseCholesky>

#include "dda/common/error.hpp"
#include "dda/df/core/linear_solver.hpp"

namespace dda::df {
namespace {

class EigenSolver final : public LinearSolver {
 public:
  std::string name() const override { return "eigen-ldlt"; }
  Eigen::VectorXd solve(const Eigen::SparseMatrix<double>& lower, const Eigen::VectorXd& b) override {
    ldlt_.compute(lower);  // reads the lower triangle only
    if (ldlt_.info() != Eigen::Success) throw InternalError("the step matrix is not positive definite");
    ++analyses_;
    return ldlt_.solve(b);
  }
  int analyses() const override { return analyses_; }

 private:
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt_;
  int analyses_ = 0;
};

}  // namespace

std::unique_ptr<LinearSolver> make_eigen_solver() { return std::make_unique<EigenSolver>(); }

}  // namespace dda::df
