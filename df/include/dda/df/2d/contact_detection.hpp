#pragma once
// Narrow phase: which vertex of which block touches which edge of which block.
//
// A contact is always a vertex P1 of block `vblock` against an edge of block
// `eblock` (edge k runs from vertex k to vertex k+1, counter-clockwise). An
// edge-to-edge contact appears as two such contacts, one per end.
//
// Signed normal distance (convention used in all of DF):
//   dn = cross(P1 - A, B - A) / l,   A -> B the edge in CCW order, l = |AB|,
// which equals Delta / l with Delta = det|1 x1 y1; 1 xB yB; 1 xA yA| (the
// edge taken clockwise). dn > 0: P1 is outside block `eblock`; dn < 0:
// penetration.
//
// Vertex-vertex (angle-angle) contacts: when P1 is within the search distance
// of a vertex Q of the other block, only one contact is made, against the
// entrance edge: the edge the vertex would cross first. Among the four edges
// at P1 and Q, a candidate is admissible if the vertex is the other block's
// extreme point toward that edge (both edges at the vertex leave the edge's
// line on the outside, within a few degrees); the entrance edge is the
// admissible candidate with the largest dn (the separating-axis choice).
#include <algorithm>
#include <functional>
#include <tuple>
#include <utility>
#include <vector>

#include "dda/common/geometry.hpp"

namespace dda::df {

struct ContactCandidate {
  int vblock = -1, vertex = -1;  // block and vertex index of P1
  int eblock = -1, edge = -1;    // block and edge index (vertex edge -> edge+1)
  double dn = 0;                 // signed normal distance at detection, m
  bool vertex_vertex = false;    // came from the angle-angle rule
};

// The contacts of the last step by (vblock, vertex, eblock[, edge]), for
// carrying their states over: a flat sorted array (no sort when the contacts
// come sorted, as detection leaves them) with where each vertex block's keys
// start, so that a lookup bisects only that block's few keys (a bisection of
// all of them cost a cache miss a level: 300k keys on a 50k-block model).
// Read-only after construction, so threads may share it.
class ContactIndex {
 public:
  ContactIndex() = default;
  // C has int members vblock, vertex, eblock, edge (a Contact).
  template <class C>
  explicit ContactIndex(const std::vector<C>& contacts) {
    keys_.reserve(contacts.size());
    int blocks = 0;
    for (std::size_t k = 0; k < contacts.size(); ++k) {
      const C& c = contacts[k];
      keys_.push_back({c.vblock, c.vertex, c.eblock, c.edge, static_cast<int>(k)});
      blocks = std::max(blocks, c.vblock + 1);
    }
    if (!std::is_sorted(keys_.begin(), keys_.end())) std::sort(keys_.begin(), keys_.end());
    index_blocks(blocks);
  }
  std::size_t size() const { return keys_.size(); }
  // Index of the contact with all four, or -1 (the last one if several).
  int exact(int vblock, int vertex, int eblock, int edge) const;
  // Index of a contact of that vertex against that block, or -1 (the last
  // one in the original order if several).
  int by_vertex(int vblock, int vertex, int eblock) const;
  // Whether the candidates are the indexed contacts, key for key and in the
  // contacts' order (they are then sorted by key too). Reads the 20-byte
  // keys, not the contacts.
  bool same_keys_in_order(const std::vector<ContactCandidate>& candidates) const;

 private:
  struct Key {
    int vblock, vertex, eblock, edge, index;
    bool operator<(const Key& o) const {
      return std::tie(vblock, vertex, eblock, edge, index) < std::tie(o.vblock, o.vertex, o.eblock, o.edge, o.index);
    }
  };
  void index_blocks(int blocks);
  // The keys of vertex block b, or an empty range.
  std::pair<const Key*, const Key*> block_keys(int vblock) const;

  std::vector<Key> keys_;
  std::vector<int> block_start_;  // keys of vertex block b: [block_start_[b], block_start_[b + 1])
};

// Signed normal distance of p from edge a -> b (CCW edge of its block).
double signed_distance(const Vec2& p, const Vec2& a, const Vec2& b);

// Vertex-edge pairs that may be in contact: for each pair of blocks, the
// vertices of either block within `reach` of an edge of the other (distance
// from the point to the segment). Grouped by block pair: the entries of
// pairs[q] are entries[start[q]] .. entries[start[q + 1] - 1]; pairs with no
// entry are left out.
struct NearPairs {
  struct Entry {
    int vblock, vertex, eblock, edge;
  };
  double reach = 0;
  std::vector<std::pair<int, int>> pairs;
  std::vector<int> start{0};
  std::vector<Entry> entries;
};

// The near pairs of the given block pairs (from the broad phase, with boxes
// grown by reach / 2); boxes[b] is the bounding box of blocks[b].
NearPairs near_pairs(const std::vector<Polygon2>& blocks, const std::vector<Box2>& boxes,
                     const std::vector<std::pair<int, int>>& pairs, double reach);

// All contacts among the near pairs closer than `search_distance` (at most
// `near.reach`). `previous(vblock, vertex, eblock)` says whether the last
// step had a contact with that vertex and block; it breaks near-ties of the
// entrance-edge rule in favour of continuity (may be empty).
std::vector<ContactCandidate> find_contacts(const std::vector<Polygon2>& blocks, const NearPairs& near,
                                            double search_distance,
                                            const std::function<bool(int, int, int)>& previous = {});

// All contacts between the given block pairs closer than `search_distance`:
// the above on near_pairs(blocks, their boxes, pairs, search_distance).
std::vector<ContactCandidate> find_contacts(
    const std::vector<Polygon2>& blocks, const std::vector<std::pair<int, int>>& pairs,
    double search_distance, const std::function<bool(int, int, int)>& previous = {});

}  // namespace dda::df
