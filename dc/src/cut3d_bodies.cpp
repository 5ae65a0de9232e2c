// Which convex parts make one rock body. Two parts touch where opposite
// faces on one plane overlap; they are glued there unless a real
// discontinuity separates them over the whole overlap: a persistent plane
// always does, a finite fracture only if it covers the overlap, and an
// excavation plane never does (it only split the rock to cut the opening).
#include <algorithm>
#include <map>
#include <numeric>

#include "cut3d_internal.hpp"
#include "dda/common/geometry.hpp"

namespace dda::dc::detail3 {

namespace {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int a) {
    while (parent[static_cast<std::size_t>(a)] != a) {
      auto& p = parent[static_cast<std::size_t>(a)];
      p = parent[static_cast<std::size_t>(p)];
      a = p;
    }
    return a;
  }
  void unite(int a, int b) { parent[static_cast<std::size_t>(find(a))] = find(b); }
};

struct FaceRef {
  int cell;
  int face;
  Box3 bounds;
};

// In-plane coordinates: the fracture's own (so its disc or polygon can be
// tested) or any orthonormal pair for an excavation plane.
class PlaneFrame {
 public:
  PlaneFrame(const Work& w, int plane) {
    const int f = w.plane_fracture[static_cast<std::size_t>(plane)];
    if (f >= 0) {
      extent_ = &w.extents[static_cast<std::size_t>(f)];
      return;
    }
    const Vec3 n = w.table[plane].n.normalized();
    const Vec3 any = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    e1_ = n.cross(any).normalized();
    e2_ = n.cross(e1_);
  }
  Vec2 operator()(const Vec3& p) const { return extent_ ? extent_->in_plane(p) : Vec2(p.dot(e1_), p.dot(e2_)); }
  const FractureExtent* extent() const { return extent_; }

 private:
  const FractureExtent* extent_ = nullptr;
  Vec3 e1_{1, 0, 0}, e2_{0, 1, 0};
};

Polygon2 face_2d(const cell::Cell& c, const cell::Face& f, const PlaneFrame& frame) {
  Polygon2 p;
  for (int v : f.loop) p.push_back(frame(c.vertices[static_cast<std::size_t>(v)].x));
  make_counter_clockwise(p);
  return p;
}

bool boxes_meet(const Box3& a, const Box3& b, double tol) {
  return (a.lo.array() <= b.hi.array() + tol).all() && (b.lo.array() <= a.hi.array() + tol).all();
}

}  // namespace

std::vector<int> glue_bodies(const Work& w, int& body_count, std::size_t& glued_fractures,
                             std::vector<std::vector<std::uint8_t>>& contact) {
  UnionFind uf(w.cells.size());
  // Faces that meet another part across a fracture that covers the overlap:
  // a contact if that part ends up in another body, a closed crack inside
  // the body if not (known only once every glue is found).
  std::vector<std::pair<FaceRef, FaceRef>> covered;
  // Faces on planes that can glue, by plane.
  std::map<int, std::vector<FaceRef>> by_plane;
  for (std::size_t c = 0; c < w.cells.size(); ++c)
    for (std::size_t f = 0; f < w.cells[c].faces.size(); ++f) {
      const cell::Face& face = w.cells[c].faces[f];
      const PlaneRole r = w.role[static_cast<std::size_t>(face.plane)];
      if (r != PlaneRole::Finite && r != PlaneRole::Excavation) continue;
      Box3 b{Vec3::Constant(1e300), Vec3::Constant(-1e300)};
      for (int v : face.loop) {
        b.lo = b.lo.cwiseMin(w.cells[c].vertices[static_cast<std::size_t>(v)].x);
        b.hi = b.hi.cwiseMax(w.cells[c].vertices[static_cast<std::size_t>(v)].x);
      }
      by_plane[face.plane].push_back({static_cast<int>(c), static_cast<int>(f), b});
    }
  std::vector<bool> fracture_glues(w.extents.size(), false);
  for (auto& [plane, faces] : by_plane) {
    const PlaneFrame frame(w, plane);
    // Sweep along x: a pair can overlap only if their x ranges do.
    std::sort(faces.begin(), faces.end(), [](const FaceRef& p, const FaceRef& q) { return p.bounds.lo.x() < q.bounds.lo.x(); });
    std::vector<Polygon2> flat(faces.size());
    auto polygon = [&](std::size_t k) -> const Polygon2& {
      if (flat[k].empty()) {
        const cell::Cell& c = w.cells[static_cast<std::size_t>(faces[k].cell)];
        flat[k] = face_2d(c, c.faces[static_cast<std::size_t>(faces[k].face)], frame);
      }
      return flat[k];
    };
    auto sense = [&](std::size_t k) {
      return w.cells[static_cast<std::size_t>(faces[k].cell)].faces[static_cast<std::size_t>(faces[k].face)].sense;
    };
    for (std::size_t i = 0; i < faces.size(); ++i) {
      const auto& a = faces[i];
      const double tol = 1e-9 * (a.bounds.hi - a.bounds.lo).norm();
      for (std::size_t j = i + 1; j < faces.size() && faces[j].bounds.lo.x() <= a.bounds.hi.x() + tol; ++j) {
        const auto& b = faces[j];
        if (sense(i) == sense(j) || !boxes_meet(a.bounds, b.bounds, tol)) continue;
        if (uf.find(a.cell) == uf.find(b.cell) && !frame.extent()) continue;  // already one body
        const Polygon2 overlap = clip_to_convex(polygon(j), polygon(i));
        // Faces that only touch along an edge leave a sliver of rounding
        // (~1e-16 of their size squared): not an overlap.
        const double size_a = (a.bounds.hi - a.bounds.lo).norm(), size_b = (b.bounds.hi - b.bounds.lo).norm();
        if (overlap.size() < 3 || std::abs(signed_area(overlap)) <= 1e-10 * size_a * size_b) continue;
        if (frame.extent() && frame.extent()->covers(overlap)) {  // a real joint here
          covered.push_back({a, b});
          continue;
        }
        uf.unite(a.cell, b.cell);
        const int f = w.plane_fracture[static_cast<std::size_t>(plane)];
        if (f >= 0) fracture_glues[static_cast<std::size_t>(f)] = true;
      }
    }
  }
  glued_fractures = static_cast<std::size_t>(std::count(fracture_glues.begin(), fracture_glues.end(), true));
  contact.assign(w.cells.size(), {});
  for (std::size_t c = 0; c < w.cells.size(); ++c) contact[c].assign(w.cells[c].faces.size(), 0);
  for (const auto& [a, b] : covered)
    if (uf.find(a.cell) != uf.find(b.cell)) {
      contact[static_cast<std::size_t>(a.cell)][static_cast<std::size_t>(a.face)] = 1;
      contact[static_cast<std::size_t>(b.cell)][static_cast<std::size_t>(b.face)] = 1;
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
