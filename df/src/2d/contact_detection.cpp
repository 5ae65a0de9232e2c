// Narrow phase: vertex-edge contacts and the entrance-edge rule.
#include "dda/df/2d/contact_detection.hpp"
#include "dda/df/core/block_system.hpp"
#include "dda/common/error.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <tuple>

namespace dda::df {
namespace {

// Neighbouring vertex indices of v (0 <= v < n), by comparison: an integer
// division per call was a measurable part of the narrow phase, which takes
// them several times for each of 100k near entries a step.
int prev_index(int n, int v) { return v == 0 ? n - 1 : v - 1; }
int next_index(int n, int v) { return v + 1 == n ? 0 : v + 1; }

// Outward normal of edge k (CCW polygon), as long as the edge.
Vec2 outward_normal(const Polygon2& poly, int k) {
  const Vec2 t = poly[next_index(static_cast<int>(poly.size()), k)] - poly[k];
  return {t.y(), -t.x()};
}

// The vertex is its block's extreme point toward an edge with outward normal
// n when both of its edges leave it on the outside of the edge's line (n
// points from the edge's block toward the vertex's block). A tolerance of a
// few degrees keeps the two contacts of a block resting flat but slightly
// rotated. Compared squared, without normalising: three square roots and
// divisions fewer per candidate, and tens of thousands of candidates a step.
bool admissible(const Polygon2& poly, int v, const Vec2& n) {
  constexpr double kSinTol = 0.0871557;  // sin(5 degrees)
  const int m = static_cast<int>(poly.size());
  const double nn = n.squaredNorm();
  auto outside = [&](const Vec2& side) {  // cos(side, n) >= -sin(5 degrees)
    const double dot = side.dot(n);
    return dot >= 0 || dot * dot <= kSinTol * kSinTol * side.squaredNorm() * nn;
  };
  return outside(poly[prev_index(m, v)] - poly[v]) && outside(poly[next_index(m, v)] - poly[v]);
}

ContactCandidate make(const std::vector<Polygon2>& blocks, int i, int v, int j, int k, bool vv) {
  const Polygon2& e = blocks[j];
  const int m = static_cast<int>(e.size());
  return {i, v, j, k, signed_distance(blocks[i][v], e[k], e[next_index(m, k)]), vv};
}

// A vertex on the inner side of an edge's line (dn < 0) is a real
// penetration of that edge only if it projects onto the edge (not past its
// ends), lies in the edge's block (or on its boundary), and is no nearer to
// another edge of that block that it could touch (admissible, above) than
// to this one: a vertex enters a block through the nearest such edge (its
// penetration is a small part of a step's motion, which the search distance
// bounds). Otherwise it is beside the block, past a neighbouring edge, or
// it entered through another edge:
//  - near a short edge of a thin or non-convex block (a wedge cut off a
//    sloping face, say) the line of one edge runs metres into the space
//    beside it, and a contact with that edge would start with metres of
//    "penetration" and throw the blocks apart (a 3.5 m wedge left a cliff
//    at 38 m/s);
//  - a corner resting on a 9 mm arm of a block, 6 mm from the arm's end,
//    is within the search distance of that end, and a contact with it
//    would start 6 mm deep (33 MN on a 200k-block model, whose roof blocks
//    then flew at 2 m/s).
// A corner pressed into a face at the other block's corner (stacked
// blocks, corners meeting at a joint) lies on the line of the side edge
// there, at distance zero, but could not touch it (inadmissible): the face
// keeps the contact.
// Within `slack` of the line (rounding of faces in touch) none of this is
// checked.
bool plausible(const std::vector<Polygon2>& blocks, const ContactCandidate& c, double slack) {
  if (c.dn >= -slack) return true;
  const Polygon2& e = blocks[c.eblock];
  const Vec2& p = blocks[c.vblock][c.vertex];
  const int m = static_cast<int>(e.size());
  const Vec2& a = e[c.edge];
  const Vec2 d = e[next_index(m, c.edge)] - a;
  const double ratio = (p - a).dot(d) / d.squaredNorm();
  if (ratio < -0.01 || ratio > 1.01) return false;
  // The other edges' distances: no admissible one may be shorter than the
  // depth (less slack); one within slack puts the vertex on the block's
  // boundary (a corner pressed along a side).
  const double depth = -c.dn - slack, depth2 = depth * depth;
  bool on_boundary = false;
  for (int k = 0; k < m; ++k) {
    if (k == c.edge) continue;
    const Vec2& q = e[k];
    const Vec2 f = e[next_index(m, k)] - q;
    const double t = std::clamp((p - q).dot(f) / f.squaredNorm(), 0.0, 1.0);
    const double dist2 = (q + t * f - p).squaredNorm();
    if (dist2 < depth2 && admissible(blocks[c.vblock], c.vertex, outward_normal(e, k))) return false;
    on_boundary = on_boundary || dist2 <= slack * slack;
  }
  return on_boundary || point_in_polygon(e, p);
}

// One contact for vertices (i, v) and (j, w) that nearly coincide.
void resolve_vertex_vertex(const std::vector<Polygon2>& blocks, int i, int v, int j, int w, double d0,
                           const std::function<bool(int, int, int)>& previous,
                           std::vector<ContactCandidate>& out) {
  const int ni = static_cast<int>(blocks[i].size()), nj = static_cast<int>(blocks[j].size());
  const std::array<ContactCandidate, 4> all{make(blocks, i, v, j, prev_index(nj, w), true),
                                            make(blocks, i, v, j, w, true),
                                            make(blocks, j, w, i, prev_index(ni, v), true),
                                            make(blocks, j, w, i, v, true)};
  const ContactCandidate* best = nullptr;
  const double tie = 1e-3 * d0;
  for (const ContactCandidate& c : all) {
    // Whether c may take the place of the best so far is asked before whether
    // it is admissible and plausible (a point-in-polygon test): the answer is
    // the same, and most candidates of a pair fall short of the best.
    if (best && !(c.dn > best->dn - tie)) continue;
    const bool better = !best || c.dn > best->dn + tie;
    if (!better && !(previous && previous(c.vblock, c.vertex, c.eblock) &&
                     !previous(best->vblock, best->vertex, best->eblock)))
      continue;  // a near-tie goes to the contact the last step had
    if (!admissible(blocks[c.vblock], c.vertex, outward_normal(blocks[c.eblock], c.edge))) continue;
    if (!plausible(blocks, c, 1e-6 * d0)) continue;
    best = &c;
  }
  if (best && best->dn <= d0) out.push_back(*best);
}

}  // namespace

void ContactIndex::index_blocks(int blocks) {
  block_start_.assign(static_cast<std::size_t>(blocks) + 1, 0);
  for (const Key& k : keys_) ++block_start_[static_cast<std::size_t>(k.vblock) + 1];
  for (int b = 0; b < blocks; ++b) block_start_[b + 1] += block_start_[b];
}

std::pair<const ContactIndex::Key*, const ContactIndex::Key*> ContactIndex::block_keys(int vblock) const {
  if (vblock < 0 || vblock + 1 >= static_cast<int>(block_start_.size())) return {nullptr, nullptr};
  return {keys_.data() + block_start_[vblock], keys_.data() + block_start_[vblock + 1]};
}

int ContactIndex::exact(int vblock, int vertex, int eblock, int edge) const {
  const auto [first, last] = block_keys(vblock);
  const Key lo{vblock, vertex, eblock, edge, -1};
  int found = -1;
  for (const Key* it = std::lower_bound(first, last, lo);
       it != last && it->vertex == vertex && it->eblock == eblock && it->edge == edge; ++it)
    found = it->index;
  return found;
}

int ContactIndex::by_vertex(int vblock, int vertex, int eblock) const {
  const auto [first, last] = block_keys(vblock);
  const Key lo{vblock, vertex, eblock, std::numeric_limits<int>::min(), -1};
  int found = -1;
  for (const Key* it = std::lower_bound(first, last, lo); it != last && it->vertex == vertex && it->eblock == eblock;
       ++it)
    found = std::max(found, it->index);
  return found;
}

bool ContactIndex::same_keys_in_order(const std::vector<ContactCandidate>& candidates) const {
  if (candidates.size() != keys_.size()) return false;
  const long n = static_cast<long>(candidates.size());
  long differ = 0;
#pragma omp parallel for schedule(static) reduction(+ : differ) if (n > 4 * parallel_grain())
  for (long k = 0; k < n; ++k) {
    const ContactCandidate& a = candidates[static_cast<std::size_t>(k)];
    const Key& b = keys_[static_cast<std::size_t>(k)];
    differ += b.index != k || a.vblock != b.vblock || a.vertex != b.vertex || a.eblock != b.eblock || a.edge != b.edge;
  }
  return differ == 0;
}

double signed_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 e = b - a;
  return cross(p - a, e) / e.norm();
}

