#pragma once
// Contact clusters, one driver for the 2D and the 3D solver: the contact
// states that a global solve changed are settled on the blocks around them,
// the rest of the model held. Internal to df/src.
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
//
// What differs between the dimensions is behind ClusterKernel: the 2D
// kernel is in simulation_clusters.cpp, the 3D one in
// simulation3d_clusters.cpp.
#include <algorithm>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace dda::df {

// What a solver offers the cluster driver. Blocks are the nodes of the
// contact graph: 0 .. block_count() - 1, or -1 for a block without
// unknowns (a fixed 3D block), which never joins a cluster.
//   contact_blocks(k)     the two blocks contact k joins
//   unsettled(k)          the last global update left contact k changed, or
//                         its friction lagging its normal force
//   prepare_round(round)  K and F of the states the last update left
//                         (round 0: those of the global update)
//   solve_on(cluster, ks) K_RR x_R = F_R - (K d)_R on the cluster's blocks R,
//                         every other block held, and d_R += x_R; ks are the
//                         contacts of R's blocks (in increasing order), the
//                         ones whose loads F_R holds; false if the local
//                         solve failed (the caller goes on globally)
//   update_contacts(ks, unsettled)
//                         the state update of contacts ks (in increasing
//                         order) from the corrected d; appends those that
//                         changed state or whose friction lags
template <class K>
concept ClusterKernel = requires(K& kernel, const K& ck, std::size_t k, int round, const std::vector<int>& ids,
                                 std::vector<int>& out) {
  { ck.block_count() } -> std::convertible_to<int>;
  { ck.contact_count() } -> std::convertible_to<std::size_t>;
  { ck.contact_blocks(k) } -> std::convertible_to<std::pair<int, int>>;
  { ck.unsettled(k) } -> std::convertible_to<bool>;
  kernel.prepare_round(round);
  { kernel.solve_on(ids, ids) } -> std::convertible_to<bool>;
  kernel.update_contacts(ids, out);
};

namespace cluster_limits {
// A cluster larger than this share of the blocks is solved globally.
constexpr double kLargestCluster = 0.25;
// Rounds of local solves before the cluster is given up.
constexpr int kMaxRounds = 30;
}  // namespace cluster_limits

// Settles the contacts the last global update left unsettled on clusters of
// blocks around them. True when no contact of the cluster changes any more
// (the caller then verifies with a full global solve); false when the
// cluster grew past a quarter of the model, a local solve failed, or the
// rounds ran out (the caller goes on with global solves; d is corrected on
// the cluster in every case, and the kernel knows which contacts changed).
template <ClusterKernel Kernel>
bool settle_contact_clusters(Kernel& kernel) {
  const int nb = kernel.block_count();
  const std::size_t nc = kernel.contact_count();
  // The contacts of each block (both blocks of a contact list it).
  std::vector<int> first(static_cast<std::size_t>(nb) + 1, 0), of_block;
  of_block.reserve(2 * nc);
  for (std::size_t k = 0; k < nc; ++k) {
    const auto [a, b] = kernel.contact_blocks(k);
    if (a >= 0) ++first[a + 1];
    if (b >= 0) ++first[b + 1];
  }
  for (int b = 0; b < nb; ++b) first[b + 1] += first[b];
  of_block.resize(static_cast<std::size_t>(first[nb]));
  {
    std::vector<int> at(first.begin(), first.end() - 1);
    for (std::size_t k = 0; k < nc; ++k) {
      const auto [a, b] = kernel.contact_blocks(k);
      if (a >= 0) of_block[at[a]++] = static_cast<int>(k);
      if (b >= 0) of_block[at[b]++] = static_cast<int>(k);
    }
  }
  const std::size_t limit = static_cast<std::size_t>(cluster_limits::kLargestCluster * nb);
  std::vector<std::uint8_t> in_cluster(static_cast<std::size_t>(nb), 0);
  std::vector<int> cluster;
  auto add_block = [&](int b) {
    if (b >= 0 && !in_cluster[b]) in_cluster[b] = 1, cluster.push_back(b);
  };
  // The blocks of the unsettled contacts (`seeds`) and their neighbours.
  std::vector<int> seeds;
  auto seed = [&](std::size_t k) {
    const auto [a, b] = kernel.contact_blocks(k);
    if (a >= 0) seeds.push_back(a);
    if (b >= 0) seeds.push_back(b);
  };
  for (std::size_t k = 0; k < nc; ++k)
    if (kernel.unsettled(k)) seed(k);
  auto grow = [&]() {
    for (const int b : seeds) {
      add_block(b);
      for (int e = first[b]; e < first[b + 1]; ++e) {
        const auto [u, v] = kernel.contact_blocks(static_cast<std::size_t>(of_block[e]));
        add_block(u == b ? v : u);
      }
    }
    seeds.clear();
    return !cluster.empty() && cluster.size() <= limit;
  };
  if (!grow()) return false;

  // Round in which each contact was last listed among the cluster's (a
  // stamp, so that no pass over every contact is made per round).
  std::vector<int> listed(nc, -1), of_cluster, unsettled;
  for (int round = 0; round < cluster_limits::kMaxRounds; ++round) {
    // The contacts of the cluster's blocks, in contact order (the order the
    // global update takes them in).
    of_cluster.clear();
    for (const int b : cluster)
      for (int e = first[b]; e < first[b + 1]; ++e)
        if (listed[of_block[e]] != round) listed[of_block[e]] = round, of_cluster.push_back(of_block[e]);
    std::sort(of_cluster.begin(), of_cluster.end());
    kernel.prepare_round(round);
    if (!kernel.solve_on(cluster, of_cluster)) return false;
    unsettled.clear();
    kernel.update_contacts(of_cluster, unsettled);
    if (unsettled.empty()) return true;
    for (const int k : unsettled) seed(static_cast<std::size_t>(k));
    if (!grow()) return false;
  }
  return false;
}

}  // namespace dda::df
