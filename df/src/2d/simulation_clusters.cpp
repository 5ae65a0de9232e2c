// The 2D kernel of the contact clusters (contact_clusters.hpp, where the
// driver and its reasons are): the residual and local solve on BlockSystem,
// the contacts' updates with update_one, and the bookkeeping of which
// contacts' springs the next assembly must swap (StateChanges).
#include <cstdint>
#include <vector>

#include "core/contact_clusters.hpp"
#include "dda/df/2d/simulation.hpp"
#include "core/local_solve.hpp"

namespace dda::df {

namespace {

// A local solve only has to decide states, like a trial solve; the global
// solve that ends the iteration is made to full accuracy.
constexpr double kLocalTolerance = 1e-6;
constexpr int kMaxLocalIterations = 500;

}  // namespace

bool Simulation::settle_clusters(double dt, std::vector<Contact>& contacts, Eigen::VectorXd& d,
                                 std::vector<std::uint8_t>& changes, std::vector<double>& friction) {
  // A local class has the member function's access to the simulation.
  struct Kernel {
    Simulation& sim;
    double dt;
    std::vector<Contact>& contacts;
    Eigen::VectorXd& d;
    std::vector<std::uint8_t>& changes;
    std::vector<double>& friction;
    Eigen::VectorXd r = Eigen::VectorXd::Zero(d.size()), x = Eigen::VectorXd::Zero(d.size());

    int block_count() const { return sim.model_.block_count(); }
    std::size_t contact_count() const { return contacts.size(); }
    std::pair<int, int> contact_blocks(std::size_t k) const { return {contacts[k].vblock, contacts[k].eblock}; }
    bool unsettled(std::size_t k) const { return sim.state_changes_.unsettled[k] != 0; }

    void prepare_round(int round) {
      StateChanges& sc = sim.state_changes_;
      {
        // K and F of the states the last update left (only the contacts it
        // flagged are revisited).
        const ScopedTimer timer(sim.timings_.assembly);
        sim.reassemble(dt, contacts, sc, friction);
      }
      // Those flags are spent: from here on only the cluster's contacts are
      // updated, and every other contact keeps its state and forces (not
      // revisited). One pass, after the global update's flags.
      if (round == 0)
        for (std::size_t k = 0; k < contacts.size(); ++k) sc.is_changed[k] = sc.revisit[k] = sc.unsettled[k] = 0;
    }

    bool solve_on(const std::vector<int>& cluster, const std::vector<int>& /*its contacts: F is whole in BlockSystem*/) {
      const ScopedTimer timer(sim.timings_.solve);
      const BlockSystem& system = sim.system_;
      for (const int b : cluster)
        r.segment<kDofs>(kDofs * b) = system.rhs().segment<kDofs>(kDofs * b) - system.multiply_row(b, d);
      const LocalSolveResult s = solve_on_blocks<kDofs>(system, cluster, r, x, kLocalTolerance, kMaxLocalIterations);
      ++sim.timings_.local_solves;
      sim.timings_.local_iterations += s.iterations;
      if (!s.converged) {
        // K and F already hold the last update's changes (reassembled, their
        // flags cleared): nothing to swap in a second time.
        sim.state_changes_.changed = 0;
        return false;
      }
      for (const int b : cluster) {
        d.segment<kDofs>(kDofs * b) += x.segment<kDofs>(kDofs * b);
        x.segment<kDofs>(kDofs * b).setZero();
      }
      return true;
    }

    void update_contacts(const std::vector<int>& ks, std::vector<int>& unsettled_out) {
      const ScopedTimer timer(sim.timings_.contact_update);
      long moved = 0;
      for (const int k : ks) {
        const ContactUpdate u = sim.update_one(static_cast<std::size_t>(k), contacts, d, dt, changes);
        if (u.flipped || u.lags) unsettled_out.push_back(k);
        moved += u.moved;
        ++sim.timings_.contact_updates;
      }
      sim.state_changes_.changed = moved;
    }
  };
  Kernel kernel{*this, dt, contacts, d, changes, friction};
  return settle_contact_clusters(kernel);
}

}  // namespace dda::df
