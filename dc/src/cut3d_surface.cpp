// Closed triangulated surfaces, as the domain (the rock is inside) or as
// excavations (the opening is inside).
//
// Cells stay convex and plane-based, so a surface of any shape is met with
// the planes of its triangles: each cell the surface passes through is split
// by the plane of every triangle that meets it. Once every triangle through
// a piece has cut it, no triangle crosses the piece's interior, so the piece
// lies wholly inside or outside the surface and one winding-number test at
// an interior point tells which. A triangle's plane runs on beyond the
// triangle, so it also splits rock that stays rock; those cuts are
// kArtificialSet faces on PlaneRole::Excavation planes, where
// cut3d_bodies.cpp glues the parts back into one body.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "cut3d_internal.hpp"

namespace dda::dc::detail3 {

namespace {

struct MeshPlanes {
  std::vector<int> plane;    // per triangle: its plane in the table, -1 if it has no area
  std::vector<Box3> bounds;  // per triangle, grown by the snap
};

MeshPlanes add_planes(Work& w, const TriangleMesh& m) {
  MeshPlanes out;
  const Box3 box = mesh_bounds(m);
  const double scale = (box.hi - box.lo).norm();
  // The two halves of a flat quad (and a fanned polygon) give one plane, so
  // that rounding in their normals cannot leave slivers between them.
  std::map<std::array<long long, 4>, int> seen;
  for (const auto& t : m.triangles) {
    const Vec3& a = m.vertices[static_cast<std::size_t>(t[0])];
    const Vec3& b = m.vertices[static_cast<std::size_t>(t[1])];
    const Vec3& c = m.vertices[static_cast<std::size_t>(t[2])];
    out.bounds.push_back(Box3{a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c)}.grown(w.snap));
    Vec3 n = (b - a).cross(c - a);
    if (!(n.norm() > 1e-14 * scale * scale)) {  // a needle: it bounds nothing
      out.plane.push_back(-1);
      continue;
    }
    n.normalize();
    const double d = n.dot(a + b + c) / 3.0;
    const std::array<long long, 4> key{std::llround(n.x() * 1e9), std::llround(n.y() * 1e9),
                                       std::llround(n.z() * 1e9), std::llround(d / scale * 1e9)};
    const auto [it, added] = seen.try_emplace(key, -1);
    if (added) it->second = w.add_plane(n, d, PlaneRole::Excavation);
    out.plane.push_back(it->second);
  }
  return out;
}

// The surface's planes, and the planes already in the table that coincide
// with one of them (either way round): a face on a fracture or on the box
// can lie on the surface too.
std::vector<bool> planes_on_surface(const Work& w, int first_plane) {
  std::vector<bool> on(w.table.size(), false);
  for (std::size_t h = static_cast<std::size_t>(first_plane); h < on.size(); ++h) on[h] = true;
  for (int p = 0; p < first_plane; ++p) {
    const exact::Plane& a = w.table[p];
    const double la = a.n.norm();
    for (std::size_t h = static_cast<std::size_t>(first_plane); h < on.size() && !on[static_cast<std::size_t>(p)]; ++h) {
      const exact::Plane& b = w.table[static_cast<int>(h)];
      const double lb = b.n.norm(), cosine = a.n.dot(b.n) / (la * lb);
      if (std::abs(cosine) < 1 - 1e-12) continue;
      // Offsets along the unit normal, b's turned to a's side.
      const double da = -a.d / la, db = (cosine > 0 ? -b.d : b.d) / lb;
      on[static_cast<std::size_t>(p)] = std::abs(da - db) <= w.snap;
    }
  }
  return on;
}

bool boxes_meet(const Box3& a, const Box3& b) {
  return (a.lo.array() <= b.hi.array()).all() && (b.lo.array() <= a.hi.array()).all();
}

// Whether the triangle meets the section of a cell by the triangle's plane
// (points in any order), by separating axes in the plane. Touching within
// `tol` counts as meeting: a triangle that only touches a piece must still
// cut it, or a face of the piece could face rock on one part and open space
// on another.
bool meets_section(const std::array<Vec3, 3>& tri, const std::vector<Vec3>& section, const Vec3& normal, double tol) {
  if (section.size() < 3) return true;
  const Vec3 n = normal.normalized();
  const Vec3 e1 = n.cross(std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).normalized();
  const Vec3 e2 = n.cross(e1);
  auto flat = [&](const Vec3& p) { return Eigen::Vector2d(p.dot(e1), p.dot(e2)); };
  std::vector<Eigen::Vector2d> s, t;
  for (const Vec3& p : section) s.push_back(flat(p));
  for (const Vec3& p : tri) t.push_back(flat(p));
  // The section is convex: ordering its points by angle about their mean
  // gives its outline.
  Eigen::Vector2d mid = Eigen::Vector2d::Zero();
  for (const auto& p : s) mid += p;
  mid /= static_cast<double>(s.size());
  std::sort(s.begin(), s.end(), [&](const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
    return std::atan2(p.y() - mid.y(), p.x() - mid.x()) < std::atan2(q.y() - mid.y(), q.x() - mid.x());
  });
  auto separated_along_edges = [&](const std::vector<Eigen::Vector2d>& poly) {
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Eigen::Vector2d d = poly[(i + 1) % poly.size()] - poly[i];
      if (!(d.norm() > 0)) continue;
      const Eigen::Vector2d axis = Eigen::Vector2d(-d.y(), d.x()) / d.norm();
      double lo_s = 1e300, hi_s = -1e300, lo_t = 1e300, hi_t = -1e300;
      for (const auto& p : s) lo_s = std::min(lo_s, p.dot(axis)), hi_s = std::max(hi_s, p.dot(axis));
      for (const auto& p : t) lo_t = std::min(lo_t, p.dot(axis)), hi_t = std::max(hi_t, p.dot(axis));
      if (hi_s + tol < lo_t || hi_t + tol < lo_s) return true;
    }
    return false;
  };
  return !separated_along_edges(t) && !separated_along_edges(s);
}

