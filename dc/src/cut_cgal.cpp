// The exact part of the 2D block cutter: the only translation unit that
// includes CGAL (compiling it costs ~20 s and 1 GB).
//
// 1. All input segments go into one Arrangement_2 (exact predicates and
//    constructions) with a single aggregated insert (sweep line). Each edge
//    keeps the list of input segments ("origins") it lies on.
// 2. Dangling edges are pruned: antennas from the leaves inward, then any
//    remaining edge with one face on both sides (a bridge), then isolated
//    vertices.
// 3. Faces are classified by a flood fill from the unbounded face: crossing
//    an edge of the domain or of excavation k changes the depth of that
//    polygon by +-1 (the side is known from the direction of the edge
//    against the CCW outline). Inside the domain (or bounded, without a
//    domain) and in no excavation = block.
// 4. Hole points remove the face that contains them.
// 5. Optional sliver merging: remove the longest joint edge shared with a
//    neighbouring block (never a boundary, excavation or artificial edge).
// 6. Faces that are not simply connected (holes, or an outer boundary that
//    touches itself at a vertex) are cut by vertical segments from the top
//    vertex of each hole upward and from its bottom vertex downward to the
//    first edge hit (set kArtificialSet); repeated until all are simple.
// 7. Vertices are rounded to double once each, so neighbouring blocks share
//    bit-identical corners; block faces are handed back as index lists.
#include <CGAL/Arr_curve_data_traits_2.h>
#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arr_walk_along_line_point_location.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <unordered_set>

#include "cut_internal.hpp"
#include "dda/common/error.hpp"

namespace dda::dc::detail {
namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = K::FT;
using Point = K::Point_2;
using SegTraits = CGAL::Arr_segment_traits_2<K>;

// The input segments an edge lies on: one id inline, more (overlaps only) in
// a shared sorted list. Cheaper to copy than CGAL's consolidated std::list,
// which the sweep copies for every sub-curve it makes.
struct Origins {
  int first = -1;
  std::shared_ptr<const std::vector<int>> all;  // set when there are several

  template <class Fn>
  void for_each(Fn&& fn) const {
    if (all)
      for (int id : *all) fn(id);
    else if (first >= 0)
      fn(first);
  }
  bool contains(int id) const {
    if (all) return std::binary_search(all->begin(), all->end(), id);
    return first == id;
  }
  bool operator==(const Origins& o) const {
    std::vector<int> a, b;
    for_each([&](int id) { a.push_back(id); });
    o.for_each([&](int id) { b.push_back(id); });
    return a == b;
  }
};
struct MergeOrigins {
  Origins operator()(const Origins& x, const Origins& y) const {
    std::vector<int> ids;
    x.for_each([&](int id) { ids.push_back(id); });
    y.for_each([&](int id) { ids.push_back(id); });
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    Origins r;
    r.first = ids.empty() ? -1 : ids.front();
    if (ids.size() > 1) r.all = std::make_shared<const std::vector<int>>(std::move(ids));
    return r;
  }
};
struct ToOrigins {
  Origins operator()(int id) const { return Origins{id, nullptr}; }
};
using Traits = CGAL::Arr_curve_data_traits_2<SegTraits, Origins, MergeOrigins, int, ToOrigins>;

enum class FaceKind : int { Unknown = 0, Outside, Excavated, Block, HoleRemoved };

struct VInfo {
  int id = -1;  // index into ArrangementResult::points
};
struct HInfo {
  int set = kArtificialSet;  // edge set, filled before extraction
};
struct FInfo {
  FaceKind kind = FaceKind::Unknown;
  int dom = 0;          // depth inside the domain outline
  int exc = 0;          // number of excavations containing the face
  bool visited = false;
  int block = -1;       // index into ArrangementResult::faces
};

using Dcel = CGAL::Arr_extended_dcel<Traits, VInfo, HInfo, FInfo>;
using Arr = CGAL::Arrangement_2<Traits, Dcel>;
using VH = Arr::Vertex_handle;
using HH = Arr::Halfedge_handle;
using FH = Arr::Face_handle;
using XCurve = Traits::X_monotone_curve_2;

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Rounds an exact coordinate to double: the middle of its interval when that
// is tighter than 1e-12 relative (error < 5e-13 x the coordinate, far below
// the snap length), else from the exact value (slow: GMP). CGAL's own
// to_double would accept a relative error of 1e-5.
double round_coordinate(const FT& x) {
  const auto& iv = x.approx();
  const double lo = iv.inf(), hi = iv.sup();
  if (lo == hi) return lo + 0.0;  // + 0.0 turns -0 into 0
  const double mag = std::max(std::abs(lo), std::abs(hi));
  if (hi - lo <= 1e-12 * mag) return 0.5 * (lo + hi) + 0.0;
  x.exact();
  const auto& iv2 = x.approx();
  return 0.5 * (iv2.inf() + iv2.sup()) + 0.0;
}

Point segment_point(const InputSegment& s, double t) {
  if (t == 0) return Point(s.a.x(), s.a.y());
  if (t == 1) return Point(s.b.x(), s.b.y());
  const FT ax(s.a.x()), ay(s.a.y()), ft(t);
  return Point(ax + ft * (FT(s.b.x()) - ax), ay + ft * (FT(s.b.y()) - ay));
}

class Cutter : public ArrangementOwner {
 public:
  Cutter(const PreparedInput& in, ArrangementResult& out) : in_(in), out_(out) {}

