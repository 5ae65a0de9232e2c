#pragma once
// Closed triangulated surfaces: a domain shaped to the ground (a slope face,
// benches) or an opening of any shape (a tunnel), read from STL or OBJ.
//
// The surface must be closed (every edge shared by exactly two triangles
// that run it in opposite directions), so that "inside" means something:
// the generalised winding number is then 1 inside and 0 outside, exactly up
// to rounding, whatever the shape (non-convex, several shells).
#include <array>
#include <string>
#include <vector>

#include "dda/common/geometry3d.hpp"

namespace dda {

struct TriangleMesh {
  std::vector<Vec3> vertices;
  // Vertex ids, counter-clockwise seen from outside once orient_outward ran.
  std::vector<std::array<int, 3>> triangles;
};

// Reads a surface by the file's extension (.stl, ASCII or binary; .obj),
// checks that it is closed and turns it outward. Every problem is one
// InputError naming the file (and the line, for the text formats).
TriangleMesh read_triangle_mesh(const std::string& path);

// The raw readers (no closedness check, no orientation). STL has no shared
// vertices: corners with bit-identical coordinates become one vertex. OBJ
// reads `v` and `f` lines (`f 1 2 3`, `f 1/2/3`, `f 1//3`, negative ids
// relative to the end); faces with more than three corners are fanned from
// their first corner; every other statement is ignored.
TriangleMesh read_stl(const std::string& path);
TriangleMesh read_obj(const std::string& path);

// An InputError "<what>: ..." unless the mesh has finite vertices, valid
// ids, no triangle with a repeated corner, every edge in exactly two
// triangles with opposite directions, and a non-zero enclosed volume.
void check_closed_surface(const TriangleMesh& mesh, const std::string& what);

// Signed volume enclosed (positive when the triangles face outward).
double enclosed_volume(const TriangleMesh& mesh);

// Flips every triangle if the enclosed volume is negative (triangles that
// faced inward), so that normals point out of the enclosed volume.
void orient_outward(TriangleMesh& mesh);

Box3 mesh_bounds(const TriangleMesh& mesh);

// Sum of the signed solid angles of the triangles seen from p, over 4 pi:
// 1 inside a closed outward surface, 0 outside (undefined on it).
double winding_number(const TriangleMesh& mesh, const Vec3& p);
inline bool mesh_contains(const TriangleMesh& mesh, const Vec3& p) { return winding_number(mesh, p) > 0.5; }

// mesh_contains for many points against one closed surface facing outward,
// in time that grows with the triangles above the point rather than all of
// them: the ray up from the point counts +1 for each triangle it leaves
// through and -1 for each it enters through (triangles found by their shadow
// on a grid); where the ray grazes an edge or the point is on the surface,
// the winding number decides. Keeps a reference to the mesh.
class MeshInsideTest {
 public:
  explicit MeshInsideTest(const TriangleMesh& mesh);
  bool contains(const Vec3& p) const;

 private:
  const TriangleMesh& mesh_;
  Box3 box_;
  double scale_ = 0, cell_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<int> offsets_, ids_;  // triangles whose shadow meets grid cell k: ids_[offsets_[k]:offsets_[k+1]]
};

}  // namespace dda
