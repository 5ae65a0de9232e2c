#pragma once
// Geometry of the contacts between two convex 3D blocks, linearised in the
// twelve unknowns of each block (docs/formulation.md, "3D"; issue 6).
//
// A contact is a material point P of block i against a material point Q of
// block j, with a unit normal n pointing from j to i:
//   vertex-face: P a vertex of i, n the outward normal of a face of j, Q the
//                foot of P on the face plane;
//   edge-edge:   P, Q the closest points of an edge of i and an edge of j,
//                n = +-(a x b)/|a x b| (a, b the edge directions), oriented
//                out of block j (see edge_edge_geometry).
// Signed normal distance dn0 = n.(P - Q): positive = gap, negative =
// penetration (the 2D convention of contact_detection.hpp).
//
// Linearisation. With u = T(x) d for both blocks:
//   dn(d_i, d_j) = dn0 + en.d_i + gn.d_j,  en = T_i(P)^T n,  gn = -T_j(Q)^T n.
// Why Q and not the face's own vertices: the face plane moves with block j's
// deformation gradient I + G (G = [r]x + E), which turns its normal into
//   n' = n + r x n - (E n - (n.E n) n)   (first order, strain INCLUDED),
// and n'.(P - A) for any A on the face then reduces to the motion of block j
// at the foot Q (the r-terms and E-terms of the moved normal cancel against
// the difference T_j(A) - T_j(Q)). For edge-edge P - Q is parallel to n and
// the normal's change is orthogonal to n, so the normal's rotation drops out
// and the same formula holds. Both are exact to first order in all twelve
// unknowns, strains included, so dn after a step is dn0 + lin + O(|d|^2).
//
// Shear: the relative tangential motion of P with respect to Q,
//   ds = es d_i + gs d_j  (2-vector, components on t1, t2),
//   es = [t1 t2]^T T_i(P),  gs = -[t1 t2]^T T_j(Q),
// with (t1, t2, n) right-handed and fixed in the step (their rotation is
// second order in the shear displacement, as in 2D).
#include <vector>

#include "dda/common/polyhedron_model.hpp"
#include "dda/df/3d/block3d.hpp"

namespace dda::df3 {

using Matrix2x12d = Eigen::Matrix<double, 2, kDofs>;

enum class ContactKind3 { VertexFace, EdgeEdge };

struct ContactGeometry3 {
  Vec3 normal{0, 0, 1};          // unit, from block j to block i
  double dn0 = 0;                // m, negative = penetration
  Vector12d en = Vector12d::Zero(), gn = Vector12d::Zero();  // d(dn)/d(d_i), d(dn)/d(d_j)
  Vec3 point_i{0, 0, 0};         // P: the vertex, or the closest point on i's edge
  Vec3 point_j{0, 0, 0};         // Q: foot of P on the face, or the closest point on j's edge
  Vec3 t1{1, 0, 0}, t2{0, 1, 0}; // tangent plane, t1 x t2 = n
  Matrix2x12d es = Matrix2x12d::Zero(), gs = Matrix2x12d::Zero();  // d(ds)/d(d_i), d(ds)/d(d_j)
  double s = 0, t = 0;           // edge-edge: P = P1 + s (P2 - P1), Q = Q1 + t (Q2 - Q1)
};

// Vertex p of block i (centroid ci) against the plane through `on_face` with
// outward unit normal `normal` of block j (centroid cj). The tangent t1 is
// `t1_hint` made orthogonal to n (give a face edge; any direction not
// parallel to n works).
ContactGeometry3 vertex_face_geometry(const Vec3& p, const Vec3& ci, const Vec3& on_face, const Vec3& normal,
                                      const Vec3& cj, const Vec3& t1_hint);

// Lines P1P2 (block i) and Q1Q2 (block j), not parallel. n = +-(a x b)/|a x b|
// with the sign that makes n.out_j > 0, out_j being any direction pointing
// out of block j at its edge (the sum of the normals of the edge's two faces;
// the candidate search passes that). t1 = a/|a|. The closest points are those
// of the infinite lines (s, t may fall outside [0, 1]; the caller checks).
ContactGeometry3 edge_edge_geometry(const Vec3& p1, const Vec3& p2, const Vec3& ci, const Vec3& q1,
                                    const Vec3& q2, const Vec3& cj, const Vec3& out_j);

struct ContactCandidate3 {
  ContactKind3 kind = ContactKind3::VertexFace;
  bool a_is_i = true;  // block i (vertex / first edge) is the first argument `a`
  int vertex = -1;     // vertex-face: vertex of i
  int face = -1;       // vertex-face: face of j
  int edge_i[2] = {-1, -1}, edge_j[2] = {-1, -1};  // edge-edge: vertex indices P1 P2, Q1 Q2
  bool preferred = true;  // false: another face of the same vertex (ContactOptions3::alternative_faces)
  ContactGeometry3 geo;
};

struct ContactOptions3 {
  double reach = 0;          // m: keep contacts with |dn0| <= reach
  double tolerance = 1e-9;   // m: slack of the "projects inside the face" and "interior to the edge" tests
  double parallel_sin = 1e-6;  // edges with |a x b| <= this |a||b| are parallel: no edge-edge contact
  double cone_tol = 1e-9;    // slack of the edge-edge normal-cone test (cosine units)
  double entry_sin = 0.087;  // sin 5 deg: how far i's edges at a vertex may dip into a face (see .cpp)
  // Also report the other admissible faces a vertex projects onto (a vertex
  // on an edge or corner of the other block), with preferred = false, so a
  // solver can keep the face a contact already had (simulation3d.hpp).
  bool alternative_faces = false;
};

// Candidate contacts between convex polyhedra a and b, both ways (vertices of
// a on faces of b and vertices of b on faces of a; each crossing edge pair
// once, with a's edge as i). Vertices and centroids are taken as stored.
// Each vertex gets at most one face of the other block (rule in the .cpp),
// unless opt.alternative_faces.
std::vector<ContactCandidate3> find_contacts3(const Polyhedron& a, const Polyhedron& b, const ContactOptions3& opt);

// An undirected edge of a polyhedron: its two vertices and its two faces.
struct PolyEdge {
  int v[2];
  int faces[2] = {-1, -1};
};
// Each edge of a closed convex polyhedron once.
std::vector<PolyEdge> polyhedron_edges(const Polyhedron& p);
// find_contacts3 with the edges of a and b known (polyhedron_edges): a
// detection over many pairs lists each block's edges once.
std::vector<ContactCandidate3> find_contacts3(const Polyhedron& a, const std::vector<PolyEdge>& edges_a,
                                              const Polyhedron& b, const std::vector<PolyEdge>& edges_b,
                                              const ContactOptions3& opt);

}  // namespace dda::df3