  void build() {
    const auto t0 = Clock::now();
    std::vector<Traits::Curve_2> curves;
    curves.reserve(in_.segments.size());
    for (const InputSegment& s : in_.segments) {
      const Point p = s.moved_start ? Point(s.start.x(), s.start.y()) : segment_point(s, s.t0);
      const Point q = s.moved_end ? Point(s.end.x(), s.end.y()) : segment_point(s, s.t1);
      if (p == q) continue;  // cannot happen for t1 > t0 and a != b, nor for a piece (near_crossings.cpp)
      curves.emplace_back(SegTraits::Curve_2(p, q), s.origin);
    }
    out_.seconds_curves = seconds_since(t0);
    CGAL::insert(arr_, curves.begin(), curves.end());
    out_.arrangement_vertices = static_cast<long long>(arr_.number_of_vertices());
    out_.arrangement_edges = static_cast<long long>(arr_.number_of_edges());
    out_.arrangement_faces = static_cast<long long>(arr_.number_of_faces());
  }

  // Removes every edge that has the same face on both sides, and isolated
  // vertices. Returns the number of edges removed.
  long long prune() {
    long long removed = 0;
    for (;;) {
      std::vector<VH> leaves;
      for (auto v = arr_.vertices_begin(); v != arr_.vertices_end(); ++v)
        if (!v->is_isolated() && v->degree() == 1) leaves.push_back(v);
      while (!leaves.empty()) {
        VH v = leaves.back();
        leaves.pop_back();
        if (v->is_isolated() || v->degree() != 1) continue;
        HH h = v->incident_halfedges();
        VH other = h->source();
        arr_.remove_edge(h, false, false);
        ++removed;
        if (!other->is_isolated() && other->degree() == 1) leaves.push_back(other);
      }
      std::vector<HH> bridges;
      for (auto e = arr_.edges_begin(); e != arr_.edges_end(); ++e)
        if (e->face() == e->twin()->face()) bridges.push_back(e);
      if (bridges.empty()) break;
      // Removing one bridge leaves the others bridges; handles stay valid.
      for (HH h : bridges) {
        arr_.remove_edge(h, false, false);
        ++removed;
      }
    }
    std::vector<VH> isolated;
    for (auto v = arr_.vertices_begin(); v != arr_.vertices_end(); ++v)
      if (v->is_isolated()) isolated.push_back(v);
    for (VH v : isolated) arr_.remove_isolated_vertex(v);
    out_.isolated_vertices_removed += static_cast<long long>(isolated.size());
    return removed;
  }

  void number_vertices() {
    for (auto v = arr_.vertices_begin(); v != arr_.vertices_end(); ++v)
      if (v->data().id < 0) new_vertex_id(v);
  }

