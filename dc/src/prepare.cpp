// Input segments for the arrangement: the domain outline, the excavation
// outlines and the lines, clipped to the domain.
//
// Conventions (see also the report keys in cut.cpp):
//  * Every line is extended by `snap` (1e-9 x model diagonal, at least a few
//    rounding units of the coordinates) at both ends before clipping. A joint
//    that DL ended "on" another line or on the boundary in floating point
//    therefore really crosses it; the overshoot is a dangling stub that the
//    cutter removes. Gaps narrower than `snap` are closed.
//  * A clipped end is put `snap` outside the domain for the same reason.
//  * Lines (or clipped pieces) shorter than min_segment_length are dropped.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "cut_internal.hpp"
#include "dda/common/error.hpp"

namespace dda::dc::detail {
namespace {

bool lex_less(const Vec2& a, const Vec2& b) {
  return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
}

// Removes consecutive duplicates (and a closing vertex) and orients CCW.
Polygon2 clean_polygon(const Polygon2& in, const char* what, std::size_t index) {
  Polygon2 out;
  for (const Vec2& p : in)
    if (out.empty() || p != out.back()) out.push_back(p);
  while (out.size() > 1 && out.front() == out.back()) out.pop_back();
  if (out.size() < 3 || signed_area(out) == 0) {
    std::ostringstream s;
    s << "The " << what;
    if (index != static_cast<std::size_t>(-1)) s << ' ' << index;
    s << " polygon has no area (it needs at least 3 distinct vertices that are not collinear).";
    throw InputError(s.str());
  }
  make_counter_clockwise(out);
  return out;
}

void add_outline(PreparedInput& out, const Polygon2& poly, Origin::Kind kind, int set, int index) {
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[(i + 1) % n];
    Origin o;
    o.kind = kind;
    o.set = set;
    o.index = index;
    o.lex_forward = lex_less(a, b);
    out.origins.push_back(o);
    out.segments.push_back({a, b, 0.0, 1.0, static_cast<int>(out.origins.size()) - 1});
  }
}

// Parameters t in (0, 1) where segment a->b meets the polygon outline.
void crossings(const Vec2& a, const Vec2& b, const Polygon2& poly, std::vector<double>& ts) {
  const Vec2 r = b - a;
  const double bxlo = std::min(a.x(), b.x()), bxhi = std::max(a.x(), b.x());
  const double bylo = std::min(a.y(), b.y()), byhi = std::max(a.y(), b.y());
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& p = poly[i];
    const Vec2& q = poly[(i + 1) % n];
    if (std::max(p.x(), q.x()) < bxlo || std::min(p.x(), q.x()) > bxhi ||
        std::max(p.y(), q.y()) < bylo || std::min(p.y(), q.y()) > byhi)
      continue;
    const Vec2 s = q - p;
    const double den = cross(r, s);
    if (den == 0) continue;  // parallel: the midpoint tests decide
    const Vec2 ap = p - a;
    const double t = cross(ap, s) / den;
    const double u = cross(ap, r) / den;
    if (u >= 0 && u <= 1 && t > 0 && t < 1) ts.push_back(t);
  }
}

}  // namespace

int edge_set_of(const std::vector<int>& ids, const std::vector<Origin>& origins) {
  // rank: boundary 0, excavation 1, line 2 (then lowest set), artificial 3
  int best_rank = 4, best_set = kArtificialSet;
  for (int id : ids) {
    const Origin& o = origins[static_cast<std::size_t>(id)];
    int rank = 3;
    switch (o.kind) {
      case Origin::Kind::Boundary: rank = 0; break;
      case Origin::Kind::Excavation: rank = 1; break;
      case Origin::Kind::Line: rank = 2; break;
      case Origin::Kind::Artificial: rank = 3; break;
    }
    if (rank < best_rank || (rank == best_rank && o.set < best_set)) {
      best_rank = rank;
      best_set = o.set;
    }
  }
  return best_set;
}

