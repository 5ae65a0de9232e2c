// Excavations: a block partly inside a convex region is cut by the region's
// planes one after another; what lies outside each plane is kept as a convex
// piece and the rest goes on to the next plane; what is left after the last
// plane is inside and removed. The kept pieces touch each other along the
// planes that separated them (kArtificialSet faces), where
// cut3d_bodies.cpp glues them back into one body. An excavation given as a
// closed surface goes to cut3d_surface.cpp, which does the same with the
// planes of its triangles.
#include "cut3d_internal.hpp"
#include "dda/common/geometry.hpp"

namespace dda::dc::detail3 {

void excavate(Work& w, const std::vector<Excavation3>& excavations) {
  std::vector<std::int8_t> sides;
  for (const Excavation3& e : excavations) {
    if (e.surface) {
      const SurfaceCut cut = cut_by_surface(w, *e.surface, false);
      w.surface_splits += cut.splits;
      w.excavated_volume += cut.removed_volume;
      w.excavated_pieces += cut.removed_pieces;
    }
    // No half-spaces would be all space: an excavation that is only a surface.
    if (e.region.half_spaces.empty()) continue;
    std::vector<int> planes;
    for (const HalfSpace& hs : e.region.half_spaces)
      planes.push_back(w.add_plane(hs.normal, hs.offset, PlaneRole::Excavation));
    std::vector<cell::Cell> out;
    out.reserve(w.cells.size());
    for (auto& c : w.cells) {
      bool outside = false;
      for (int h : planes) outside = outside || cell::bounds_side(c, w.table[h]) > 0;
      if (outside) {
        out.push_back(std::move(c));
        continue;
      }
      std::vector<cell::Cell> pieces;
      cell::Cell cur = c;
      bool inside = true;
      for (int h : planes) {
        int where = cell::bounds_side(cur, w.table[h]);
        if (where == 0) where = classify(w, cur, h, sides);
        if (where > 0) {
          inside = false;
          break;
        }
        if (where < 0) continue;
        cell::Cell below, above;
        split(w, cur, h, sides, kArtificialSet, below, above);
        above.faces.back().tag = kExcavationSet;  // the cap facing the opening
        pieces.push_back(std::move(above));
        cur = std::move(below);
      }
      if (!inside) {  // nothing of the block is in the opening: keep it whole
        out.push_back(std::move(c));
        continue;
      }
      w.excavated_volume += cell::moments(cur).volume;
      ++w.excavated_pieces;
      for (auto& p : pieces) {
        p.exposed = true;
        out.push_back(std::move(p));
      }
    }
    w.cells = std::move(out);
  }
}

}  // namespace dda::dc::detail3