  void classify() {
    FH uf = arr_.unbounded_face();
    uf->data().visited = true;
    std::vector<FH> stack{uf};
    auto visit_ccb = [&](FH f, Arr::Ccb_halfedge_circulator first) {
      auto c = first;
      do {
        HH h = c;
        FH g = h->twin()->face();
        if (!g->data().visited) {
          int ddom = 0, dexc = 0;
          const bool h_lex = h->direction() == CGAL::ARR_LEFT_TO_RIGHT;
          h->curve().data().for_each([&](int id) {
            const Origin& o = in_.origins[static_cast<std::size_t>(id)];
            if (o.kind != Origin::Kind::Boundary && o.kind != Origin::Kind::Excavation) return;
            // f lies left of h; the polygon's inside lies left of its CCW edges.
            const int step = (h_lex == o.lex_forward) ? -1 : +1;
            (o.kind == Origin::Kind::Boundary ? ddom : dexc) += step;
          });
          g->data().visited = true;
          g->data().dom = f->data().dom + ddom;
          g->data().exc = f->data().exc + dexc;
          stack.push_back(g);
        }
      } while (++c != first);
    };
    while (!stack.empty()) {
      FH f = stack.back();
      stack.pop_back();
      if (f->has_outer_ccb()) visit_ccb(f, f->outer_ccb());
      for (auto ic = f->inner_ccbs_begin(); ic != f->inner_ccbs_end(); ++ic) visit_ccb(f, *ic);
    }
    for (auto f = arr_.faces_begin(); f != arr_.faces_end(); ++f) {
      FInfo& d = f->data();
      const bool inside = in_.has_domain ? d.dom > 0 : !f->is_unbounded();
      if (f->is_unbounded() || !inside) {
        d.kind = FaceKind::Outside;
        if (!f->is_unbounded()) ++out_.faces_outside_domain;
      } else if (d.exc > 0) {
        d.kind = FaceKind::Excavated;
        ++out_.faces_in_excavations;
      } else {
        d.kind = FaceKind::Block;
      }
      if (!f->is_unbounded()) ++out_.bounded_faces;
      if (inside && !f->is_unbounded()) {
        const double a = face_area(f);
        out_.domain_area += a;
        if (d.kind == FaceKind::Excavated) out_.excavated_area += a;
      }
    }
  }

  // Locates p; returns the face (block if possible) and where it is.
  FH locate(const Vec2& p, int& where) {
    if (!pl_) pl_ = std::make_unique<CGAL::Arr_walk_along_line_point_location<Arr>>(arr_);
    const Point q(p.x(), p.y());
    auto res = pl_->locate(q);
    std::vector<FH> cand;
    if (auto* fh = boost::get<Arr::Face_const_handle>(&res)) {
      cand.push_back(arr_.non_const_handle(*fh));
    } else if (auto* hh = boost::get<Arr::Halfedge_const_handle>(&res)) {
      // On an edge: the block above it (left of the edge directed by
      // increasing x; west of a vertical edge), else the other side.
      HH h = arr_.non_const_handle(*hh);
      if (h->direction() != CGAL::ARR_LEFT_TO_RIGHT) h = h->twin();
      cand.push_back(h->face());
      cand.push_back(h->twin()->face());
    } else if (auto* vh = boost::get<Arr::Vertex_const_handle>(&res)) {
      VH v = arr_.non_const_handle(*vh);
      bool blocked = false;
      FH up = face_in_direction(v, K::Direction_2(0, 1), blocked);
      if (up != FH()) cand.push_back(up);
      if (!v->is_isolated()) {
        auto c = v->incident_halfedges(), first = c;
        do {
          cand.push_back(c->face());
        } while (++c != first);
      } else {
        cand.push_back(v->face());
      }
    }
    for (FH f : cand)
      if (f->data().kind == FaceKind::Block) {
        where = 0;
        return f;
      }
    const FaceKind k = cand.empty() ? FaceKind::Outside : cand.front()->data().kind;
    where = k == FaceKind::Excavated ? 1 : k == FaceKind::HoleRemoved ? 3 : 2;
    return cand.empty() ? FH() : cand.front();
  }

  void remove_hole_points(const std::vector<Vec2>& holes, std::vector<int>& where_out) {
    for (const Vec2& p : holes) {
      int where = 2;
      FH f = locate(p, where);
      where_out.push_back(where);
      if (where == 0) {
        f->data().kind = FaceKind::HoleRemoved;
        out_.excavated_area += face_area(f);
        ++out_.removed_by_hole_points;
      }
    }
  }

