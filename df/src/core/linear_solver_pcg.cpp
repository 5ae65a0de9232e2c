// The automatic solver choice and PCG's warm start (block_pcg.hpp has the
// iteration itself), and the LinearSolver defaults.
#include <cstdint>
#include <vector>

#include "core/block_pcg.hpp"
#include "dda/common/error.hpp"
#include "dda/df/core/block_system.hpp"
#include "dda/df/core/linear_solver.hpp"
#include "dda/df/core/types.hpp"
#include "core/lower_block_csc.hpp"

namespace dda::df {

Eigen::VectorXd LinearSolver::solve_step(const BlockSystem& sys, double /*dt*/) { return solve(sys.csc(), sys.rhs()); }

Eigen::VectorXd LinearSolver::solve_step(const Eigen::SparseMatrix<double>& lower, const Eigen::VectorXd& b,
                                         double /*dt*/) {
  return solve(lower, b);
}

Eigen::VectorXd LinearSolver::solve_step(const Eigen::SparseMatrix<double>& lower, const SpringCoupling& /*coupling*/,
                                         const Eigen::VectorXd& b, double dt) {
  return solve_step(lower, b, dt);
}

SolverStats LinearSolver::stats() const {
  SolverStats s;
  s.analyses = analyses();
  return s;
}

namespace {

constexpr int kBlock3d = 12;  // unknowns per 3D block

// The operator of a system given by its diagonal blocks (read from K's
// stored lower triangle) and its coupling springs.
struct DiagonalAndSprings12 {
  const LowerBlockCsc<kBlock3d>& view;
  const SpringCoupling& coupling;
  int blocks() const { return view.blocks(); }
  LowerBlockCsc<kBlock3d>::Block diagonal(int i) const { return view.diagonal(i); }
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y, const LowerBlockCsc<kBlock3d>::Block* symmetric) const {
    view.multiply_diagonal(x, y, symmetric);
    coupling.add_product(x, y);
  }
};

class HybridSolver final : public LinearSolver {
 public:
  enum class Mode { Pcg, Auto };
  HybridSolver(Mode mode, int pcg_blocks, PcgOptions options)
      : mode_(mode),
        pcg_blocks_(pcg_blocks),
        options_(options),
        direct_(make_cholmod_solver()),
        pcg6_(options.max_iterations),
        pcg12_(options.max_iterations) {
    if (options.block_size != kDofs && options.block_size != kBlock3d)
      throw InternalError("PcgOptions::block_size must be 6 or 12");
  }

  std::string name() const override { return mode_ == Mode::Pcg ? "pcg" : "auto"; }
  int analyses() const override { return direct_->analyses(); }
  SolverStats stats() const override {
    SolverStats s = direct_->stats();
    s.solves = solves_;
    s.pcg_solves = pcg_solves_;
    s.pcg_iterations = pcg6_.iterations() + pcg12_.iterations();
    s.fallbacks = fallbacks_;
    s.pcg_residuals_kept = pcg6_.residuals_kept();
    s.pcg_rows_refreshed = pcg6_.rows_refreshed();
    return s;
  }

  void set_trial(bool trial) override { trial_ = trial; }
  bool last_was_trial() const override { return last_was_trial_; }
  WarmStart warm_start() const override { return {x_last_, dt_last_}; }
  void set_warm_start(const WarmStart& w) override {
    x_last_ = w.x;
    dt_last_ = w.dt;
    x_last_solved_ = false;
  }

  Eigen::VectorXd solve(const Eigen::SparseMatrix<double>& lower, const Eigen::VectorXd& b) override {
    return solve_step(lower, b, 0.0);
  }

  // 3D (block size 12): PCG reads K in place. 2D: K is copied into 6x6
  // blocks first (tests and odd callers; the 2D solver passes its
  // BlockSystem to the overload below).
  Eigen::VectorXd solve_step(const Eigen::SparseMatrix<double>& lower, const Eigen::VectorXd& b,
                             double dt) override {
    const int bs = options_.block_size;
    last_was_trial_ = false;
    if (lower.rows() % bs != 0 || !use_pcg(static_cast<int>(lower.rows() / bs))) {
      ++solves_;
      return direct_->solve(lower, b);
    }
    if (bs == kDofs) return solve_step(BlockSystem::from_lower(lower, b), dt);
    return solve_blocks12(lower, nullptr, b, dt);
  }

  // 3D with the coupling as springs: K's stored coupling blocks are read
  // only by a direct solve. (2D ignores the coupling.)
  Eigen::VectorXd solve_step(const Eigen::SparseMatrix<double>& lower, const SpringCoupling& coupling,
                             const Eigen::VectorXd& b, double dt) override {
    if (options_.block_size != kBlock3d || lower.rows() % kBlock3d != 0 ||
        !use_pcg(static_cast<int>(lower.rows() / kBlock3d)))
      return solve_step(lower, b, dt);
    last_was_trial_ = false;
    return solve_blocks12(lower, &coupling, b, dt);
  }