NearPairs near_pairs(const std::vector<Polygon2>& blocks, const std::vector<Box2>& boxes,
                     const std::vector<std::pair<int, int>>& pairs, double reach) {
  const int npairs = static_cast<int>(pairs.size());
  // Per thread: its pairs (index into `pairs`, entry count) and entries, in
  // order; joined in thread order, which is pair order (static schedule).
  struct Part {
    std::vector<std::pair<int, int>> pairs;
    std::vector<NearPairs::Entry> entries;
  };
  std::vector<Part> parts;
#pragma omp parallel if (npairs > 2 * parallel_grain())
  {
#pragma omp single
    parts.resize(static_cast<std::size_t>(omp_get_num_threads()));
    Part mine;  // moved into parts at the end (see find_contacts: no shared cache line)
    auto scan = [&](int i, int j) {  // vertices of i against edges of j
      const Polygon2& pi = blocks[i];
      const Polygon2& pj = blocks[j];
      const int ni = static_cast<int>(pi.size()), nj = static_cast<int>(pj.size());
      const Box2& bj = boxes[j];
      for (int v = 0; v < ni; ++v) {
        const Vec2& p = pi[v];
        // Farther than reach from the box of j: from every edge of j too.
        if (p.x() < bj.lo.x() - reach || p.x() > bj.hi.x() + reach || p.y() < bj.lo.y() - reach ||
            p.y() > bj.hi.y() + reach)
          continue;
        for (int k = 0; k < nj; ++k) {
          const Vec2& a = pj[k];
          const Vec2 e = pj[next_index(nj, k)] - a;
          const double l2 = e.squaredNorm();
          if (l2 == 0) continue;
          const double t = std::clamp((p - a).dot(e) / l2, 0.0, 1.0);
          if ((a + t * e - p).squaredNorm() <= reach * reach) mine.entries.push_back({i, v, j, k});
        }
      }
    };
#pragma omp for schedule(static) nowait
    for (int q = 0; q < npairs; ++q) {
      const std::size_t before = mine.entries.size();
      scan(pairs[q].first, pairs[q].second);
      scan(pairs[q].second, pairs[q].first);
      const int count = static_cast<int>(mine.entries.size() - before);
      if (count > 0) mine.pairs.emplace_back(q, count);
    }
    parts[static_cast<std::size_t>(omp_get_thread_num())] = std::move(mine);
  }
  NearPairs near;
  near.reach = reach;
  std::size_t npairs_near = 0, nentries = 0;
  for (const Part& part : parts) {
    npairs_near += part.pairs.size();
    nentries += part.entries.size();
  }
  near.pairs.reserve(npairs_near);
  near.start.reserve(npairs_near + 1);
  near.entries.reserve(nentries);
  for (const Part& part : parts) {
    for (const auto& [q, count] : part.pairs) {
      near.pairs.push_back(pairs[static_cast<std::size_t>(q)]);
      near.start.push_back(near.start.back() + count);
    }
    near.entries.insert(near.entries.end(), part.entries.begin(), part.entries.end());
  }
  return near;
}

