// Excavations and the bodies they leave: a block partly inside a convex
// region is cut by the region's planes one after another; what lies outside
// each plane is kept as a convex piece and the rest goes on to the next
// plane; what is left after the last plane is inside and removed. The kept
// pieces are glued to each other along the planes that separated them.
#include <Eigen/Geometry>
#include <numeric>

#include "cut3d_internal.hpp"
#include "dda/common/geometry.hpp"

namespace dda::dc::detail3 {

namespace {

double cell_volume(const cell::Cell& c) {
  std::vector<Vec3> xs;
  xs.reserve(c.vertices.size());
  for (const auto& v : c.vertices) xs.push_back(v.x);
  std::vector<std::vector<int>> loops;
  for (const auto& f : c.faces) loops.push_back(f.loop);
  return polyhedron_moments(xs, loops).volume;
}

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int a) {
    while (parent[static_cast<std::size_t>(a)] != a) a = parent[static_cast<std::size_t>(a)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(a)])];
    return a;
  }
  void unite(int a, int b) { parent[static_cast<std::size_t>(find(a))] = find(b); }
};

// A face loop in 2D coordinates of its plane, counter-clockwise about the
// plane's own normal whatever the face's sense.
Polygon2 face_in_plane(const cell::Cell& c, const cell::Face& f, const Vec3& n) {
  const Vec3 any = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 e1 = n.cross(any).normalized();
  const Vec3 e2 = n.normalized().cross(e1);
  Polygon2 p;
  for (int v : f.loop) {
    const Vec3& x = c.vertices[static_cast<std::size_t>(v)].x;
    p.emplace_back(x.dot(e1), x.dot(e2));
  }
  make_counter_clockwise(p);
  return p;
}

}  // namespace

void excavate(Work& w, const std::vector<Excavation3>& excavations) {
  int next_origin = 0;
  for (const auto& c : w.cells) next_origin = std::max(next_origin, c.origin + 1);
  std::vector<std::int8_t> sides;
  for (const Excavation3& e : excavations) {
    std::vector<int> planes;
    for (const HalfSpace& hs : e.region.half_spaces) planes.push_back(w.table.add(hs.normal, hs.offset));
    std::vector<cell::Cell> out;
    out.reserve(w.cells.size());
    for (auto& c : w.cells) {
      bool outside = false;
      for (int h : planes) outside = outside || cell::bounds_side(c, w.table[h]) > 0;
      if (outside) {
        out.push_back(std::move(c));
        continue;
      }
      std::vector<cell::Cell> pieces;
      cell::Cell cur = c;
      bool inside = true;
      for (int h : planes) {
        int where = cell::bounds_side(cur, w.table[h]);
        if (where == 0) where = classify(w, cur, h, sides);
        if (where > 0) {
          inside = false;
          break;
        }
        if (where < 0) continue;
        cell::Cell below, above;
        split(w, cur, h, sides, kArtificialSet, below, above);
        above.faces.back().tag = kExcavationSet;  // the cap facing the opening
        pieces.push_back(std::move(above));
        cur = std::move(below);
      }
      if (!inside) {  // nothing of the block is in the opening: keep it whole
        out.push_back(std::move(c));
        continue;
      }
      w.excavated_volume += cell_volume(cur);
      ++w.excavated_pieces;
      const int origin = c.origin >= 0 ? c.origin : next_origin++;
      for (auto& p : pieces) {
        p.origin = origin;
        p.exposed = true;
        out.push_back(std::move(p));
      }
    }
    w.cells = std::move(out);
  }
}

std::vector<int> glue_bodies(const Work& w, int& body_count) {
  UnionFind uf(w.cells.size());
  // Pieces of one origin, glued where an artificial face of one overlaps the
  // opposite face of another on the same plane.
  std::vector<std::vector<int>> by_origin;
  for (std::size_t i = 0; i < w.cells.size(); ++i) {
    const int o = w.cells[i].origin;
    if (o < 0) continue;
    if (by_origin.size() <= static_cast<std::size_t>(o)) by_origin.resize(static_cast<std::size_t>(o) + 1);
    by_origin[static_cast<std::size_t>(o)].push_back(static_cast<int>(i));
  }
  for (const auto& group : by_origin)
    for (int a : group)
      for (const auto& fa : w.cells[static_cast<std::size_t>(a)].faces) {
        if (fa.tag != kArtificialSet) continue;
        const Vec3& n = w.table[fa.plane].n;
        const auto& ca = w.cells[static_cast<std::size_t>(a)];
        const Polygon2 pa = face_in_plane(ca, fa, n);
        const double tol = 1e-9 * (ca.bounds.hi - ca.bounds.lo).norm();
        for (int b : group) {
          if (b == a) continue;
          const auto& cb = w.cells[static_cast<std::size_t>(b)];
          for (const auto& fb : cb.faces)
            if (fb.plane == fa.plane && fb.sense == -fa.sense &&
                convex_polygons_overlap(pa, face_in_plane(cb, fb, n), tol))
              uf.unite(a, b);
        }
      }
  std::vector<int> body(w.cells.size(), -1), root_body(w.cells.size(), -1);
  body_count = 0;
  for (std::size_t i = 0; i < w.cells.size(); ++i) {
    const auto r = static_cast<std::size_t>(uf.find(static_cast<int>(i)));
    if (root_body[r] < 0) root_body[r] = body_count++;
    body[i] = root_body[r];
  }
  return body;
}

}  // namespace dda::dc::detail3
