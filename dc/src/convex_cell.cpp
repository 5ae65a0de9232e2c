#include "convex_cell.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dda/common/error.hpp"

namespace dda::dc::cell {

namespace {

// A vertex whose planes meet at a good angle has double coordinates accurate
// to ~1e-13 of their size, so a plane value far beyond that margin has a
// certain sign; anything else goes to the exact determinant.
constexpr double kConditioned = 1e-6;
constexpr double kMargin = 1e-9;

bool well_conditioned(const PlaneTable& t, const Vertex& v) {
  const auto& p = t[v.planes[0]];
  const auto& q = t[v.planes[1]];
  const auto& r = t[v.planes[2]];
  const double det = std::abs(p.n.dot(q.n.cross(r.n)));
  return det >= kConditioned * p.n.norm() * q.n.norm() * r.n.norm();
}

Vertex make_vertex(const PlaneTable& t, int a, int b, int c) {
  Vertex v;
  v.planes = {a, b, c};
  const int o = exact::orientation(t[a], t[b], t[c]);
  if (o == 0) throw InternalError("3D cutter: a vertex was made from three planes that do not meet in a point");
  v.orient = static_cast<std::int8_t>(o);
  v.x = exact::meeting_point(t[a], t[b], t[c]);
  return v;
}

int vertex_side(const PlaneTable& t, const Vertex& v, const exact::Plane& h) {
  for (int p : v.planes)  // a vertex lies on its own planes
    if (&t[p] == &h) return 0;
  const double value = h.value_at(v.x);
  const double margin = kMargin * (h.n.cwiseAbs().sum() * v.x.cwiseAbs().maxCoeff() + std::abs(h.d));
  if (std::abs(value) > margin && well_conditioned(t, v)) return value > 0 ? 1 : -1;
  return exact::side(t[v.planes[0]], t[v.planes[1]], t[v.planes[2]], v.orient, h);
}

}  // namespace

void Cell::update_bounds() {
  bounds.lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  bounds.hi = -bounds.lo;
  for (const auto& v : vertices) {
    bounds.lo = bounds.lo.cwiseMin(v.x);
    bounds.hi = bounds.hi.cwiseMax(v.x);
  }
}

Cell make_box(const PlaneTable& table, const int plane[6], int tag) {
  Cell c;
  // Corner i + 2j + 4k sits on the x-plane i, the y-plane j and the z-plane k.
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) c.vertices.push_back(make_vertex(table, plane[i], plane[2 + j], plane[4 + k]));
  const int loops[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (int f = 0; f < 6; ++f) c.faces.push_back({plane[f], 1, tag, {loops[f], loops[f] + 4}});
  c.update_bounds();
  return c;
}

PolyhedronMoments moments(const Cell& c) {
  std::vector<Vec3> xs;
  xs.reserve(c.vertices.size());
  for (const auto& v : c.vertices) xs.push_back(v.x);
  std::vector<std::vector<int>> loops;
  loops.reserve(c.faces.size());
  for (const auto& f : c.faces) loops.push_back(f.loop);
  return polyhedron_moments(xs, loops);
}

int bounds_side(const Cell& c, const exact::Plane& h) {
  const Vec3 centre = 0.5 * (c.bounds.lo + c.bounds.hi);
  const Vec3 half = 0.5 * (c.bounds.hi - c.bounds.lo);
  const double value = h.value_at(centre);
  const double reach = h.n.cwiseAbs().dot(half);
  const double margin =
      kMargin * (h.n.cwiseAbs().sum() * (centre.cwiseAbs() + half).maxCoeff() + std::abs(h.d)) + 1e-6 * reach;
  if (value - reach > margin) return 1;
  if (value + reach < -margin) return -1;
  return 0;
}

namespace {

// A face of a convex cell meets a plane in nothing, a vertex, an edge or a
// chord: around its loop the sides form at most one run of each sign, and
// zeros only where the runs meet (one zero each), or, if one sign is absent,
// at most two zeros in a row.
bool face_sides_convex(const Face& f, const std::vector<std::int8_t>& sides) {
  const std::size_t m = f.loop.size();
  int changes = 0, zeros = 0, longest_zero_run = 0, run = 0;
  bool pos = false, neg = false;
  std::int8_t last = 0;
  // Start the walk at a non-zero vertex so runs are not split at the seam.
  std::size_t start = 0;
  while (start < m && sides[static_cast<std::size_t>(f.loop[start])] == 0) ++start;
  if (start == m) return true;  // the face lies in the plane
  for (std::size_t k = 0; k <= m; ++k) {
    const std::int8_t s = sides[static_cast<std::size_t>(f.loop[(start + k) % m])];
    if (s == 0) {
      if (k < m) ++zeros;
      longest_zero_run = std::max(longest_zero_run, ++run);
      continue;
    }
    run = 0;
    pos |= s > 0;
    neg |= s < 0;
    if (last != 0 && s != last) ++changes;
    last = s;
  }
  if (pos && neg) return changes == 2 && zeros <= 2 && longest_zero_run <= 1;
  return zeros <= 2 && longest_zero_run <= 2 && (zeros < 2 || longest_zero_run == 2);
}

int classify_with(const Cell& c, const PlaneTable& table, int h, std::vector<std::int8_t>& sides, double snap) {
  const exact::Plane& plane = table[h];
  const double norm = plane.n.norm();
  sides.resize(c.vertices.size());
  bool below = false, above = false;
  for (std::size_t i = 0; i < c.vertices.size(); ++i) {
    int s;
    if (snap > 0 && std::abs(plane.value_at(c.vertices[i].x)) <= snap * norm) s = 0;
    else s = vertex_side(table, c.vertices[i], plane);
    sides[i] = static_cast<std::int8_t>(s);
    below |= s < 0;
    above |= s > 0;
  }
  if (below && above) return 0;
  return above ? 1 : -1;
}

}  // namespace

int classify(const Cell& c, const PlaneTable& table, int h, std::vector<std::int8_t>& sides, double snap) {
  const int where = classify_with(c, table, h, sides, snap);
  if (snap <= 0 || where != 0) return where;
  for (const Face& f : c.faces)
    if (!face_sides_convex(f, sides)) return classify_with(c, table, h, sides, 0);
  return 0;
}

namespace {

// Dense n x n table of small ints, for edge lookups in one cell.
struct EdgeTable {
  std::size_t n;
  std::vector<int> data;
  explicit EdgeTable(std::size_t n_) : n(n_), data(n_ * n_, -1) {}
  int& at(int a, int b) { return data[static_cast<std::size_t>(a) * n + static_cast<std::size_t>(b)]; }
};

}  // namespace

std::vector<Vec3> section_points(const Cell& c, const PlaneTable& table, int h,
                                 const std::vector<std::int8_t>& sides) {
  std::vector<Vec3> pts;
  const exact::Plane& plane = table[h];
  for (std::size_t i = 0; i < c.vertices.size(); ++i)
    if (sides[i] == 0) pts.push_back(c.vertices[i].x);
  for (const Face& f : c.faces) {
    const std::size_t m = f.loop.size();
    for (std::size_t i = 0; i < m; ++i) {
      const int a = f.loop[i], b = f.loop[(i + 1) % m];
      // Each crossing edge once: from its below end.
      if (sides[static_cast<std::size_t>(a)] < 0 && sides[static_cast<std::size_t>(b)] > 0) {
        const Vec3& xa = c.vertices[static_cast<std::size_t>(a)].x;
        const Vec3& xb = c.vertices[static_cast<std::size_t>(b)].x;
        const double va = plane.value_at(xa), vb = plane.value_at(xb);
        const double t = va / (va - vb);
        pts.push_back(xa + std::clamp(t, 0.0, 1.0) * (xb - xa));
      }
    }
  }
  return pts;
}

void split(const Cell& c, const PlaneTable& table, int h, const std::vector<std::int8_t>& sides, int cap_tag,
           Cell& below, Cell& above, std::vector<Vec3>* section) {
  const int nv = static_cast<int>(c.vertices.size());
  EdgeTable face_of(c.vertices.size());  // directed edge -> face
  for (std::size_t f = 0; f < c.faces.size(); ++f) {
    const auto& loop = c.faces[f].loop;
    for (std::size_t i = 0; i < loop.size(); ++i) face_of.at(loop[i], loop[(i + 1) % loop.size()]) = static_cast<int>(f);
  }
  // New vertices where h crosses an edge: on the edge's two face planes and h.
  std::vector<Vertex> all(c.vertices);
  EdgeTable crossing(c.vertices.size());
  auto side = [&](int v) { return v < nv ? sides[static_cast<std::size_t>(v)] : 0; };
  for (const Face& f : c.faces) {
    const std::size_t m = f.loop.size();
    for (std::size_t i = 0; i < m; ++i) {
      const int a = f.loop[i], b = f.loop[(i + 1) % m];
      if (side(a) * side(b) >= 0 || crossing.at(a, b) >= 0) continue;
      const int other = face_of.at(b, a);
      if (other < 0) throw InternalError("3D cutter: a cell edge has only one face");
      all.push_back(make_vertex(table, f.plane, c.faces[static_cast<std::size_t>(other)].plane, h));
      crossing.at(a, b) = crossing.at(b, a) = static_cast<int>(all.size()) - 1;
    }
  }
  auto on_plane = [&](int v) { return v >= nv || sides[static_cast<std::size_t>(v)] == 0; };

  std::vector<Face> faces_below, faces_above;
  std::vector<int> cap_next(all.size(), -1);
  for (const Face& f : c.faces) {
    Face lo{f.plane, f.sense, f.tag, {}}, hi{f.plane, f.sense, f.tag, {}};
    const std::size_t m = f.loop.size();
    for (std::size_t i = 0; i < m; ++i) {
      const int a = f.loop[i], b = f.loop[(i + 1) % m];
      if (side(a) <= 0) lo.loop.push_back(a);
      if (side(a) >= 0) hi.loop.push_back(a);
      if (side(a) * side(b) < 0) {
        lo.loop.push_back(crossing.at(a, b));
        hi.loop.push_back(crossing.at(a, b));
      }
    }
    if (lo.loop.size() >= 3) {
      // The edge of this face on h runs u -> w; the cap, seen from its own
      // outside, runs w -> u.
      for (std::size_t i = 0; i < lo.loop.size(); ++i) {
        const int u = lo.loop[i], w = lo.loop[(i + 1) % lo.loop.size()];
        if (on_plane(u) && on_plane(w)) cap_next[static_cast<std::size_t>(w)] = u;
      }
      faces_below.push_back(std::move(lo));
    }
    if (hi.loop.size() >= 3) faces_above.push_back(std::move(hi));
  }
  Face cap{h, 1, cap_tag, {}};
  int start = -1;
  for (std::size_t v = 0; v < cap_next.size() && start < 0; ++v)
    if (cap_next[v] >= 0) start = static_cast<int>(v);
  for (int v = start; v >= 0;) {
    cap.loop.push_back(v);
    v = cap_next[static_cast<std::size_t>(v)];
    if (v == start) break;
    if (cap.loop.size() > all.size()) v = -1;  // not a cycle: caught below
  }
  if (cap.loop.size() < 3 || cap.loop.front() != start || cap_next[static_cast<std::size_t>(cap.loop.back())] != start)
    throw InternalError("3D cutter: the section of a cell by a plane is not a closed polygon");

  // Re-index the two parts.
  auto build = [&](Cell& out, std::vector<Face>& faces, bool keep_below) {
    std::vector<int> map(all.size(), -1);
    out = Cell{};
    out.exposed = c.exposed;
    for (int v = 0; v < static_cast<int>(all.size()); ++v) {
      const int s = side(v);
      if (keep_below ? s <= 0 : s >= 0) {
        map[static_cast<std::size_t>(v)] = static_cast<int>(out.vertices.size());
        out.vertices.push_back(all[static_cast<std::size_t>(v)]);
      }
    }
    for (Face& f : faces) {
      for (int& v : f.loop) v = map[static_cast<std::size_t>(v)];
      out.faces.push_back(std::move(f));
    }
    // Drop vertices no face uses (a vertex on h whose every face went to the
    // other side cannot exist in a convex cell, but stay safe).
    out.update_bounds();
  };
  Face cap_above{h, -1, cap_tag, {cap.loop.rbegin(), cap.loop.rend()}};
  if (section) {
    section->clear();
    for (int v : cap.loop) section->push_back(all[static_cast<std::size_t>(v)].x);
  }
  faces_below.push_back(std::move(cap));
  faces_above.push_back(std::move(cap_above));
  build(below, faces_below, true);
  build(above, faces_above, false);
}

}  // namespace dda::dc::cell
