#pragma once
// Solvers for the symmetric positive definite step system.
#include <Eigen/SparseCore>
#include <memory>
#include <string>

namespace dda::df {

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  virtual std::string name() const = 0;
  // Solves K x = b given the lower triangle of K (CSC). Throws InternalError
  // if K is not positive definite (a broken invariant: inertia keeps it SPD).
  virtual Eigen::VectorXd solve(const Eigen::SparseMatrix<double>& lower, const Eigen::VectorXd& b) = 0;
  // How many symbolic analyses were done (pattern reuse diagnostics).
  virtual int analyses() const = 0;
};

// CHOLMOD supernodal/simplicial Cholesky; the symbolic analysis is kept while
// the sparsity pattern is unchanged.
std::unique_ptr<LinearSolver> make_cholmod_solver();
// Eigen SimplicialLDLT: a dependency-free reference for tests.
std::unique_ptr<LinearSolver> make_eigen_solver();

}  // namespace dda::df