  void merge_slivers(const SliverFilter& filter) {
    for (int pass = 0; pass < 50; ++pass) {
      struct Candidate {
        FH f;
        double area;
      };
      std::vector<Candidate> slivers;
      for (auto f = arr_.faces_begin(); f != arr_.faces_end(); ++f) {
        if (f->data().kind != FaceKind::Block) continue;
        const double a = face_area(f);
        const ShapeMeasures sm = shape_measures(outer_polygon(f));
        if (is_sliver(a, sm.aspect, filter)) slivers.push_back({f, a});
      }
      std::stable_sort(slivers.begin(), slivers.end(),
                       [](const Candidate& x, const Candidate& y) { return x.area < y.area; });
      std::unordered_set<const void*> touched;
      long long merged = 0, failed = 0;
      for (const Candidate& c : slivers) {
        if (touched.count(&*c.f)) continue;
        HH best;
        double best_len = -1;
        bool blocked_by_touched = false;
        for_each_ccb_halfedge(c.f, [&](HH h) {
          FH g = h->twin()->face();
          if (g == c.f || g->data().kind != FaceKind::Block) return;
          if (edge_set(h) < 0) return;  // boundary, excavation or artificial
          if (touched.count(&*g)) {
            blocked_by_touched = true;
            return;
          }
          const double len = (point_of(h->source()) - point_of(h->target())).norm();
          if (len > best_len) {
            best_len = len;
            best = h;
          }
        });
        if (best_len < 0) {
          if (!blocked_by_touched) ++failed;
          continue;
        }
        const void* fa = &*c.f;
        const void* fb = &*best->twin()->face();
        FH m = arr_.remove_edge(best, true, true);
        m->data().kind = FaceKind::Block;
        touched.insert(fa);
        touched.insert(fb);
        touched.insert(&*m);
        ++merged;
      }
      out_.slivers_merged += merged;
      out_.dangling_edges_removed += prune();
      out_.sliver_merge_failed = failed;
      if (merged == 0) break;
    }
  }

  // Makes every block face simply connected with vertical cuts.
  void cut_holes() {
    for (int round = 0; round < 12; ++round) {
      struct Work {
        VH top, bottom;  // null if no cut in that direction
      };
      std::vector<Work> work;
      std::unordered_set<const void*> seen_faces;
      for (auto f = arr_.faces_begin(); f != arr_.faces_end(); ++f) {
        if (f->data().kind != FaceKind::Block) continue;
        bool problem = false;
        for (auto ic = f->inner_ccbs_begin(); ic != f->inner_ccbs_end(); ++ic) {
          std::vector<VH> loop;
          auto c = *ic, first = c;
          do {
            loop.push_back(c->target());
          } while (++c != first);
          work.push_back({extreme(loop, +1, VH()), extreme(loop, -1, VH())});
          problem = true;
        }
        if (!problem) {
          if (auto w = pinch_work(f)) {
            work.push_back({w->first, w->second});
            problem = true;
          }
        }
        if (problem && seen_faces.insert(&*f).second && round == 0) ++out_.faces_with_holes;
      }
      if (work.empty()) return;
      for (const Work& w : work) {
        if (w.top != VH()) vertical_cut(w.top, +1);
        if (w.bottom != VH()) vertical_cut(w.bottom, -1);
      }
    }
  }

  void extract(const std::vector<Vec2>& locate_points) {
    // Edge sets once per edge.
    for (auto e = arr_.edges_begin(); e != arr_.edges_end(); ++e) {
      const int s = compute_edge_set(e);
      e->data().set = s;
      e->twin()->data().set = s;
    }
    number_vertices();
    for (auto f = arr_.faces_begin(); f != arr_.faces_end(); ++f) {
      if (f->data().kind != FaceKind::Block) continue;
      RawFace rf;
      rf.has_holes = f->number_of_inner_ccbs() > 0 || f->number_of_isolated_vertices() > 0;
      auto c = f->outer_ccb(), first = c;
      do {
        HH h = c;
        rf.vertex.push_back(h->source()->data().id);
        rf.edge_set.push_back(h->data().set);
      } while (++c != first);
      const std::size_t n = rf.vertex.size();
      rf.straight.assign(n, 0);
      std::size_t i = 0;
      c = first;
      do {
        HH h = c;  // edge i, vertex i is its source
        HH prev = h->prev();
        rf.straight[i] = (prev->data().set == h->data().set && share_origin(prev, h)) ? 1 : 0;
        ++i;
      } while (++c != first);
      {
        std::vector<int> sorted = rf.vertex;
        std::sort(sorted.begin(), sorted.end());
        rf.repeated_vertex = std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
      }
      f->data().block = static_cast<int>(out_.faces.size());
      out_.faces.push_back(std::move(rf));
    }
    for (const Vec2& p : locate_points) {
      int where = 2;
      FH f = locate(p, where);
      out_.point_face.push_back(where == 0 ? f->data().block : -1);
      out_.point_where.push_back(where);
    }
  }

