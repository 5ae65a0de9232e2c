// Block-Jacobi preconditioned conjugate gradients, the automatic solver
// choice, and the LinearSolver defaults.
//
// Determinism: every vector loop runs over fixed chunks of blocks; the dot
// products add the chunks' partial sums serially in chunk order, so the
// iterates are the same bit for bit with any number of OpenMP threads.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Cholesky>

#include "dda/common/error.hpp"
#include "dda/df/block_system.hpp"
#include "dda/df/linear_solver.hpp"
#include "dda/df/types.hpp"

namespace dda::df {

Eigen::VectorXd LinearSolver::solve_step(const BlockSystem& sys, double /*dt*/) { return solve(sys.csc(), sys.rhs()); }

SolverStats LinearSolver::stats() const {
  SolverStats s;
  s.analyses = analyses();
  return s;
}

namespace {

constexpr int kChunkBlocks = 32;  // blocks per chunk of the vector loops (fixed: it sets the sum order)

class HybridSolver final : public LinearSolver {
 public:
  enum class Mode { Pcg, Auto };
  HybridSolver(Mode mode, int pcg_blocks, PcgOptions options)
      : mode_(mode), pcg_blocks_(pcg_blocks), options_(options), direct_(make_cholmod_solver()) {}

  std::string name() const override { return mode_ == Mode::Pcg ? "pcg" : "auto"; }
  int analyses() const override { return direct_->analyses(); }
  SolverStats stats() const override {
    SolverStats s = direct_->stats();
    s.solves = solves_;
    s.pcg_solves = pcg_solves_;
    s.pcg_iterations = pcg_iterations_;
    s.fallbacks = fallbacks_;
    return s;
  }

  WarmStart warm_start() const override { return {x_last_, dt_last_}; }
  void set_warm_start(const WarmStart& w) override {
    x_last_ = w.x;
    dt_last_ = w.dt;
  }

  Eigen::VectorXd solve(const Eigen::SparseMatrix<double>& lower, const Eigen::VectorXd& b) override {
    if (lower.rows() % kDofs != 0 || !use_pcg(static_cast<int>(lower.rows() / kDofs))) {
      ++solves_;
      return direct_->solve(lower, b);
    }
    return solve_step(BlockSystem::from_lower(lower, b), 0.0);
  }

  Eigen::VectorXd solve_step(const BlockSystem& sys, double dt) override {
    ++solves_;
    if (!use_pcg(sys.blocks())) return direct_->solve_step(sys, dt);
    const Eigen::Index n = static_cast<Eigen::Index>(kDofs) * sys.blocks();
    if (n == 0) return {};
    Eigen::VectorXd x;
    if (x_last_.size() == n) {
      const double scale = (dt > 0 && dt_last_ > 0) ? dt / dt_last_ : 1.0;
      x = scale * x_last_;
    } else {
      x = Eigen::VectorXd::Zero(n);
    }
    if (!pcg(sys, x)) {
      ++fallbacks_;
      x = direct_->solve_step(sys, dt);
    }
    x_last_ = x;
    dt_last_ = dt;
    return x;
  }

 private:
  bool use_pcg(int blocks) const { return mode_ == Mode::Pcg || blocks >= pcg_blocks_; }

  // Symmetric diagonal blocks and their inverses; false if one is not
  // positive definite. A block equal to the one of the last solve keeps its
  // inverse (most do from one open-close iterate to the next).
  bool precondition(const BlockSystem& sys) {
    const int nb = sys.blocks();
    if (static_cast<int>(diagonal_.size()) != nb) {
      diagonal_.assign(nb, Matrix6d::Constant(std::numeric_limits<double>::quiet_NaN()));
      inverse_.resize(nb);
    }
    int bad = 0;
#pragma omp parallel for schedule(static) reduction(+ : bad) if (nb > parallel_grain())
    for (int i = 0; i < nb; ++i) {
      const Matrix6d d = sys.diagonal(i).selfadjointView<Eigen::Lower>();
      if (d == diagonal_[i]) continue;
      diagonal_[i] = d;
      const Eigen::LLT<Matrix6d> llt(d);
      if (llt.info() != Eigen::Success) {
        ++bad;
        diagonal_[i].setConstant(std::numeric_limits<double>::quiet_NaN());  // never matches
        inverse_[i].setIdentity();
        continue;
      }
      inverse_[i] = llt.solve(Matrix6d::Identity());
    }
    return bad == 0;
  }

