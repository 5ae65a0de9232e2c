// Crossings closer than the snap length are merged into one point before
// the exact arrangement is built (a form of snap rounding, applied only
// where crossings crowd).
//
// Why: joints that nearly meet at one point (a star of joints written to
// 12 decimals, traces of fractures that share a line) cross each other at
// points a few 1e-10 m apart. The exact arrangement keeps every one of
// them: a thousand such joints make 500,000 crossings and as many faces
// smaller than 1e-18 m^2, which cost 15-30 s to build, and the faces around
// them are no simple polygons once their corners are rounded to doubles,
// so the cutter dropped them, 27 % of the rock with them. The rock means
// one point there. So the crossings are found in doubles, those within the
// snap length of each other are grouped, and every segment of a group is
// rerouted through one point of it: the segment is cut there into pieces
// that share that point exactly. The exact arrangement then sees one
// vertex where the segments meet. A segment moves by at most about the
// snap length (1e-9 of the model's size).
//
// Crossings that stand alone (all but a few in any model) are left to the
// exact arrangement as before, and so are exact multiple points (checked in
// exact arithmetic: joints through a corner of a grid). A group is merged onto an outline vertex when it holds one, so
// the domain and excavation outlines keep their corners.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>
#include <vector>

#include "cut_internal.hpp"

namespace dda::dc::detail {
namespace {

struct Crossing {
  Vec2 at;
  int i, j;  // the two segments
};

// Segments bucketed in a uniform grid of cells, each segment listed in the
// cells it passes within `reach` of (walked column by column).
class SegmentGrid {
 public:
  SegmentGrid(const std::vector<Vec2>& from, const std::vector<Vec2>& to, double reach) {
    Vec2 lo(1e300, 1e300), hi(-1e300, -1e300);
    for (std::size_t k = 0; k < from.size(); ++k) {
      lo = lo.cwiseMin(from[k]).cwiseMin(to[k]);
      hi = hi.cwiseMax(from[k]).cwiseMax(to[k]);
    }
    lo_ = lo - Vec2(reach, reach);
    const Vec2 size = hi - lo_ + Vec2(reach, reach);
    // About two cells a segment: few pairs per cell for scattered joints.
    const double cells = std::max(1.0, 2.0 * static_cast<double>(from.size()));
    cell_ = std::max({std::sqrt(size.x() * size.y() / cells), size.x() / 4096, size.y() / 4096, 1e-300});
    nx_ = std::max(1, static_cast<int>(std::ceil(size.x() / cell_)));
    ny_ = std::max(1, static_cast<int>(std::ceil(size.y() / cell_)));
    for (std::size_t k = 0; k < from.size(); ++k) add(static_cast<int>(k), from[k], to[k], reach);
  }

  // Calls fn(members) for every non-empty cell, and tells which cell holds a
  // point (for the crossing to be counted once, in its own cell).
  template <class Fn>
  void for_each_cell(Fn&& fn) const {
    for (const auto& [key, members] : cells_) fn(key, members);
  }
  std::int64_t key_of(const Vec2& p) const {
    const int cx = std::clamp(static_cast<int>(std::floor((p.x() - lo_.x()) / cell_)), 0, nx_ - 1);
    const int cy = std::clamp(static_cast<int>(std::floor((p.y() - lo_.y()) / cell_)), 0, ny_ - 1);
    return static_cast<std::int64_t>(cy) * nx_ + cx;
  }

 private:
  void add(int id, const Vec2& a, const Vec2& b, double reach) {
    const double x0 = std::min(a.x(), b.x()) - reach, x1 = std::max(a.x(), b.x()) + reach;
    const int c0 = column(x0), c1 = column(x1);
    for (int c = c0; c <= c1; ++c) {
      // The segment's y range over this column's x range (widened by reach).
      const double xa = std::max(x0, lo_.x() + c * cell_), xb = std::min(x1, lo_.x() + (c + 1) * cell_);
      double ya, yb;
      if (a.x() == b.x()) {
        ya = std::min(a.y(), b.y()), yb = std::max(a.y(), b.y());
      } else {
        auto y_at = [&](double x) {
          const double t = std::clamp((x - a.x()) / (b.x() - a.x()), 0.0, 1.0);
          return a.y() + t * (b.y() - a.y());
        };
        ya = std::min(y_at(xa), y_at(xb)), yb = std::max(y_at(xa), y_at(xb));
      }
      const int r0 = row(ya - reach), r1 = row(yb + reach);
      for (int r = r0; r <= r1; ++r) cells_[static_cast<std::int64_t>(r) * nx_ + c].push_back(id);
    }
  }
  int column(double x) const { return std::clamp(static_cast<int>(std::floor((x - lo_.x()) / cell_)), 0, nx_ - 1); }
  int row(double y) const { return std::clamp(static_cast<int>(std::floor((y - lo_.y()) / cell_)), 0, ny_ - 1); }