// Splits `c` by every plane of a triangle that meets it, into convex pieces
// none of which a triangle crosses. Each part carries on with only the
// triangles still to try that reach its bounds, so a large surface costs
// about as much as the triangles near each part.
std::vector<cell::Cell> pieces_of(Work& w, cell::Cell c, const TriangleMesh& m, const MeshPlanes& planes,
                                  std::size_t& splits) {
  struct Part {
    cell::Cell cell;
    std::vector<int> untried;  // triangles, in order
  };
  std::vector<Part> stack(1);
  stack[0].cell = std::move(c);
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    if (planes.plane[t] >= 0 && boxes_meet(planes.bounds[t], stack[0].cell.bounds)) stack[0].untried.push_back(static_cast<int>(t));
  std::vector<cell::Cell> done;
  std::vector<std::int8_t> sides;
  while (!stack.empty()) {
    Part part = std::move(stack.back());
    stack.pop_back();
    const cell::Cell& p = part.cell;
    std::size_t k = 0;
    for (; k < part.untried.size(); ++k) {
      const auto t = static_cast<std::size_t>(part.untried[k]);
      const int h = planes.plane[t];
      if (!boxes_meet(planes.bounds[t], p.bounds) || cell::bounds_side(p, w.table[h]) != 0) continue;
      if (classify(w, p, h, sides) != 0) continue;
      const std::array<Vec3, 3> tri{m.vertices[static_cast<std::size_t>(m.triangles[t][0])],
                                    m.vertices[static_cast<std::size_t>(m.triangles[t][1])],
                                    m.vertices[static_cast<std::size_t>(m.triangles[t][2])]};
      if (meets_section(tri, cell::section_points(p, w.table, h, sides), w.table[h].n, w.snap)) break;
    }
    if (k == part.untried.size()) {
      done.push_back(std::move(part.cell));
      continue;
    }
    Part below, above;
    split(w, p, planes.plane[static_cast<std::size_t>(part.untried[k])], sides, kArtificialSet, below.cell, above.cell);
    ++splits;
    for (Part* child : {&below, &above}) {
      for (std::size_t r = k + 1; r < part.untried.size(); ++r)
        if (boxes_meet(planes.bounds[static_cast<std::size_t>(part.untried[r])], child->cell.bounds))
          child->untried.push_back(part.untried[r]);
      stack.push_back(std::move(*child));
    }
  }
  return done;
}