  Eigen::VectorXd solve_step(const BlockSystem& sys, double dt) override {
    ++solves_;
    last_was_trial_ = false;
    if (!use_pcg(sys.blocks())) {
      last_record_ = 0;
      return direct_->solve_step(sys, dt);
    }
    // What PCG may take over from its last solve (BlockJacobiPcg::Since):
    // the rows of this system that did not change since then, if that solve
    // was of this system with this pattern (the record of changes started
    // right after it); and for a trial solve from that solution (the
    // open-close iterates of one step), its residual.
    BlockJacobiPcg<kDofs>::Since since;
    const std::uint64_t pattern = sys.pattern_id();
    if (last_record_ != 0 && sys.change_record() == last_record_ && pattern == last_pattern_) {
      since.changed = sys.changed_rows();
      since.residual = trial_ && x_last_solved_ && dt == dt_last_;
    }
    Eigen::VectorXd x = iterate(pcg6_, sys, sys.rhs(), dt, [&] { return direct_->solve_step(sys, dt); }, since);
    sys.clear_changes();
    last_record_ = sys.change_record();
    last_pattern_ = pattern;
    return x;
  }

 private:
  bool use_pcg(int blocks) const { return mode_ == Mode::Pcg || blocks >= pcg_blocks_; }

  // PCG on a 3D system in 12x12 blocks: the product reads K's coupling
  // blocks, or `coupling` if given. A matrix not laid out in such blocks is
  // solved directly.
  Eigen::VectorXd solve_blocks12(const Eigen::SparseMatrix<double>& lower, const SpringCoupling* coupling,
                                 const Eigen::VectorXd& b, double dt) {
    ++solves_;
    last_record_ = 0;
    if (!view12_.bind(lower, /*coupling_blocks=*/coupling == nullptr)) {
      ++fallbacks_;
      return direct_->solve(lower, b);
    }
    auto direct = [&] { return direct_->solve(lower, b); };
    if (coupling) return iterate(pcg12_, DiagonalAndSprings12{view12_, *coupling}, b, dt, direct);
    return iterate(pcg12_, view12_, b, dt, direct);
  }

  // PCG from the warm start: the last solution, times dt / dt_last across
  // steps (d ~ v dt), or what set_warm_start() gave (the 2D simulation sets
  // the predicted motion at every step); `direct` solves when PCG does not
  // converge.
  template <class Pcg, class Op, class Direct>
  Eigen::VectorXd iterate(Pcg& pcg, const Op& op, const Eigen::VectorXd& b, double dt, Direct&& direct,
                          const typename Pcg::Since& since = {}) {
    const Eigen::Index n = b.size();
    if (n == 0) return {};
    Eigen::VectorXd x;
    if (x_last_.size() == n) {
      const double scale = (dt > 0 && dt_last_ > 0) ? dt / dt_last_ : 1.0;
      x = scale * x_last_;
    } else {
      x = Eigen::VectorXd::Zero(n);
    }
    ++pcg_solves_;
    x_last_solved_ = false;
    if (pcg.solve(op, b, x, trial_ ? options_.trial_tolerance : options_.tolerance, since)) {
      last_was_trial_ = trial_;
      x_last_solved_ = true;
    } else {
      ++fallbacks_;
      x = direct();
    }
    x_last_ = x;
    dt_last_ = dt;
    return x;
  }

  Mode mode_;
  int pcg_blocks_;
  PcgOptions options_;
  std::unique_ptr<LinearSolver> direct_;
  BlockJacobiPcg<kDofs> pcg6_;
  BlockJacobiPcg<kBlock3d> pcg12_;
  LowerBlockCsc<kBlock3d> view12_;
  long solves_ = 0, pcg_solves_ = 0, fallbacks_ = 0;
  bool trial_ = false, last_was_trial_ = false;
  Eigen::VectorXd x_last_;
  bool x_last_solved_ = false;  // x_last_ is what PCG's last solve returned (not a warm start set from outside)
  std::uint64_t last_record_ = 0, last_pattern_ = 0;  // of the 2D system PCG last solved (0: none)
  double dt_last_ = 0;
};

}  // namespace

std::unique_ptr<LinearSolver> make_pcg_solver(PcgOptions options) {
  return std::make_unique<HybridSolver>(HybridSolver::Mode::Pcg, 0, options);
}

std::unique_ptr<LinearSolver> make_solver(const std::string& choice, int pcg_blocks, PcgOptions options) {
  if (choice == "cholmod") return make_cholmod_solver();
  if (choice == "pcg") return make_pcg_solver(options);
  if (choice == "auto") return std::make_unique<HybridSolver>(HybridSolver::Mode::Auto, pcg_blocks, options);
  throw InputError("control.solver is '" + choice + "'; it must be auto, cholmod or pcg.");
}

}  // namespace dda::df
