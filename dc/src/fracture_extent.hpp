#pragma once
// The bounded part of a fracture's plane (a disc or a convex polygon), and
// whether it reaches right through a block: the test that decides if a
// finite fracture cuts.
#include <vector>

#include "dda/common/fracture_model.hpp"
#include "dda/common/geometry.hpp"

namespace dda::dc {

enum class Coverage {
  None,     // the fracture misses the block's section
  Partial,  // it ends inside the block
  Full,     // the whole section lies on the fracture: it cuts the block
};

class FractureExtent {
 public:
  explicit FractureExtent(const Fracture3& f);
  bool bounded() const { return bounded_; }
  const Box3& bounds() const { return bounds_; }  // infinite for a plane
  // `section`: points of a block's section by the fracture plane (the cap
  // polygon's vertices, any order).
  Coverage coverage(const std::vector<Vec3>& section) const;

  // Coordinates in the fracture's plane (origin at its centre).
  Vec2 in_plane(const Vec3& p) const { return {(p - origin_).dot(e1_), (p - origin_).dot(e2_)}; }
  // Whether every point of `poly` (in-plane coordinates) lies on the
  // fracture, within a rounding tolerance; always true for a plane.
  bool covers(const Polygon2& poly) const;

 private:
  bool bounded_ = false;
  bool disc_ = false;
  Vec3 origin_, e1_, e2_;
  double radius_ = 0;
  Polygon2 polygon_;  // counter-clockwise in (e1, e2)
  Box3 bounds_;
  double tol_ = 0;    // absolute, for "on the fracture's rim"
};

}  // namespace dda::dc
