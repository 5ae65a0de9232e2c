#pragma once
// Stages of the 3D cutter (plain interfaces; only exact_plane_cgal.cpp sees CGAL).
//
//   cut3d.cpp            orchestration, input checks, persistent and finite fractures
//   cut3d_excavate.cpp   excavations, glued pieces -> bodies, hole points
//   cut3d_output.cpp     cells -> Polyhedra, bodies, removability, report
//   convex_cell.cpp      the plane-based convex cell and its split
//   fracture_extent.cpp  does a finite fracture reach through a block
#include <cstddef>
#include <string>
#include <vector>

#include "convex_cell.hpp"
#include "dda/common/fracture_model.hpp"
#include "dda/common/polyhedron_model.hpp"
#include "dda/dc/cut3d.hpp"

namespace dda::dc::detail3 {

struct Work {
  cell::PlaneTable table;
  std::vector<cell::Cell> cells;
  int boundary_planes[6] = {0, 1, 2, 3, 4, 5};  // -x +x -y +y -z +z
  double snap = 0;  // m: vertices this close to a cutting plane count as on it
  std::size_t splits = 0;
  double excavated_volume = 0;
  std::size_t excavated_pieces = 0;
};

// Where cell c lies relative to plane h (cell::classify with the job's snap).
int classify(const Work& w, const cell::Cell& c, int h, std::vector<std::int8_t>& sides);
// cell::split, falling back to the exact sides if the snapped ones do not
// close the section (`sides` is then recomputed).
void split(const Work& w, const cell::Cell& c, int h, std::vector<std::int8_t>& sides, int cap_tag,
           cell::Cell& below, cell::Cell& above);

// Removes what lies inside each excavation; pieces of a block partly inside
// get a common `origin` and kArtificialSet faces where they stay glued.
void excavate(Work& w, const std::vector<Excavation3>& excavations);

// Union of glued pieces (same origin, overlapping opposite faces on one
// plane): the body index of every cell, bodies numbered from 0.
std::vector<int> glue_bodies(const Work& w, int& body_count);

// Builds the output blocks and bodies (moments, layers, removability) and
// removes the bodies that contain hole points.
void build_output(Work& w, const FractureModel& in, const Cut3dOptions& options, PolyhedronModel& out,
                  std::size_t& removed_by_holes);

// 0..5 for "x-", "x+", "y-", "y+", "z-", "z+"; -1 for anything else.
int boundary_index(const std::string& name);

}  // namespace dda::dc::detail3
