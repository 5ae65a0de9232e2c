#pragma once
// A convex polyhedron in plane-based form, and its split by a plane: the
// working object of the 3D cutter.
//
// Every vertex remembers the three planes that define it and every face the
// plane it lies in, so all decisions go through exact::side (see
// exact_plane.hpp); the double coordinates are for bounds and output only.
// Faces are vertex loops counter-clockwise seen from outside.
#include <array>
#include <cstdint>
#include <vector>

#include "dda/common/geometry3d.hpp"
#include "exact_plane.hpp"

namespace dda::dc::cell {

// Every plane a job uses, by index; planes are only ever appended.
class PlaneTable {
 public:
  // The plane normal . x = offset.
  int add(const Vec3& normal, double offset) {
    planes_.push_back({normal, -offset});
    return static_cast<int>(planes_.size()) - 1;
  }
  const exact::Plane& operator[](int i) const { return planes_[static_cast<std::size_t>(i)]; }
  std::size_t size() const { return planes_.size(); }

 private:
  std::vector<exact::Plane> planes_;
};

struct Vertex {
  std::array<int, 3> planes{};  // meeting planes, with orientation != 0
  std::int8_t orient = 1;       // exact::orientation of the three
  Vec3 x{0, 0, 0};              // doubles, for bounds and output
};

struct Face {
  int plane = 0;
  std::int8_t sense = 1;        // outward normal = sense * plane normal
  int tag = 0;                  // joint set or a reserved set id (line_model.hpp)
  std::vector<int> loop;        // vertex indices, counter-clockwise from outside
};

struct Cell {
  std::vector<Vertex> vertices;
  std::vector<Face> faces;
  Box3 bounds;                  // of the double coordinates
  bool exposed = false;         // has lost a part to an excavation
  void update_bounds();
};

// The box as a cell, from the ids of its six planes in the order of
// box_region (-x, +x, -y, +y, -z, +z; normals outward), every face tagged `tag`.
Cell make_box(const PlaneTable& table, const int plane[6], int tag);

// Where a cell lies relative to plane h: -1 if no vertex is above it (the
// cell is on the negative side, possibly touching), +1 if none is below, 0 if
// the plane passes through the interior. `sides` receives each vertex's side.
//
// With snap > 0, a vertex closer to the plane than `snap` (m) counts as on
// it: planes meant to meet in one point or line (input rounded to doubles)
// then do, instead of leaving blocks 1e-16 m wide. If the snapped sides
// could not come from a convex cell (the check is per face), the exact
// sides are used instead, so the result is always a valid polyhedron.
int classify(const Cell& c, const PlaneTable& table, int h, std::vector<std::int8_t>& sides, double snap = 0);

// Volume, centroid and second moment of the cell (from its double coordinates).
PolyhedronMoments moments(const Cell& c);

// Quick conservative bound test in doubles: -1 / +1 if the cell's bounding
// box is clearly on one side of plane h (well beyond rounding), else 0 (use
// classify to know).
int bounds_side(const Cell& c, const exact::Plane& h);

// Splits a cell that classify found straddling h (result 0) into the part
// below h (`below`, outward cap normal +n_h) and the part above (`above`,
// cap normal -n_h). Both caps get `cap_tag`. `section`, if given, receives
// the cap polygon (counter-clockwise about +n_h).
void split(const Cell& c, const PlaneTable& table, int h, const std::vector<std::int8_t>& sides, int cap_tag,
           Cell& below, Cell& above, std::vector<Vec3>* section = nullptr);

// The cap polygon a split would make, without splitting: the points where h
// crosses the cell's edges and the vertices on h, in no particular order.
std::vector<Vec3> section_points(const Cell& c, const PlaneTable& table, int h,
                                 const std::vector<std::int8_t>& sides);

}  // namespace dda::dc::cell