 private:
  const PreparedInput& in_;
  ArrangementResult& out_;
  Arr arr_;
  std::unique_ptr<CGAL::Arr_walk_along_line_point_location<Arr>> pl_;
  std::vector<HH> walk_;
  std::vector<unsigned> seen_at_;
  std::vector<std::size_t> seen_pos_;
  unsigned stamp_ = 0;

  int point_id(VH v) {
    if (v->data().id < 0) new_vertex_id(v);
    return v->data().id;
  }

  void new_vertex_id(VH v) {
    v->data().id = static_cast<int>(out_.points.size());
    out_.points.emplace_back(round_coordinate(v->point().x()), round_coordinate(v->point().y()));
  }

  const Vec2& point_of(VH v) {
    if (v->data().id < 0) new_vertex_id(v);
    return out_.points[static_cast<std::size_t>(v->data().id)];
  }

  template <class Fn>
  void for_each_ccb_halfedge(FH f, Fn&& fn) {
    auto walk = [&](Arr::Ccb_halfedge_circulator first) {
      auto c = first;
      do {
        fn(HH(c));
      } while (++c != first);
    };
    if (f->has_outer_ccb()) walk(f->outer_ccb());
    for (auto ic = f->inner_ccbs_begin(); ic != f->inner_ccbs_end(); ++ic) walk(*ic);
  }

  // Signed area of all boundary cycles of f (holes count negative).
  double face_area(FH f) {
    double total = 0;
    auto ring = [&](Arr::Ccb_halfedge_circulator first) {
      const Vec2 o = point_of(first->source());
      double twice = 0;
      auto c = first;
      do {
        twice += cross(point_of(c->source()) - o, point_of(c->target()) - o);
      } while (++c != first);
      total += 0.5 * twice;
    };
    if (f->has_outer_ccb()) ring(f->outer_ccb());
    for (auto ic = f->inner_ccbs_begin(); ic != f->inner_ccbs_end(); ++ic) ring(*ic);
    return total;
  }

  Polygon2 outer_polygon(FH f) {
    Polygon2 poly;
    if (!f->has_outer_ccb()) return poly;
    auto c = f->outer_ccb(), first = c;
    do {
      poly.push_back(point_of(c->source()));
    } while (++c != first);
    return poly;
  }

  int compute_edge_set(HH h) {
    thread_local std::vector<int> ids;
    ids.clear();
    h->curve().data().for_each([&](int id) { ids.push_back(id); });
    return edge_set_of(ids, in_.origins);
  }
  int edge_set(HH h) { return compute_edge_set(h); }

  static bool share_origin(HH a, HH b) {
    const Origins& ob = b->curve().data();
    bool shared = false;
    a->curve().data().for_each([&](int id) { shared = shared || ob.contains(id); });
    return shared;
  }

  // The vertex of `loop` that is highest (sign +1; ties: rightmost) or lowest
  // (sign -1; ties: leftmost), skipping `except`.
  static VH extreme(const std::vector<VH>& loop, int sign, VH except) {
    VH best;
    for (VH v : loop) {
      if (v == except) continue;
      if (best == VH()) {
        best = v;
        continue;
      }
      const auto cmp = CGAL::compare_xy(K::Point_2(v->point().y(), v->point().x()),
                                        K::Point_2(best->point().y(), best->point().x()));
      if ((sign > 0 && cmp == CGAL::LARGER) || (sign < 0 && cmp == CGAL::SMALLER)) best = v;
    }
    return best;
  }

