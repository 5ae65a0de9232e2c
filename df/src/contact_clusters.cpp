// Contact clusters: the contact states that a global solve changed are
// settled on the blocks around them, the rest of the model held.
//
// Why: the open-close iteration ends only when no contact of the whole
// model changes state, and on a model of thousands of blocks some contact
// somewhere changes in almost every iterate (a brick of the top row
// sticking and slipping, a bed joint of one corner opening). Every such
// change cost a solve of the whole system: the solves per step grew with
// the model (10.5 at 101 bricks, 22.6 at 401, 29.5 at 1,601). A change of
// state alters the forces of one contact; the blocks near it answer, the far
// ones hardly move. So after a global solve the changed contacts' blocks and
// their neighbours (one ring) are solved again alone, the other blocks held
// where the global solve put them (local_solve.hpp), their contacts updated,
// and the cluster grown by the blocks of any contact that changes next,
// until no contact of the cluster changes. A full global solve then checks
// the whole model: if it changes no state either, the step is accepted with
// every contact checked against the solution of the whole system, as before;
// if it does (the far field moved a little), the clusters start again from
// it. A cluster that grows past a quarter of the model is not local: the
// iteration then goes on with global solves, as it always did.
//
// Nothing of the physics of an accepted step changes: the last solve is
// always a full global one, after which every contact is updated and none
// may have changed state.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "dda/df/simulation.hpp"
#include "local_solve.hpp"

namespace dda::df {

namespace {

// A cluster larger than this share of the blocks is solved globally.
constexpr double kLargestCluster = 0.25;
// Rounds of local solves before the cluster is given up.
constexpr int kMaxRounds = 30;
// A local solve only has to decide states, like a trial solve; the global
// solve that ends the iteration is made to full accuracy.
constexpr double kLocalTolerance = 1e-6;
constexpr int kMaxLocalIterations = 500;

}  // namespace

bool Simulation::settle_clusters(double dt, std::vector<Contact>& contacts, Eigen::VectorXd& d,
                                 std::vector<std::uint8_t>& changes, std::vector<double>& friction) {
  const int nb = model_.block_count();
  const std::size_t nc = contacts.size();
  StateChanges& sc = state_changes_;
  // The contacts of each block (both blocks of a contact list it).
  std::vector<int> first(static_cast<std::size_t>(nb) + 1, 0), of_block(2 * nc);
  for (const Contact& c : contacts) ++first[c.vblock + 1], ++first[c.eblock + 1];
  for (int b = 0; b < nb; ++b) first[b + 1] += first[b];
  {
    std::vector<int> at(first.begin(), first.end() - 1);
    for (std::size_t k = 0; k < nc; ++k) {
      of_block[at[contacts[k].vblock]++] = static_cast<int>(k);
      of_block[at[contacts[k].eblock]++] = static_cast<int>(k);
    }
  }
  const std::size_t limit = static_cast<std::size_t>(kLargestCluster * nb);
  std::vector<std::uint8_t> in_cluster(nb, 0);
  std::vector<int> cluster;
  auto add_block = [&](int b) {
    if (!in_cluster[b]) in_cluster[b] = 1, cluster.push_back(b);
  };
  // The blocks of the unsettled contacts (`seeds`) and their neighbours.
  std::vector<int> seeds;
  for (std::size_t k = 0; k < nc; ++k)
    if (sc.unsettled[k]) seeds.push_back(contacts[k].vblock), seeds.push_back(contacts[k].eblock);
  auto grow = [&]() {
    for (const int b : seeds) {
      add_block(b);
      for (int e = first[b]; e < first[b + 1]; ++e) {
        const Contact& c = contacts[of_block[e]];
        add_block(c.vblock == b ? c.eblock : c.vblock);
      }
    }
    seeds.clear();
    return cluster.size() <= limit;
  };
  if (!grow()) return false;

  Eigen::VectorXd r = Eigen::VectorXd::Zero(d.size()), x = Eigen::VectorXd::Zero(d.size());
  // Round in which each contact was last listed among the cluster's (a
  // stamp, so that no pass over every contact is made per round).
  std::vector<int> listed(nc, -1), of_cluster;
  for (int round = 0; round < kMaxRounds; ++round) {
    {
      // K and F of the states the last update left (only the contacts it
      // flagged are revisited).
      const ScopedTimer timer(timings_.assembly);
      reassemble(dt, contacts, sc, friction);
    }
    // Those flags are spent: from here on only the cluster's contacts are
    // updated, and every other contact keeps its state and forces (not
    // revisited). One pass, after the global update's flags.
    if (round == 0)
      for (std::size_t k = 0; k < nc; ++k) sc.is_changed[k] = sc.revisit[k] = sc.unsettled[k] = 0;
    {
      const ScopedTimer timer(timings_.solve);
      for (const int b : cluster)
        r.segment<kDofs>(kDofs * b) = system_.rhs().segment<kDofs>(kDofs * b) - system_.multiply_row(b, d);
      const LocalSolveResult s = solve_on_blocks(system_, cluster, r, x, kLocalTolerance, kMaxLocalIterations);
      ++timings_.local_solves;
      timings_.local_iterations += s.iterations;
      if (!s.converged) {
        // K and F already hold the last update's changes (reassembled
        // above, their flags cleared): nothing to swap in a second time.
        sc.changed = 0;
        return false;
      }
      for (const int b : cluster) {
        d.segment<kDofs>(kDofs * b) += x.segment<kDofs>(kDofs * b);
        x.segment<kDofs>(kDofs * b).setZero();
      }
    }
    // The contacts of the cluster's blocks from the corrected d, in
    // contact order (the order the global update takes them in).
    const ScopedTimer timer(timings_.contact_update);
    of_cluster.clear();
    for (const int b : cluster)
      for (int e = first[b]; e < first[b + 1]; ++e)
        if (listed[of_block[e]] != round) listed[of_block[e]] = round, of_cluster.push_back(of_block[e]);
    std::sort(of_cluster.begin(), of_cluster.end());
    bool unsettled = false;
    long moved = 0;
    for (const int k : of_cluster) {
      const ContactUpdate u = update_one(k, contacts, d, dt, changes);
      if (u.flipped || u.lags) {
        unsettled = true;
        seeds.push_back(contacts[k].vblock), seeds.push_back(contacts[k].eblock);
      }
      moved += u.moved;
      ++timings_.contact_updates;
    }
    sc.changed = moved;
    if (!unsettled) return true;
    if (!grow()) return false;
  }
  return false;
}

}  // namespace dda::df
