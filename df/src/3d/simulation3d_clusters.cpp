// The 3D kernel of the contact clusters (contact_clusters.hpp, where the
// driver and its reasons are): the residual and local solve on K's lower
// block triangle (LowerBlockCsc), the contacts' updates with
// update_contact3, and the list of changes whose springs the next assembly
// swaps. Fixed blocks have no unknowns: they hold, and never join a
// cluster.
#include <vector>

#include "core/contact_clusters.hpp"
#include "dda/df/3d/simulation3d.hpp"
#include "core/local_solve.hpp"
#include "core/lower_block_csc.hpp"
#include "3d/simulation3d_assembly.hpp"

namespace dda::df3 {

namespace {

// A local solve only has to decide states: to the 3D trial tolerance
// (simulation3d.cpp, pcg_options3); the global solve that ends the
// iteration is made to full accuracy.
constexpr double kLocalTolerance = 1e-4;
constexpr int kMaxLocalIterations = 500;

}  // namespace

bool Simulation3::settle_clusters(double dt, std::vector<Vector12d>& d, std::vector<int>& changes,
                                  std::vector<std::pair<int, ContactState3>>& changed,
                                  const std::vector<std::uint8_t>& unsettled) {
  // A local class has the member function's access to the simulation.
  struct Kernel3 {
    Simulation3& sim;
    double dt;
    std::vector<Vector12d>& d;
    std::vector<int>& changes;
    std::vector<std::pair<int, ContactState3>>& changed;
    // The global update (of every contact) changed these or left their
    // friction lagging.
    const std::vector<std::uint8_t>& seeds;
    df::LowerBlockCsc<kDofs> rows{};
    std::vector<int> block_of_free{};    // the block of each free block number
    Eigen::VectorXd x_all{}, r{}, x{}, f{};  // by unknown: d, the residual, the correction, contact loads

    int free_of(int b) const { return sim.dof_[static_cast<std::size_t>(b)] < 0 ? -1 : sim.dof_[b] / kDofs; }

    void start() {
      const int n = sim.n_dofs_;
      block_of_free.assign(static_cast<std::size_t>(n / kDofs), -1);
      x_all = r = x = f = Eigen::VectorXd::Zero(n);
      for (std::size_t b = 0; b < d.size(); ++b)
        if (sim.dof_[b] >= 0) {
          block_of_free[static_cast<std::size_t>(sim.dof_[b] / kDofs)] = static_cast<int>(b);
          x_all.segment<kDofs>(sim.dof_[b]) = d[b];
        }
      // K's pattern is fixed for the attempt (its contacts are), so the row
      // index is built once; the values are read live as the rounds swap
      // springs into K.
      rows.bind(sim.k_lower_, /*coupling_blocks=*/false);
    }

    int block_count() const { return static_cast<int>(block_of_free.size()); }
    std::size_t contact_count() const { return sim.contacts_.size(); }
    std::pair<int, int> contact_blocks(std::size_t k) const {
      const Contact3& c = sim.contacts_[k];
      return {free_of(c.i), free_of(c.j)};
    }
    bool unsettled(std::size_t k) const { return seeds[k] != 0; }

    void prepare_round(int /*round*/) {
      const df::ScopedTimer timer(sim.timings_.assembly);
      // Swapping a spring costs twice adding it (as in solve()).
      if (3 * changed.size() > sim.contacts_.size())
        sim.assemble(dt);
      else
        sim.swap_springs(changed);
      changed.clear();
    }

    bool solve_on(const std::vector<int>& cluster, const std::vector<int>& its_contacts) {
      const df::ScopedTimer timer(sim.timings_.solve);
      // F on the cluster: the blocks' loads and those of every contact of
      // its blocks in its current state (as solve() assembles them).
      Assembly3 loads{sim.dof_, sim.k_lower_, f};
      for (const int k : its_contacts) {
        const Contact3& c = sim.contacts_[static_cast<std::size_t>(k)];
        add_contact_loads(c, sim.springs_of(c), sim.known_, loads);
      }
      for (const int fb : cluster)
        r.segment<kDofs>(kDofs * fb) = sim.block_loads_.segment<kDofs>(kDofs * fb) +
                                       f.segment<kDofs>(kDofs * fb) - rows.multiply_row(fb, x_all);
      for (const int k : its_contacts) {  // f back to zero, for the next round
        const Contact3& c = sim.contacts_[static_cast<std::size_t>(k)];
        for (const int b : {c.i, c.j})
          if (sim.dof_[b] >= 0) f.segment<kDofs>(sim.dof_[b]).setZero();
      }
      const df::LocalSolveResult s =
          df::solve_on_blocks<kDofs>(rows, cluster, r, x, kLocalTolerance, kMaxLocalIterations);
      ++sim.timings_.local_solves;
      sim.timings_.local_iterations += s.iterations;
      if (!s.converged) return false;
      for (const int fb : cluster) {
        const auto dx = x.segment<kDofs>(kDofs * fb);
        x_all.segment<kDofs>(kDofs * fb) += dx;
        d[static_cast<std::size_t>(block_of_free[static_cast<std::size_t>(fb)])] += dx;
        x.segment<kDofs>(kDofs * fb).setZero();
      }
      return true;
    }

    void update_contacts(const std::vector<int>& ks, std::vector<int>& unsettled_out) {
      const df::ScopedTimer timer(sim.timings_.contact_update);
      for (const int k : ks) {
        Contact3& c = sim.contacts_[static_cast<std::size_t>(k)];
        bool friction_settled = true;
        const ContactState3 before = c.state;
        const ContactState3 s = update_contact3(c, sim.model_, sim.springs_of(c), sim.law_of(c), dt, d[c.i], d[c.j],
                                                changes[static_cast<std::size_t>(k)] >= 2, friction_settled);
        if (s != before) {
          ++changes[static_cast<std::size_t>(k)];
          changed.emplace_back(k, before);
        }
        c.state = s;
        if (s != before || !friction_settled) unsettled_out.push_back(k);
        ++sim.timings_.contact_updates;
      }
    }
  };
  Kernel3 kernel{*this, dt, d, changes, changed, unsettled};
  kernel.start();
  const bool settled = df::settle_contact_clusters(kernel);
  solver_->set_warm_start({kernel.x_all, dt});
  return settled;
}

}  // namespace dda::df3
