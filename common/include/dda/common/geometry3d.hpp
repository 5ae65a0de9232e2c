#pragma once
// Plain 3D geometry on doubles, shared by DL, DC and (later) DF in 3D.
//
// Conventions: x east, y north, z up; metres. A plane is stored as
// normal . x = offset with a unit normal; where a plane has an orientation
// (dip d, dip direction a, degrees) its normal is the upper-hemisphere one,
//   (sin d sin a, sin d cos a, cos d).
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products, used by every 3D caller
#include <vector>

namespace dda {

using Vec3 = Eigen::Vector3d;

// Axis-aligned box [lo.x, hi.x] x [lo.y, hi.y] x [lo.z, hi.z].
struct Box3 {
  Vec3 lo{0, 0, 0};
  Vec3 hi{0, 0, 0};
  double volume() const { return (hi - lo).prod(); }
  Box3 grown(double margin) const {
    const Vec3 m = Vec3::Constant(margin);
    return {lo - m, hi + m};
  }
  bool contains(const Vec3& p) const {
    return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
  }
};

// The closed half-space normal . x <= offset (normal need not be unit).
struct HalfSpace {
  Vec3 normal{0, 0, 1};
  double offset = 0;
  double signed_distance(const Vec3& p) const { return (normal.dot(p) - offset) / normal.norm(); }
};

// A convex region: the intersection of half-spaces (normals point out of the
// region). Excavations (tunnel prisms, a slope's open air) and the domain box
// are convex regions.
struct ConvexRegion {
  std::vector<HalfSpace> half_spaces;
  bool contains(const Vec3& p, double tol = 0) const {
    for (const auto& h : half_spaces)
      if (h.signed_distance(p) > tol) return false;
    return true;
  }
};

// Exact integrals of a closed polyhedron given by its vertices and faces
// (vertex loops counter-clockwise seen from outside; faces may be any planar
// polygons): a sum over the tetrahedra from a reference vertex to each
// face's fan triangles. Valid for non-convex polyhedra too.
struct PolyhedronMoments {
  double volume = 0;
  Vec3 centroid{0, 0, 0};
  Eigen::Matrix3d second_moment = Eigen::Matrix3d::Zero();  // integral of (x-c)(x-c)^T dV
};
PolyhedronMoments polyhedron_moments(const std::vector<Vec3>& vertices, const std::vector<std::vector<int>>& faces);

// The six half-spaces of a box, in the order -x, +x, -y, +y, -z, +z.
ConvexRegion box_region(const Box3& box);

}  // namespace dda