  // Runs body(lo, hi) over chunks of blocks in parallel and returns the sum
  // of its results, added in chunk order.
  template <class Body>
  double chunked(int nb, Body&& body) {
    const int chunks = (nb + kChunkBlocks - 1) / kChunkBlocks;
    partial_.assign(static_cast<std::size_t>(chunks), 0.0);
#pragma omp parallel for schedule(static) if (nb > parallel_grain() && chunks > 1)
    for (int c = 0; c < chunks; ++c) partial_[c] = body(c * kChunkBlocks, std::min(nb, (c + 1) * kChunkBlocks));
    double sum = 0;
    for (const double v : partial_) sum += v;
    return sum;
  }

  // Solves sys x = b starting from x; true on convergence.
  bool pcg(const BlockSystem& sys, Eigen::VectorXd& x) {
    const int nb = sys.blocks();
    const Eigen::Index n = x.size();
    const Eigen::VectorXd& b = sys.rhs();
    ++pcg_solves_;
    if (!precondition(sys)) return false;  // not SPD: CHOLMOD will say so
    r_.resize(n);
    z_.resize(n);
    p_.resize(n);
    q_.resize(n);
    auto apply = [this](const Eigen::VectorXd& v, Eigen::VectorXd& out, int i) {
      out.segment<kDofs>(kDofs * i).noalias() = inverse_[i] * v.segment<kDofs>(kDofs * i);
    };
    // |b|_M^-1, with z as scratch.
    const double bb = chunked(nb, [&](int lo, int hi) {
      double s = 0;
      for (int i = lo; i < hi; ++i) {
        apply(b, z_, i);
        s += b.segment<kDofs>(kDofs * i).dot(z_.segment<kDofs>(kDofs * i));
      }
      return s;
    });
    if (!(bb > 0)) {
      x.setZero();
      return std::isfinite(bb);
    }
    const double target = options_.tolerance * options_.tolerance * bb;
    sys.multiply(x, q_, diagonal_.data());
    double rz = chunked(nb, [&](int lo, int hi) {
      double s = 0;
      for (int i = lo; i < hi; ++i) {
        const Eigen::Index a = kDofs * i;
        r_.segment<kDofs>(a) = b.segment<kDofs>(a) - q_.segment<kDofs>(a);
        apply(r_, z_, i);
        p_.segment<kDofs>(a) = z_.segment<kDofs>(a);
        s += r_.segment<kDofs>(a).dot(z_.segment<kDofs>(a));
      }
      return s;
    });
    for (int it = 0; it < options_.max_iterations; ++it) {
      if (rz <= target) return true;
      if (!std::isfinite(rz)) return false;
      sys.multiply(p_, q_, diagonal_.data());
      const double pq = chunked(nb, [&](int lo, int hi) {
        return p_.segment(kDofs * lo, kDofs * (hi - lo)).dot(q_.segment(kDofs * lo, kDofs * (hi - lo)));
      });
      if (!(pq > 0)) return false;  // breakdown: not SPD in floating point
      const double alpha = rz / pq;
      const double rz_new = chunked(nb, [&](int lo, int hi) {
        const Eigen::Index a = kDofs * lo, len = kDofs * (hi - lo);
        x.segment(a, len) += alpha * p_.segment(a, len);
        r_.segment(a, len) -= alpha * q_.segment(a, len);
        for (int i = lo; i < hi; ++i) apply(r_, z_, i);
        return r_.segment(a, len).dot(z_.segment(a, len));
      });
      const double beta = rz_new / rz;
      rz = rz_new;
      ++pcg_iterations_;
      chunked(nb, [&](int lo, int hi) {
        const Eigen::Index a = kDofs * lo, len = kDofs * (hi - lo);
        p_.segment(a, len) = z_.segment(a, len) + beta * p_.segment(a, len);
        return 0.0;
      });
    }
    return rz <= target;
  }

  Mode mode_;
  int pcg_blocks_;
  PcgOptions options_;
  std::unique_ptr<LinearSolver> direct_;
  long solves_ = 0, pcg_solves_ = 0, pcg_iterations_ = 0, fallbacks_ = 0;
  Eigen::VectorXd x_last_;
  double dt_last_ = 0;
  std::vector<Matrix6d> diagonal_, inverse_;
  std::vector<double> partial_;
  Eigen::VectorXd r_, z_, p_, q_;
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