Vec3 vertex_mean(const cell::Cell& c) {
  Vec3 s = Vec3::Zero();
  for (const auto& v : c.vertices) s += v.x;
  return s / static_cast<double>(c.vertices.size());
}

// Whether a face on the surface's planes faces the other side of the
// surface: a point just off the face's middle, outward, is tested. The step
// is a fraction of the face's own clearance, so it cannot reach past the
// face's edges, where the surface may turn.
bool faces_across(const cell::Cell& c, const cell::Face& f, const cell::PlaneTable& table, const MeshInsideTest& m,
                  bool piece_inside, double diag) {
  Vec3 mid = Vec3::Zero();
  for (int v : f.loop) mid += c.vertices[static_cast<std::size_t>(v)].x;
  mid /= static_cast<double>(f.loop.size());
  const Vec3 n = (f.sense * table[f.plane].n).normalized();
  double clearance = 1e300;
  for (std::size_t i = 0; i < f.loop.size(); ++i) {
    const Vec3& a = c.vertices[static_cast<std::size_t>(f.loop[i])].x;
    const Vec3& b = c.vertices[static_cast<std::size_t>(f.loop[(i + 1) % f.loop.size()])].x;
    const Vec3 d = b - a;
    if (d.norm() > 0) clearance = std::min(clearance, (mid - a).cross(d).norm() / d.norm());
  }
  const double step = std::min(0.25 * clearance, 1e-6 * diag);
  return m.contains(mid + step * n) != piece_inside;
}

}  // namespace

SurfaceCut cut_by_surface(Work& w, const TriangleMesh& surface, bool keep_inside) {
  TriangleMesh m = surface;
  orient_outward(m);  // the inside test counts +1 inside an outward surface
  SurfaceCut out;
  const int first_plane = static_cast<int>(w.table.size());
  const MeshPlanes planes = add_planes(w, m);
  out.on_surface = planes_on_surface(w, first_plane);
  const Box3 box = mesh_bounds(m).grown(w.snap);
  const double diag = (box.hi - box.lo).norm();
  const int facing_tag = keep_inside ? kBoundarySet : kExcavationSet;
  const MeshInsideTest inside_test(m);

  std::vector<cell::Cell> kept;
  kept.reserve(w.cells.size());
  for (auto& c : w.cells) {
    if (!boxes_meet(c.bounds, box)) {  // wholly outside the surface
      if (!keep_inside) kept.push_back(std::move(c));
      else {
        out.removed_volume += cell::moments(c).volume;
        ++out.removed_pieces;
      }
      continue;
    }
    std::vector<cell::Cell> pieces = pieces_of(w, std::move(c), m, planes, out.splits);
    std::vector<bool> inside(pieces.size());
    bool lost = false;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      inside[i] = inside_test.contains(vertex_mean(pieces[i]));
      lost = lost || inside[i] != keep_inside;
    }
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      cell::Cell& p = pieces[i];
      if (inside[i] != keep_inside) {
        out.removed_volume += cell::moments(p).volume;
        ++out.removed_pieces;
        continue;
      }
      bool faces_opening = lost;
      for (cell::Face& f : p.faces)
        if (out.on_surface[static_cast<std::size_t>(f.plane)] && f.tag != facing_tag &&
            faces_across(p, f, w.table, inside_test, inside[i], diag)) {
          f.tag = facing_tag;
          faces_opening = true;
        }
      // A block can face the opening without losing any of it: where it
      // ends on a joint that is also the opening's wall.
      if (faces_opening && !keep_inside) p.exposed = true;
      kept.push_back(std::move(p));
    }
  }
  w.cells = std::move(kept);
  return out;
}

}  // namespace dda::dc::detail3