std::vector<ContactCandidate> find_contacts(const std::vector<Polygon2>& blocks,
                                            const std::vector<std::pair<int, int>>& pairs, double search_distance,
                                            const std::function<bool(int, int, int)>& previous) {
  std::vector<Box2> boxes;
  boxes.reserve(blocks.size());
  for (const Polygon2& b : blocks) boxes.push_back(bounding_box(b));
  return find_contacts(blocks, near_pairs(blocks, boxes, pairs, search_distance), search_distance, previous);
}

std::vector<ContactCandidate> find_contacts(const std::vector<Polygon2>& blocks, const NearPairs& near,
                                            double search_distance,
                                            const std::function<bool(int, int, int)>& previous) {
  // Pairs are independent (a vertex-vertex contact involves the two blocks
  // of one pair only), so they are scanned in parallel into per-thread
  // lists, which are then sorted into one (see the end). `previous` is only
  // read. The near pairs hold every vertex-edge pair within reach, so the
  // contacts do not depend on how far reach exceeds the search distance.
  const double d0 = search_distance;
  if (d0 > near.reach) throw InternalError("find_contacts: the search distance exceeds the near pairs' reach");
  const int npairs = static_cast<int>(near.pairs.size());
  const int nblocks = static_cast<int>(blocks.size());
  std::vector<std::vector<ContactCandidate>> found;
#pragma omp parallel if (npairs > 2 * parallel_grain())
  {
#pragma omp single
    found.resize(static_cast<std::size_t>(omp_get_num_threads()));
    // A list of this thread's own, moved into `found` at the end: pushing
    // onto found[t] directly had the threads write one cache line (the
    // vectors' ends lie side by side) all the time.
    std::vector<ContactCandidate> out;
    std::vector<std::array<int, 4>> vertex_pairs;  // (lower block, its vertex, other block, its vertex)
#pragma omp for schedule(static) nowait
    for (int q = 0; q < npairs; ++q) {
      vertex_pairs.clear();
      for (int n = near.start[q]; n < near.start[q + 1]; ++n) {
        const auto [i, v, j, k] = near.entries[static_cast<std::size_t>(n)];
        const Polygon2& pi = blocks[i];
        const Polygon2& pj = blocks[j];
        const int nj = static_cast<int>(pj.size());
        const Vec2& p = pi[v];
        const Vec2& a = pj[k];
        const Vec2& b = pj[next_index(nj, k)];
        const Vec2 e = b - a;
        const double l2 = e.squaredNorm();
        if (l2 == 0) continue;
        // Near an end: a vertex-vertex contact. Asked first, since it needs no
        // projection onto the edge and holds for two in three near entries of
        // a layered model (corners meet corners); the vertex is then within
        // d0 of the edge too.
        const double da2 = (p - a).squaredNorm(), db2 = (p - b).squaredNorm();
        if (std::min(da2, db2) < d0 * d0) {
          const int w = da2 <= db2 ? k : next_index(nj, k);
          vertex_pairs.push_back(i < j ? std::array<int, 4>{i, v, j, w} : std::array<int, 4>{j, w, i, v});
          continue;
        }
        const double t = std::clamp((p - a).dot(e) / l2, 0.0, 1.0);
        if ((a + t * e - p).squaredNorm() > d0 * d0) continue;  // no root for the many that are not near
        if (!admissible(pi, v, outward_normal(pj, k))) continue;
        const ContactCandidate c = make(blocks, i, v, j, k, false);
        if (plausible(blocks, c, 1e-6 * d0)) out.push_back(c);
      }
      std::sort(vertex_pairs.begin(), vertex_pairs.end());
      vertex_pairs.erase(std::unique(vertex_pairs.begin(), vertex_pairs.end()), vertex_pairs.end());
      // A vertex near both ends of a short edge (one shorter than d0) pairs
      // with both, and both pairs can resolve to that edge: one contact, not
      // two (two would put its springs in twice). Such repeats come from the
      // vertex pairs of one pair of blocks, so they are dropped here, among
      // the few contacts this pair's vertex pairs made.
      const std::size_t first = out.size();
      for (const auto& vp : vertex_pairs) {
        resolve_vertex_vertex(blocks, vp[0], vp[1], vp[2], vp[3], d0, previous, out);
        if (out.size() < first + 2) continue;
        const ContactCandidate& c = out.back();
        for (std::size_t m = first; m + 1 < out.size(); ++m)
          if (out[m].vblock == c.vblock && out[m].vertex == c.vertex && out[m].eblock == c.eblock &&
              out[m].edge == c.edge) {
            out.pop_back();
            break;
          }
      }
    }
    found[static_cast<std::size_t>(omp_get_thread_num())] = std::move(out);
  }
  // Sorted by (vblock, vertex, eblock, edge): bucketed by vertex block, then
  // each block's few candidates sorted, in parallel (one serial sort of all
  // of them cost a millisecond a step on 10k blocks). Candidates with the
  // same key are equal in every field (a key comes from one pair of blocks),
  // so the result is the one a full sort gives. Each thread counts and
  // places its own list; a bucket holds thread 0's candidates first, in
  // their order, then thread 1's, as a serial pass would place them.
  const int nthreads = static_cast<int>(found.size());
  std::vector<int> count(static_cast<std::size_t>(nthreads) * nblocks, 0);  // [thread][block]
  std::vector<int> start(static_cast<std::size_t>(nblocks) + 1, 0);
  std::vector<ContactCandidate> out;
#pragma omp parallel num_threads(nthreads) if (nthreads > 1 && nblocks > parallel_grain())
  {
    // Lists by thread of the search; by the thread of this team too (one
    // each unless the team came out smaller).
    const int me = omp_get_thread_num(), team = omp_get_num_threads();
    for (int t = me; t < nthreads; t += team) {
      int* at = count.data() + static_cast<std::size_t>(t) * nblocks;
      for (const ContactCandidate& c : found[static_cast<std::size_t>(t)]) ++at[c.vblock];
    }
#pragma omp barrier
#pragma omp single
    {
      for (int b = 0; b < nblocks; ++b) {  // count becomes where each thread's candidates of b go
        int at = start[b];
        for (int u = 0; u < nthreads; ++u) {
          int& n = count[static_cast<std::size_t>(u) * nblocks + b];
          const int here = n;
          n = at;
          at += here;
        }
        start[b + 1] = at;
      }
      out.resize(static_cast<std::size_t>(start[nblocks]));
    }
    for (int t = me; t < nthreads; t += team) {
      int* at = count.data() + static_cast<std::size_t>(t) * nblocks;
      for (const ContactCandidate& c : found[static_cast<std::size_t>(t)]) out[static_cast<std::size_t>(at[c.vblock]++)] = c;
    }
  }
  // Keys are unique: a plain vertex-edge contact has its vertex away from
  // the edge's ends, so no vertex pair makes its key, and the repeats among
  // the vertex pairs' contacts were dropped above. Should one come through
  // all the same, each block drops its own below while its candidates are
  // sorted, and only then are the blocks' lists closed up (in parallel).
  std::vector<int> kept(static_cast<std::size_t>(nblocks) + 1, 0);  // candidates block b keeps, at b + 1
#pragma omp parallel for schedule(static) if (nblocks > parallel_grain())
  for (int b = 0; b < nblocks; ++b) {
    const auto first = out.begin() + start[b], last = out.begin() + start[b + 1];
    std::sort(first, last, [](const ContactCandidate& x, const ContactCandidate& y) {
      return std::tie(x.vertex, x.eblock, x.edge) < std::tie(y.vertex, y.eblock, y.edge);
    });
    const auto end = std::unique(first, last, [](const ContactCandidate& x, const ContactCandidate& y) {
      return std::tie(x.vertex, x.eblock, x.edge) == std::tie(y.vertex, y.eblock, y.edge);
    });
    kept[static_cast<std::size_t>(b) + 1] = static_cast<int>(end - first);
  }
  for (int b = 0; b < nblocks; ++b) kept[b + 1] += kept[b];  // where block b's candidates go
  if (kept[nblocks] == start[nblocks]) return out;
  std::vector<ContactCandidate> unique(static_cast<std::size_t>(kept[nblocks]));
#pragma omp parallel for schedule(static) if (nblocks > parallel_grain())
  for (int b = 0; b < nblocks; ++b)
    std::copy(out.begin() + start[b], out.begin() + start[b] + (kept[b + 1] - kept[b]), unique.begin() + kept[b]);
  out = std::move(unique);
  return out;
}

}  // namespace dda::df
