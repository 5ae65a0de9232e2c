#pragma once
// Stages of the 3D cutter (plain interfaces; only exact_plane_cgal.cpp sees CGAL).
//
//   cut3d.cpp            orchestration, input checks, persistent and finite fractures
//   cut3d_excavate.cpp   excavations
//   cut3d_surface.cpp    closed triangulated surfaces: the domain's or an excavation's
//   cut3d_bodies.cpp     glued parts -> bodies
//   cut3d_output.cpp     cells -> Polyhedra, bodies, removability, report
//   convex_cell.cpp      the plane-based convex cell and its split
//   fracture_extent.cpp  does a finite fracture reach through a block
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "convex_cell.hpp"
#include "fracture_extent.hpp"
#include "dda/common/fracture_model.hpp"
#include "dda/common/polyhedron_model.hpp"
#include "dda/dc/cut3d.hpp"

namespace dda::dc::detail3 {

// What a plane of the table is, for deciding which faces glue parts together.
enum class PlaneRole : std::uint8_t { Boundary, Persistent, Finite, Excavation };

struct Work {
  cell::PlaneTable table;
  std::vector<PlaneRole> role;           // per plane
  std::vector<int> plane_fracture;       // per plane: input fracture index, or -1
  std::vector<FractureExtent> extents;   // per input fracture
  int add_plane(const Vec3& normal, double offset, PlaneRole r, int fracture = -1) {
    role.push_back(r);
    plane_fracture.push_back(fracture);
    return table.add(normal, offset);
  }
  std::vector<cell::Cell> cells;
  int boundary_planes[6] = {0, 1, 2, 3, 4, 5};  // -x +x -y +y -z +z
  double snap = 0;  // m: vertices this close to a cutting plane count as on it
  std::size_t splits = 0;
  std::size_t surface_splits = 0;  // by the planes of closed surfaces
  double excavated_volume = 0;
  std::size_t excavated_pieces = 0;
  // Per plane (as far as it reaches): on the domain's surface, its own or
  // one that coincides with it. Faces there are free surfaces (cut3d_output.cpp).
  std::vector<bool> domain_surface_planes;
};

// Where cell c lies relative to plane h (cell::classify with the job's snap).
int classify(const Work& w, const cell::Cell& c, int h, std::vector<std::int8_t>& sides);
// cell::split, falling back to the exact sides if the snapped ones do not
// close the section (`sides` is then recomputed).
void split(const Work& w, const cell::Cell& c, int h, std::vector<std::int8_t>& sides, int cap_tag,
           cell::Cell& below, cell::Cell& above);

// Removes what lies inside each excavation; a block partly inside leaves
// its outside parts, flagged exposed, with kArtificialSet faces where they
// touch each other.
void excavate(Work& w, const std::vector<Excavation3>& excavations);

// What cutting by a closed surface did.
struct SurfaceCut {
  // Per plane of the table: the surface's own planes, and earlier planes
  // (fractures, the box) that coincide with one of them.
  std::vector<bool> on_surface;
  std::size_t splits = 0;
  std::size_t removed_pieces = 0;
  double removed_volume = 0;
};

// Cuts every cell the surface passes through by the planes of the triangles
// that meet it (PlaneRole::Excavation: the parts glue back into bodies),
// until each piece lies wholly inside or outside, then keeps the pieces
// inside (`keep_inside`: a domain surface) or outside (an excavation). The
// kept faces on the surface get kBoundarySet or kExcavationSet (also where a
// fracture or the box lies on the surface); the other cuts are
// kArtificialSet. Cells that lose part to an excavation are flagged exposed.
SurfaceCut cut_by_surface(Work& w, const TriangleMesh& surface, bool keep_inside);

// Bodies: parts are glued where opposite faces on one plane overlap and the
// plane is an excavation's (artificial) or a finite fracture that does not
// cover the whole overlap. Returns the body of every cell (numbered from 0);
// `glued_fractures` counts the finite fractures that glue somewhere (they
// end inside a body). `contact[c][f]` is 1 for a face of cell c on a finite
// fracture that meets another body across it (faces on finite fractures
// inside one body do not hold it).
std::vector<int> glue_bodies(const Work& w, int& body_count, std::size_t& glued_fractures,
                             std::vector<std::vector<std::uint8_t>>& contact);

// Builds the output blocks and bodies (moments, layers, removability) and
// removes the bodies that contain hole points.
// `unfinished_fractures`: finite fractures that end inside a body.
void build_output(Work& w, const FractureModel& in, const Cut3dOptions& options, PolyhedronModel& out,
                  std::size_t& removed_by_holes, std::size_t& unfinished_fractures);

// 0..5 for "x-", "x+", "y-", "y+", "z-", "z+"; -1 for anything else.
int boundary_index(const std::string& name);

}  // namespace dda::dc::detail3