  Vec2 lo_;
  double cell_ = 1;
  int nx_ = 1, ny_ = 1;
  std::unordered_map<std::int64_t, std::vector<int>> cells_;
};

// Where segment a0->a1 meets b0->b1, in doubles, allowing a miss of `reach`
// past either end (joints that nearly meet count as meeting).
bool crossing_of(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1, double reach, Vec2& at) {
  const Vec2 r = a1 - a0, s = b1 - b0;
  const double den = cross(r, s);
  if (den == 0 || !std::isfinite(den)) return false;  // parallel: the exact stage decides overlaps
  const Vec2 ab = b0 - a0;
  const double u = cross(ab, s) / den, v = cross(ab, r) / den;
  const double su = reach / r.norm(), sv = reach / s.norm();
  if (u < -su || u > 1 + su || v < -sv || v > 1 + sv) return false;
  at = a0 + u * r;
  return true;
}

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void join(int a, int b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace

NearCrossings merge_near_crossings(PreparedInput& in) {
  NearCrossings out;
  const std::size_t n = in.segments.size();
  if (n < 2 || !(in.snap > 0)) return out;
  const double pixel = in.snap;
  std::vector<Vec2> from(n), to(n);
  for (std::size_t k = 0; k < n; ++k) {
    const InputSegment& s = in.segments[k];
    from[k] = s.a + s.t0 * (s.b - s.a);
    to[k] = s.a + s.t1 * (s.b - s.a);
  }

  // 1. The crossings, each found once (in the cell that holds it).
  std::vector<Crossing> crossings;
  const SegmentGrid grid(from, to, pixel);
  grid.for_each_cell([&](std::int64_t key, const std::vector<int>& members) {
    for (std::size_t p = 0; p < members.size(); ++p)
      for (std::size_t q = p + 1; q < members.size(); ++q) {
        const int i = members[p], j = members[q];
        Vec2 at;
        if (crossing_of(from[i], to[i], from[j], to[j], pixel, at) && grid.key_of(at) == key)
          crossings.push_back({at, std::min(i, j), std::max(i, j)});
      }
  });
  out.crossings = static_cast<long long>(crossings.size());

  // 2. Groups: crossings in the same or neighbouring pixels (pixel = snap
  // length), so members lie within about three snap lengths of each other.
  const Vec2 origin = crossings.empty() ? Vec2(0, 0) : crossings.front().at;
  auto pixel_of = [&](const Vec2& p) {
    return std::pair<std::int64_t, std::int64_t>(static_cast<std::int64_t>(std::floor((p.x() - origin.x()) / pixel)),
                                                 static_cast<std::int64_t>(std::floor((p.y() - origin.y()) / pixel)));
  };
  struct PairHash {
    std::size_t operator()(const std::pair<std::int64_t, std::int64_t>& k) const {
      return std::hash<std::int64_t>()(k.first * 73856093LL ^ k.second * 19349663LL);
    }
  };
  std::unordered_map<std::pair<std::int64_t, std::int64_t>, int, PairHash> first_in_pixel;
  UnionFind groups(crossings.size());
  for (std::size_t c = 0; c < crossings.size(); ++c) {
    const auto [it, fresh] = first_in_pixel.emplace(pixel_of(crossings[c].at), static_cast<int>(c));
    if (!fresh) groups.join(it->second, static_cast<int>(c));
  }
  for (const auto& [px, c] : first_in_pixel)
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto nb = first_in_pixel.find({px.first + dx, px.second + dy});
        if (nb != first_in_pixel.end()) groups.join(c, nb->second);
      }
  std::vector<std::vector<int>> members(crossings.size());
  for (std::size_t c = 0; c < crossings.size(); ++c) members[groups.find(static_cast<int>(c))].push_back(static_cast<int>(c));

  // 3. One point per group of two or more crossings; the segments through
  // it, with where along them it lies.
  struct Stop {
    double t;  // along from -> to
    Vec2 at;
  };
  std::vector<std::vector<Stop>> stops(n);
  for (const std::vector<int>& group : members) {
    if (group.size() < 2) continue;
    Vec2 mean(0, 0), lo(1e300, 1e300), hi(-1e300, -1e300);
    for (const int c : group) {
      mean += crossings[c].at;
      lo = lo.cwiseMin(crossings[c].at), hi = hi.cwiseMax(crossings[c].at);
    }
    mean /= static_cast<double>(group.size());
    // A chain of pixels longer than a few snap lengths is no point: leave it
    // to the exact stage.
    if ((hi - lo).maxCoeff() > 8 * pixel) continue;
    // An exact multiple point (joints through a corner of a grid, lines
    // through lattice points) is kept as it is: the exact stage handles it,
    // and moving its lines would only break their exact meeting.
    std::vector<std::pair<int, int>> pairs;
    for (const int c : group) pairs.emplace_back(crossings[c].i, crossings[c].j);
    if (crossings_coincide(in, pairs)) continue;
    std::vector<int> through;
    for (const int c : group) through.push_back(crossings[c].i), through.push_back(crossings[c].j);
    std::sort(through.begin(), through.end());
    through.erase(std::unique(through.begin(), through.end()), through.end());
    // The point: a corner of the domain or an excavation in the group, else
    // the crossing nearest the group's mean.
    Vec2 point = crossings[group.front()].at;
    double best = 1e300;
    for (const int c : group)
      if ((crossings[c].at - mean).squaredNorm() < best) best = (crossings[c].at - mean).squaredNorm(), point = crossings[c].at;
    for (const int k : through) {
      const Origin::Kind kind = in.origins[static_cast<std::size_t>(in.segments[k].origin)].kind;
      if (kind != Origin::Kind::Boundary && kind != Origin::Kind::Excavation) continue;
      for (const Vec2& corner : {from[k], to[k]})
        if ((corner - mean).norm() <= 4 * pixel) point = corner;
    }
    ++out.merged;
    for (const int k : through) {
      const Vec2 r = to[k] - from[k];
      stops[k].push_back({(point - from[k]).dot(r) / r.squaredNorm(), point});
    }
  }

  if (out.merged == 0) return out;  // nothing crowds: the segments stay as they are

  // 4. Every segment with stops is cut into pieces through them. A stop
  // within a snap length of an end moves that end instead. Each piece gets
  // an origin of its own (a copy, with the direction of the piece), so the
  // inside tests of the outlines see the piece's own direction.
  const Origin artificial = in.origins.back();
  in.origins.pop_back();
  std::vector<InputSegment> pieces;
  for (std::size_t k = 0; k < n; ++k) {
    const InputSegment& s = in.segments[k];
    if (stops[k].empty()) {
      pieces.push_back(s);
      continue;
    }
    ++out.rerouted;
    std::vector<Stop>& st = stops[k];
    std::sort(st.begin(), st.end(), [](const Stop& x, const Stop& y) { return x.t < y.t; });
    const double near = pixel / (to[k] - from[k]).norm();
    InputSegment piece = s;
    for (const Stop& stop : st) {
      if (stop.t <= near && !piece.moved_start) {
        piece.moved_start = true, piece.start = stop.at;
        continue;
      }
      if (stop.t >= 1 - near) {
        piece.moved_end = true, piece.end = stop.at;
        break;
      }
      piece.moved_end = true, piece.end = stop.at;
      pieces.push_back(piece);
      piece = s;
      piece.moved_start = true, piece.start = stop.at;
    }
    pieces.push_back(piece);
  }
  // Drop pieces that shrank to a point; give the rest their own origins.
  std::vector<InputSegment> kept;
  for (InputSegment& p : pieces) {
    const Vec2 a = p.moved_start ? p.start : p.a + p.t0 * (p.b - p.a);
    const Vec2 b = p.moved_end ? p.end : p.a + p.t1 * (p.b - p.a);
    if (a == b) continue;
    if (p.moved_start || p.moved_end) {
      Origin o = in.origins[static_cast<std::size_t>(p.origin)];
      o.lex_forward = a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
      in.origins.push_back(o);
      p.origin = static_cast<int>(in.origins.size()) - 1;
    }
    kept.push_back(p);
  }
  in.segments = std::move(kept);
  in.origins.push_back(artificial);
  in.artificial_origin = static_cast<int>(in.origins.size()) - 1;
  return out;
}

}  // namespace dda::dc::detail
