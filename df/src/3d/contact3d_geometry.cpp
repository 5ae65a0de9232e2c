// Vertex-face and edge-edge contacts between convex polyhedra (see the header
// for the linearisation).
#include "dda/df/3d/contact3d_geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

namespace dda::df3 {

namespace {

// Shared by both kinds: everything follows from P, Q, n and the tangent.
ContactGeometry3 linearise(const Vec3& p, const Vec3& ci, const Vec3& q, const Vec3& cj, const Vec3& n,
                           const Vec3& t1_hint) {
  ContactGeometry3 g;
  g.normal = n;
  g.point_i = p;
  g.point_j = q;
  g.dn0 = n.dot(p - q);
  g.t1 = (t1_hint - t1_hint.dot(n) * n).normalized();
  g.t2 = n.cross(g.t1);
  const Matrix3x12d ti = displacement_matrix(p, ci);
  const Matrix3x12d tj = displacement_matrix(q, cj);
  g.en = ti.transpose() * n;
  g.gn = -tj.transpose() * n;
  Eigen::Matrix<double, 2, 3> tt;
  tt.row(0) = g.t1.transpose();
  tt.row(1) = g.t2.transpose();
  g.es = tt * ti;
  g.gs = -tt * tj;
  return g;
}

// An axis-aligned box: the cheap first test of the candidate search.
struct Bounds {
  Vec3 lo, hi;
  bool contains(const Vec3& p) const { return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all(); }
  bool overlaps(const Bounds& o) const { return (lo.array() <= o.hi.array()).all() && (o.lo.array() <= hi.array()).all(); }
};

// The bounds of the points, grown by `margin` on every side.
template <class Points>
Bounds bounds(const Points& points, double margin) {
  Bounds b{Vec3::Constant(1e300), Vec3::Constant(-1e300)};
  for (const Vec3& p : points) b.lo = b.lo.cwiseMin(p), b.hi = b.hi.cwiseMax(p);
  b.lo.array() -= margin;
  b.hi.array() += margin;
  return b;
}

using Edge = PolyEdge;

}  // namespace

// Each undirected edge once, with its two faces (a closed convex polyhedron
// has exactly two per edge).
std::vector<PolyEdge> polyhedron_edges(const Polyhedron& p) {
  std::map<std::pair<int, int>, int> index;
  std::vector<Edge> edges;
  for (int f = 0; f < static_cast<int>(p.faces.size()); ++f) {
    const auto& loop = p.faces[f].vertices;
    for (size_t k = 0; k < loop.size(); ++k) {
      const int u = loop[k], w = loop[(k + 1) % loop.size()];
      const auto key = std::minmax(u, w);
      auto [it, fresh] = index.try_emplace(key, static_cast<int>(edges.size()));
      if (fresh) edges.push_back(Edge{{u, w}, {f, -1}});
      else edges[it->second].faces[1] = f;
    }
  }
  return edges;
}

namespace {

// Foot of x on face f lies in the (convex, CCW from outside) polygon, with
// `tol` metres of slack, so a vertex exactly above a face edge still counts.
bool projects_inside(const Polyhedron& p, const PolyFace& f, const Vec3& x, double tol) {
  const auto& loop = f.vertices;
  for (size_t k = 0; k < loop.size(); ++k) {
    const Vec3& a = p.vertices[loop[k]];
    const Vec3 e = p.vertices[loop[(k + 1) % loop.size()]] - a;
    if (f.normal.dot(e.cross(x - a)) < -tol * e.norm()) return false;
  }
  return true;
}

// How clearly block `p` at vertex v stays on the outer side of a plane with
// normal n: the smallest n.e over the unit edges e leaving v. >= 0 means the
// whole block lies above the plane near v (convexity), i.e. the face is one
// the vertex can enter without the block's own edges crossing it first.
double entry_margin(const Polyhedron& p, const std::vector<Edge>& edges, int v, const Vec3& n) {
  double m = 1;
  for (const auto& e : edges) {
    if (e.v[0] != v && e.v[1] != v) continue;
    const int w = e.v[0] == v ? e.v[1] : e.v[0];
    m = std::min(m, n.dot((p.vertices[w] - p.vertices[v]).normalized()));
  }
  return m;
}

// Vertices of i against faces of j. One face per vertex: a vertex near an
// edge or corner of j qualifies for several faces (it projects onto their
// common boundary, within tolerance). Like the 2D entrance edge, keep the
// admissible face (entry_margin >= -entry_sin) with the largest dn0, the
// separating-axis choice: the face the vertex has crossed least, hence the
// one it entered. Ties in dn0 (a vertex exactly on j's edge) go to the larger
// margin. If none is admissible, the largest margin wins.
void vertex_face_contacts(const Polyhedron& i, const std::vector<Edge>& edges_i, const Polyhedron& j, bool a_is_i,
                          const ContactOptions3& opt, std::vector<ContactCandidate3>& out) {
  const Bounds reach_of_j = bounds(j.vertices, opt.reach);
  for (int v = 0; v < static_cast<int>(i.vertices.size()); ++v) {
    const Vec3& p = i.vertices[v];
    if (!reach_of_j.contains(p)) continue;  // no face of j within reach (most vertices of a neighbour)
    int best = -1;
    double best_dn = 0, best_margin = 0;
    bool best_ok = false;
    std::vector<int> admissible;
    for (int f = 0; f < static_cast<int>(j.faces.size()); ++f) {
      const PolyFace& face = j.faces[f];
      const double dn = face.normal.dot(p - j.vertices[face.vertices[0]]);
      if (std::abs(dn) > opt.reach || !projects_inside(j, face, p, opt.tolerance)) continue;
      const double margin = entry_margin(i, edges_i, v, face.normal);
      const bool ok = margin >= -opt.entry_sin;
      if (ok) admissible.push_back(f);
      bool better = best < 0 || (ok && !best_ok);
      if (!better && ok == best_ok) {
        if (ok)
          better = dn > best_dn + opt.tolerance || (std::abs(dn - best_dn) <= opt.tolerance && margin > best_margin);
        else
          better = margin > best_margin;
      }
      if (better) best = f, best_dn = dn, best_margin = margin, best_ok = ok;
    }
    if (best < 0) continue;
    auto emit = [&](int f, bool preferred) {
      const PolyFace& face = j.faces[f];
      const Vec3& a = j.vertices[face.vertices[0]];
      ContactCandidate3 c;
      c.kind = ContactKind3::VertexFace;
      c.a_is_i = a_is_i;
      c.vertex = v;
      c.face = f;
      c.preferred = preferred;
      c.geo = vertex_face_geometry(p, i.centroid, a, face.normal, j.centroid, j.vertices[face.vertices[1]] - a);
      out.push_back(c);
    };
    emit(best, true);
    if (opt.alternative_faces)
      for (int f : admissible)
        if (f != best) emit(f, false);
  }
}

}  // namespace

ContactGeometry3 vertex_face_geometry(const Vec3& p, const Vec3& ci, const Vec3& on_face, const Vec3& normal,
                                      const Vec3& cj, const Vec3& t1_hint) {
  const Vec3 q = p - normal.dot(p - on_face) * normal;
  return linearise(p, ci, q, cj, normal, t1_hint);
}

namespace {

// The closest points of two non-parallel lines and the contact normal,
// without the linearisation (the candidate search rejects most edge pairs
// on these alone).
struct EdgePair {
  Vec3 normal, p, q;
  double s = 0, t = 0, dn0 = 0;
};

EdgePair closest_points(const Vec3& p1, const Vec3& p2, const Vec3& q1, const Vec3& q2, const Vec3& out_j) {
  const Vec3 a = p2 - p1, b = q2 - q1, w = p1 - q1;
  EdgePair e;
  e.normal = a.cross(b).normalized();
  if (e.normal.dot(out_j) < 0) e.normal = -e.normal;
  // Closest points of the two lines: (P - Q) orthogonal to a and b.
  const double aa = a.dot(a), ab = a.dot(b), bb = b.dot(b), aw = a.dot(w), bw = b.dot(w);
  const double den = aa * bb - ab * ab;  // = |a x b|^2 > 0 for non-parallel lines
  e.s = (ab * bw - bb * aw) / den;
  e.t = (aa * bw - ab * aw) / den;
  e.p = p1 + e.s * a;
  e.q = q1 + e.t * b;
  e.dn0 = e.normal.dot(e.p - e.q);
  return e;
}

ContactGeometry3 edge_geometry(const EdgePair& e, const Vec3& ci, const Vec3& cj, const Vec3& a) {
  ContactGeometry3 g = linearise(e.p, ci, e.q, cj, e.normal, a);
  g.s = e.s;
  g.t = e.t;
  return g;
}

}  // namespace

ContactGeometry3 edge_edge_geometry(const Vec3& p1, const Vec3& p2, const Vec3& ci, const Vec3& q1,
                                    const Vec3& q2, const Vec3& cj, const Vec3& out_j) {
  return edge_geometry(closest_points(p1, p2, q1, q2, out_j), ci, cj, p2 - p1);
}

std::vector<ContactCandidate3> find_contacts3(const Polyhedron& a, const Polyhedron& b, const ContactOptions3& opt) {
  return find_contacts3(a, polyhedron_edges(a), b, polyhedron_edges(b), opt);
}

std::vector<ContactCandidate3> find_contacts3(const Polyhedron& a, const std::vector<PolyEdge>& edges_a,
                                              const Polyhedron& b, const std::vector<PolyEdge>& edges_b,
                                              const ContactOptions3& opt) {
  std::vector<ContactCandidate3> out;
  vertex_face_contacts(a, edges_a, b, true, opt, out);
  vertex_face_contacts(b, edges_b, a, false, opt, out);

  // Edge-edge: a real edge-edge contact has a plane through both edges that
  // separates the blocks, i.e. n lies in b's edge normal cone (between its two
  // face normals) and -n in a's. Without that test, edges that merely pass
  // near each other (one of them hidden behind a face) would be taken.
  // In the plane orthogonal to the edge, n is inside the cone of normals f1, f2
  // iff n.m >= m.f1, m the unit bisector; boundary included (face-face
  // contacts put n on it).
  auto bisector = [](const Polyhedron& p, const Edge& e) {
    return (p.faces[e.faces[0]].normal + p.faces[e.faces[1]].normal).normalized();
  };
  // Edges farther apart than the reach along some axis cannot touch.
  std::vector<Bounds> near_b;
  near_b.reserve(edges_b.size());
  for (const auto& eb : edges_b) near_b.push_back(bounds(std::array{b.vertices[eb.v[0]], b.vertices[eb.v[1]]}, opt.reach));
  const Bounds reach_of_b = bounds(b.vertices, opt.reach);
  for (const auto& ea : edges_a) {
    const Vec3 &p1 = a.vertices[ea.v[0]], &p2 = a.vertices[ea.v[1]];
    const Bounds box_a = bounds(std::array{p1, p2}, 0.0);
    if (!box_a.overlaps(reach_of_b)) continue;
    const Vec3 mi = bisector(a, ea);
    const double cos_i = mi.dot(a.faces[ea.faces[0]].normal);
    for (size_t kb = 0; kb < edges_b.size(); ++kb) {
      if (!box_a.overlaps(near_b[kb])) continue;
      const Edge& eb = edges_b[kb];
      const Vec3 &q1 = b.vertices[eb.v[0]], &q2 = b.vertices[eb.v[1]];
      const Vec3 da = p2 - p1, db = q2 - q1;
      if (da.cross(db).norm() <= opt.parallel_sin * da.norm() * db.norm()) continue;
      const Vec3 mj = bisector(b, eb);
      const EdgePair e = closest_points(p1, p2, q1, q2, mj);
      if (std::abs(e.dn0) > opt.reach) continue;
      // Strictly interior: an end on the other edge is a vertex-face contact.
      const double ts = opt.tolerance / da.norm(), tt = opt.tolerance / db.norm();
      if (e.s <= ts || e.s >= 1 - ts || e.t <= tt || e.t >= 1 - tt) continue;
      if (e.normal.dot(mj) < mj.dot(b.faces[eb.faces[0]].normal) - opt.cone_tol) continue;
      if (-e.normal.dot(mi) < cos_i - opt.cone_tol) continue;
      const ContactGeometry3 g = edge_geometry(e, a.centroid, b.centroid, da);
      ContactCandidate3 c;
      c.kind = ContactKind3::EdgeEdge;
      c.a_is_i = true;
      c.edge_i[0] = ea.v[0], c.edge_i[1] = ea.v[1];
      c.edge_j[0] = eb.v[0], c.edge_j[1] = eb.v[1];
      c.geo = g;
      out.push_back(c);
    }
  }
  return out;
}

}  // namespace dda::df3