  // If the outer boundary of f visits a vertex twice, the loop between the
  // two visits that encloses no part of f (clockwise) is treated as a hole
  // touching the boundary: cut up from its top and down from its bottom.
  std::optional<std::pair<VH, VH>> pinch_work(FH f) {
    walk_.clear();
    auto c = f->outer_ccb(), first = c;
    do {
      walk_.push_back(c);
    } while (++c != first);
    // first position of each vertex on this walk, via a per-vertex stamp
    ++stamp_;
    if (seen_at_.size() < out_.points.size()) {
      seen_at_.resize(out_.points.size(), 0);
      seen_pos_.resize(out_.points.size(), 0);
    }
    const std::vector<HH>& walk = walk_;
    for (std::size_t j = 0; j < walk.size(); ++j) {
      VH v = walk[j]->target();
      const std::size_t id = static_cast<std::size_t>(point_id(v));
      if (seen_at_[id] != stamp_) {
        seen_at_[id] = stamp_;
        seen_pos_[id] = j;
        continue;
      }
      const std::size_t i = seen_pos_[id];
      // loop A: walk[i+1..j]; loop B: the rest
      std::vector<VH> a, b;
      double area_a = 0;
      const Vec2 o = point_of(v);
      for (std::size_t k = 0; k < walk.size(); ++k) {
        const bool in_a = k > i && k <= j;
        (in_a ? a : b).push_back(walk[k]->target());
        if (in_a)
          area_a += cross(point_of(walk[k]->source()) - o, point_of(walk[k]->target()) - o);
      }
      const std::vector<VH>& loop = area_a < 0 ? a : b;
      VH top = extreme(loop, +1, v), bottom = extreme(loop, -1, v);
      if (top != VH() && CGAL::compare_xy(K::Point_2(top->point().y(), top->point().x()),
                                          K::Point_2(v->point().y(), v->point().x())) !=
                             CGAL::LARGER)
        top = VH();  // v itself is the top of the loop: the bottom cut suffices
      if (bottom != VH() &&
          CGAL::compare_xy(K::Point_2(bottom->point().y(), bottom->point().x()),
                           K::Point_2(v->point().y(), v->point().x())) != CGAL::SMALLER)
        bottom = VH();
      if (top == VH() && bottom == VH()) bottom = extreme(loop, -1, v);
      return std::make_pair(top, bottom);
    }
    return std::nullopt;
  }

  // The face that the direction d leaves v into; blocked if an edge leaves v
  // exactly in direction d; FH() then.
  FH face_in_direction(VH v, const K::Direction_2& d, bool& blocked) {
    blocked = false;
    if (v->is_isolated()) return v->face();
    auto c = v->incident_halfedges(), first = c;
    if (v->degree() == 1) {
      if (K::Direction_2(c->source()->point() - v->point()) == d) {
        blocked = true;
        return FH();
      }
      return c->face();
    }
    do {
      HH h = c;
      const K::Direction_2 d1(h->next()->target()->point() - v->point());
      const K::Direction_2 d2(h->source()->point() - v->point());
      if (d == d1 || d == d2) {
        blocked = true;
        return FH();
      }
      if (d.counterclockwise_in_between(d1, d2)) return h->face();
    } while (++c != first);
    return FH();
  }

