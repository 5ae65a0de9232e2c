#pragma once
// Solvers for the symmetric positive definite step system.
//
// Choice (Control::solver, make_solver):
//  * "cholmod": sparse Cholesky (CHOLMOD, fill-reducing ordering chosen by
//    CHOLMOD: AMD, or METIS when AMD fills badly), the symbolic analysis kept
//    while the pattern holds.
//  * "pcg": conjugate gradients preconditioned by the inverse diagonal blocks
//    (block Jacobi: 6x6 in 2D, 12x12 in 3D, PcgOptions::block_size; each
//    block inverted through its Cholesky factor),
//    warm-started from the last solution: within a step that is the previous
//    open-close iterate; across steps the last solution of the previous step
//    times dt / dt_previous (d ~ v dt). It stops when the block-Jacobi
//    preconditioned residual norm sqrt(r' M^-1 r) falls to
//    PcgOptions::tolerance (1e-10) times that of the right-hand side, or
//    PcgOptions::trial_tolerance (1e-6; 1e-4 in 3D) for a trial solve (set_trial: an
//    open-close iterate whose states still change). A solve
//    that has not converged after PcgOptions::max_iterations is redone by
//    CHOLMOD (counted in SolverStats::fallbacks).
//  * "auto" (default): CHOLMOD below kAutoPcgBlocks blocks (3D:
//    kAutoPcgBlocks3 free blocks), PCG from there on.
//    Measured on brick walls under gravity (bench/bench_df.cpp, 2 cores):
//    per settled step CHOLMOD wins at 30 blocks (0.30 vs 0.59 ms), PCG at
//    100 (1.2 vs 4.5 ms) and 1,000 (8 vs 160 ms); on the first step from
//    rest (PCG from zero, ~50 iterations; CHOLMOD analysing) they tie at
//    about 100 blocks and PCG wins from 250 (41 vs 56 ms) on.
// All of them give the same result with any number of OpenMP threads (PCG
// sums its dot products in fixed chunks, in a fixed order).
#include <Eigen/SparseCore>
#include <memory>
#include <string>

namespace dda::df {

class BlockSystem;

// K's coupling blocks (those off the block diagonal) given by the penalty
// springs that make them, for iterative solvers: a product through the
// springs reads fewer bytes than K's stored 12 x 12 blocks (3D: a closed
// contact's normal spring is two 12-vectors, against a 144-value block per
// pair of blocks, and the product is bound by memory traffic).
class SpringCoupling {
 public:
  virtual ~SpringCoupling() = default;
  // y += (K - blockdiag(K)) x, the same bit for bit on any number of threads.
  virtual void add_product(const Eigen::VectorXd& x, Eigen::VectorXd& y) const = 0;
};

// Counters over the life of a solver.
struct SolverStats {
  long solves = 0;            // systems solved
  long analyses = 0;          // CHOLMOD symbolic analyses (pattern changes)
  long factorizations = 0;    // CHOLMOD numeric factorisations
  long pcg_solves = 0;        // systems solved by PCG
  long pcg_iterations = 0;    // PCG iterations, summed
  long fallbacks = 0;         // PCG did not converge: CHOLMOD solved instead
  long pcg_residuals_kept = 0;  // PCG trial solves that took the last solve's residual (block_pcg.hpp)
  long pcg_rows_refreshed = 0;  // in those, the block rows whose residual was formed afresh, summed
  std::string ordering;       // fill-reducing ordering CHOLMOD chose last ("" if none)
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  virtual std::string name() const = 0;
  // Solves K x = b given the lower triangle of K (CSC). Throws InternalError
  // if K is not positive definite (a broken invariant: inertia keeps it SPD).
  virtual Eigen::VectorXd solve(const Eigen::SparseMatrix<double>& lower, const Eigen::VectorXd& b) = 0;
  // Solves the assembled step system (sys.rhs() is b). `dt` is the time step
  // it was assembled for; iterative solvers scale their warm start with it
  // (0: no scaling). The default forms the CSC lower triangle and calls solve.
  virtual Eigen::VectorXd solve_step(const BlockSystem& sys, double dt);
  // The same for a system given by its lower triangle (the 3D solver's K,
  // laid out in 12x12 blocks, see lower_block_csc.hpp). The default calls
  // solve.
  virtual Eigen::VectorXd solve_step(const Eigen::SparseMatrix<double>& lower, const Eigen::VectorXd& b, double dt);
  // The same, where `coupling` gives K's off-diagonal blocks as springs
  // (`lower` holds all of K, for direct solves). The default ignores it.
  virtual Eigen::VectorXd solve_step(const Eigen::SparseMatrix<double>& lower, const SpringCoupling& coupling,
                                     const Eigen::VectorXd& b, double dt);
  // How many symbolic analyses were done (pattern reuse diagnostics).
  virtual int analyses() const = 0;
  virtual SolverStats stats() const;
  // What carries over from one solve to the next and changes the result
  // (PCG's warm start, within its tolerance): for checkpoints. Empty for
  // direct solvers.
  struct WarmStart {
    Eigen::VectorXd x;  // last solution
    double dt = 0;      // the step it was for
  };
  // Trial solves. While the open-close states are still changing, an
  // iterate's answer only has to decide them, and is solved again anyway: an
  // iterative solver may then stop at PcgOptions::trial_tolerance. The
  // caller solves the iterate that settles the states at full accuracy
  // (last_was_trial tells it whether it must). Direct solvers ignore this.
  virtual void set_trial(bool /*trial*/) {}
  // Whether the last solve stopped at the trial tolerance (false for direct
  // solves and CHOLMOD fallbacks).
  virtual bool last_was_trial() const { return false; }
  virtual WarmStart warm_start() const { return {}; }
  virtual void set_warm_start(const WarmStart& /*w*/) {}
};

// Trial solves off again when an open-close iteration ends, however it ends
// (a later solve outside the iteration must be a full one).
class TrialScope {
 public:
  explicit TrialScope(LinearSolver& solver) : solver_(solver) {}
  TrialScope(const TrialScope&) = delete;
  TrialScope& operator=(const TrialScope&) = delete;
  ~TrialScope() { solver_.set_trial(false); }

 private:
  LinearSolver& solver_;
};

struct PcgOptions {
  double tolerance = 1e-10;   // relative, block-Jacobi preconditioned residual norm
  double trial_tolerance = 1e-6;  // the same for trial solves (LinearSolver::set_trial)
  int max_iterations = 2000;  // then CHOLMOD solves the system
  int block_size = 6;         // unknowns per block: 6 (2D) or 12 (3D)
};

// Size from which "auto" uses PCG, in blocks (2D).
constexpr int kAutoPcgBlocks = 200;

// CHOLMOD supernodal/simplicial Cholesky; the symbolic analysis is kept while
// the sparsity pattern is unchanged.
std::unique_ptr<LinearSolver> make_cholmod_solver();
// Eigen SimplicialLDLT: a dependency-free reference for tests.
std::unique_ptr<LinearSolver> make_eigen_solver();
// Block-Jacobi PCG with warm start and CHOLMOD fallback.
std::unique_ptr<LinearSolver> make_pcg_solver(PcgOptions options = {});
// "auto", "cholmod" or "pcg" (anything else is an InputError);
// `pcg_blocks`: the size from which "auto" uses PCG.
std::unique_ptr<LinearSolver> make_solver(const std::string& choice, int pcg_blocks = kAutoPcgBlocks,
                                          PcgOptions options = {});

}  // namespace dda::df