PreparedInput prepare_segments(const LineModel& m, const CutOptions& options) {
  PreparedInput out;
  out.input_lines = static_cast<long long>(m.lines.size());
  out.has_domain = !m.domain.empty();

  Polygon2 domain;
  if (out.has_domain) domain = clean_polygon(m.domain, "domain", static_cast<std::size_t>(-1));
  std::vector<Polygon2> excavations;
  for (std::size_t k = 0; k < m.excavations.size(); ++k)
    excavations.push_back(clean_polygon(m.excavations[k], "excavation", k));

  // Scale of the model: the domain's diagonal, or the lines' box diagonal.
  Polygon2 cloud;
  double max_abs = 0;
  if (out.has_domain) {
    cloud = domain;
  } else {
    for (const JointLine& l : m.lines) {
      cloud.push_back(l.a);
      cloud.push_back(l.b);
    }
    for (const Polygon2& e : excavations) cloud.insert(cloud.end(), e.begin(), e.end());
  }
  for (const JointLine& l : m.lines) {
    if (!std::isfinite(l.a.x()) || !std::isfinite(l.a.y()) || !std::isfinite(l.b.x()) ||
        !std::isfinite(l.b.y())) {
      std::ostringstream s;
      s << "Line " << (&l - m.lines.data()) << " has a coordinate that is not a finite number.";
      throw InputError(s.str());
    }
    if (l.set < 0) {
      std::ostringstream s;
      s << "Line " << (&l - m.lines.data()) << " has joint set " << l.set
        << "; joint sets of lines must be >= 0.";
      throw InputError(s.str());
    }
    max_abs = std::max({max_abs, std::abs(l.a.x()), std::abs(l.a.y()), std::abs(l.b.x()),
                        std::abs(l.b.y())});
  }
  for (const Vec2& p : cloud) max_abs = std::max({max_abs, std::abs(p.x()), std::abs(p.y())});
  if (!cloud.empty()) {
    const Box2 box = bounding_box(cloud);
    out.scale = std::hypot(box.width(), box.height());
  }
  if (!(out.scale > 0)) out.scale = 1;
  out.min_segment_length =
      options.min_segment_length > 0 ? options.min_segment_length : 1e-9 * out.scale;
  out.snap = std::max(1e-9 * out.scale, 1e-13 * max_abs);

  if (out.has_domain) add_outline(out, domain, Origin::Kind::Boundary, kBoundarySet, -1);
  for (std::size_t k = 0; k < excavations.size(); ++k)
    add_outline(out, excavations[k], Origin::Kind::Excavation, kExcavationSet, static_cast<int>(k));

  std::vector<double> ts;
  for (std::size_t i = 0; i < m.lines.size(); ++i) {
    const JointLine& l = m.lines[i];
    const double len = (l.b - l.a).norm();
    if (!(len >= out.min_segment_length) || len == 0) {
      ++out.segments_too_short;
      continue;
    }
    // The extended segment in parameters of l.a -> l.b.
    const double ext = out.snap / len;
    const double lo = -ext, hi = 1 + ext;
    const Vec2 a = l.a + lo * (l.b - l.a);
    const Vec2 b = l.a + hi * (l.b - l.a);
    const double elen = len + 2 * out.snap;

    // Pieces of [0, 1] along a->b that lie inside the domain.
    std::vector<std::pair<double, double>> pieces;
    if (!out.has_domain) {
      pieces.emplace_back(0.0, 1.0);
    } else {
      ts.clear();
      crossings(a, b, domain, ts);
      ts.push_back(0.0);
      ts.push_back(1.0);
      std::sort(ts.begin(), ts.end());
      for (std::size_t j = 0; j + 1 < ts.size(); ++j) {
        const double t0 = ts[j], t1 = ts[j + 1];
        if (t1 <= t0) continue;
        const Vec2 mid = a + (0.5 * (t0 + t1)) * (b - a);
        if (!point_in_polygon(domain, mid)) continue;
        if (!pieces.empty() && pieces.back().second == t0)
          pieces.back().second = t1;
        else
          pieces.emplace_back(t0, t1);
      }
    }
    if (pieces.empty()) {
      ++out.lines_outside_domain;
      continue;
    }
    if (pieces.size() != 1 || pieces[0].first != 0.0 || pieces[0].second != 1.0) ++out.lines_clipped;
    const double dt = out.snap / elen;
    bool any = false;
    for (auto [t0, t1] : pieces) {
      if ((t1 - t0) * elen < out.min_segment_length) continue;
      if (t0 > 0) t0 = std::max(0.0, t0 - dt);
      if (t1 < 1) t1 = std::min(1.0, t1 + dt);
      // back to parameters along l.a -> l.b
      const double s0 = t0 == 0 ? lo : lo + t0 * (hi - lo);
      const double s1 = t1 == 1 ? hi : lo + t1 * (hi - lo);
      if (!(s1 > s0)) continue;
      Origin o;
      o.kind = Origin::Kind::Line;
      o.set = l.set;
      o.index = static_cast<int>(i);
      o.lex_forward = lex_less(l.a, l.b);
      out.origins.push_back(o);
      out.segments.push_back({l.a, l.b, s0, s1, static_cast<int>(out.origins.size()) - 1});
      any = true;
    }
    if (!any) ++out.segments_too_short;
  }

  Origin art;
  art.kind = Origin::Kind::Artificial;
  art.set = kArtificialSet;
  out.origins.push_back(art);
  out.artificial_origin = static_cast<int>(out.origins.size()) - 1;
  return out;
}

}  // namespace dda::dc::detail