  // Cuts from v straight up (sign +1) or down (-1) to the first edge or
  // vertex of the block face in that direction.
  void vertical_cut(VH v, int sign) {
    bool blocked = false;
    FH f = face_in_direction(v, K::Direction_2(0, sign), blocked);
    if (blocked || f == FH() || f->data().kind != FaceKind::Block) return;
    const FT vx = v->point().x(), vy = v->point().y();
    bool found = false;
    FT best_y;
    VH hit_vertex;
    HH hit_edge;
    auto beyond = [&](const FT& y) { return sign > 0 ? y > vy : y < vy; };
    auto nearer = [&](const FT& y) { return !found || (sign > 0 ? y < best_y : y > best_y); };
    for_each_ccb_halfedge(f, [&](HH h) {
      const Point& p = h->source()->point();
      const Point& q = h->target()->point();
      if (p.x() == q.x()) {
        if (p.x() != vx) return;
        // vertical edge on the ray: its nearer end is hit first
        VH end = (sign > 0) == (p.y() < q.y()) ? h->source() : h->target();
        const FT y = end->point().y();
        if (beyond(y) && nearer(y)) {
          found = true;
          best_y = y;
          hit_vertex = end;
          hit_edge = HH();
        }
        return;
      }
      const FT xlo = CGAL::min(p.x(), q.x()), xhi = CGAL::max(p.x(), q.x());
      if (vx < xlo || vx > xhi) return;
      VH end;
      FT y;
      if (vx == p.x()) {
        end = h->source();
        y = p.y();
      } else if (vx == q.x()) {
        end = h->target();
        y = q.y();
      } else {
        y = p.y() + (vx - p.x()) * (q.y() - p.y()) / (q.x() - p.x());
      }
      if (beyond(y) && nearer(y)) {
        found = true;
        best_y = y;
        hit_vertex = end;
        hit_edge = end == VH() ? h : HH();
      }
    });
    if (!found) {
      out_.warnings.push_back("a vertical cut from a hole found no edge to end on");
      return;
    }
    VH w = hit_vertex;
    if (w == VH()) {
      const Point hp(vx, best_y);
      XCurve c1, c2;
      arr_.geometry_traits()->split_2_object()(hit_edge->curve(), hp, c1, c2);
      HH first_part = arr_.split_edge(hit_edge, c1, c2);
      w = first_part->target();
      new_vertex_id(w);
    }
    if (w == v) return;
    const XCurve cut(SegTraits::X_monotone_curve_2(v->point(), w->point()),
                     Origins{in_.artificial_origin, nullptr});
    HH h = arr_.insert_at_vertices(cut, v, w);
    const FInfo data = f->data();
    h->face()->data() = data;
    h->twin()->face()->data() = data;
    h->face()->data().block = -1;
    h->twin()->face()->data().block = -1;
    ++out_.artificial_cuts;
  }
};

}  // namespace

bool crossings_coincide(const PreparedInput& in, const std::vector<std::pair<int, int>>& pairs) {
  // The first pair's crossing, exactly; then whether every other pair's two
  // lines pass through it (most groups of near crossings fail at their
  // first test, decided by the interval filter without exact arithmetic).
  auto line_of = [&](int k) {
    const InputSegment& s = in.segments[static_cast<std::size_t>(k)];
    return K::Line_2(segment_point(s, 0.0), segment_point(s, 1.0));
  };
  if (pairs.empty()) return true;
  const auto hit = CGAL::intersection(line_of(pairs.front().first), line_of(pairs.front().second));
  const Point* at = hit ? boost::get<Point>(&*hit) : nullptr;
  if (!at) return false;  // parallel or the same line: no single point
  for (const auto& [i, j] : pairs)
    if (!line_of(i).has_on(*at) || !line_of(j).has_on(*at)) return false;
  return true;
}

ArrangementResult cut_arrangement(const PreparedInput& in, const std::vector<Vec2>& hole_points,
                                  const std::vector<Vec2>& locate, const SliverFilter& sliver,
                                  std::vector<int>& hole_where) {
  ArrangementResult out;
  auto cutter_ptr = std::make_unique<Cutter>(in, out);
  Cutter& cutter = *cutter_ptr;
  auto t0 = Clock::now();
  cutter.build();
  out.seconds_arrangement = seconds_since(t0);

  t0 = Clock::now();
  out.dangling_edges_removed += cutter.prune();
  out.seconds_prune = seconds_since(t0);
  auto t1 = Clock::now();
  cutter.number_vertices();
  cutter.classify();
  out.seconds_classify = seconds_since(t1);
  cutter.remove_hole_points(hole_points, hole_where);
  if (sliver.merge && (sliver.min_area > 0 || sliver.max_aspect > 0)) cutter.merge_slivers(sliver);
  t1 = Clock::now();
  cutter.cut_holes();
  out.seconds_cuts = seconds_since(t1);
  out.seconds_topology = seconds_since(t0);

  t0 = Clock::now();
  cutter.extract(locate);
  out.seconds_extract = seconds_since(t0);
  out.owner = std::move(cutter_ptr);
  return out;
}

}  // namespace dda::dc::detail
