#include "dda/dc/cut3d.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

#include "cut3d_internal.hpp"
#include "dda/common/error.hpp"

namespace dda::dc {

using detail3::Work;

namespace detail3 {

int classify(const Work& w, const cell::Cell& c, int h, std::vector<std::int8_t>& sides) {
  return cell::classify(c, w.table, h, sides, w.snap);
}

void split(const Work& w, const cell::Cell& c, int h, std::vector<std::int8_t>& sides, int cap_tag,
           cell::Cell& below, cell::Cell& above) {
  try {
    cell::split(c, w.table, h, sides, cap_tag, below, above);
  } catch (const InternalError&) {
    if (w.snap <= 0) throw;
    if (cell::classify(c, w.table, h, sides, 0) != 0) throw;
    cell::split(c, w.table, h, sides, cap_tag, below, above);
  }
}

}  // namespace detail3

namespace {

void check_input(const FractureModel& m) {
  for (int i = 0; i < 3; ++i)
    if (!(std::isfinite(m.domain.lo[i]) && std::isfinite(m.domain.hi[i]) && m.domain.lo[i] < m.domain.hi[i]))
      throw InputError("fractures file: the domain box must have finite lo < hi on every axis");
  for (std::size_t i = 0; i < m.fractures.size(); ++i) {
    const Fracture3& f = m.fractures[i];
    std::ostringstream where;
    where << "fractures file: fracture " << i << " ";
    if (!f.normal.allFinite() || f.normal.norm() < 1e-12 || !f.centre.allFinite())
      throw InputError(where.str() + "has a zero or non-finite normal or centre");
    if (f.shape == FractureShape::Disc && !(f.radius > 0 && std::isfinite(f.radius)))
      throw InputError(where.str() + "is a disc without a positive finite radius");
    if (f.shape == FractureShape::Polygon && f.vertices.size() < 3)
      throw InputError(where.str() + "is a polygon with fewer than 3 vertices");
    if (f.set < 0 || f.set >= static_cast<int>(m.sets.size()))
      throw InputError(where.str() + "names a joint set that the file does not list");
  }
  for (const auto& e : m.excavations) {
    for (const auto& h : e.region.half_spaces)
      if (!h.normal.allFinite() || h.normal.norm() < 1e-12 || !std::isfinite(h.offset))
        throw InputError("fractures file: excavation '" + e.name + "' has a zero or non-finite half-space normal");
    if (e.surface) check_closed_surface(*e.surface, "fractures file: the surface of excavation '" + e.name + "'");
    else if (e.region.half_spaces.empty())
      throw InputError("fractures file: excavation '" + e.name + "' has neither half-spaces nor a surface");
  }
  if (m.domain_surface) {
    check_closed_surface(*m.domain_surface, "fractures file: the domain surface");
    // The cells start as the box; rock outside it would be lost unseen.
    const Box3 b = mesh_bounds(*m.domain_surface);
    const double tol = 1e-9 * (m.domain.hi - m.domain.lo).norm();
    if ((b.lo.array() < m.domain.lo.array() - tol).any() || (b.hi.array() > m.domain.hi.array() + tol).any())
      throw InputError("fractures file: the domain surface reaches outside the domain box (the box must hold it)");
  }
}

bool boxes_meet(const Box3& a, const Box3& b) {
  return (a.lo.array() <= b.hi.array()).all() && (b.lo.array() <= a.hi.array()).all();
}

// One fracture against every cell. Returns the number of cells it split;
// `partial` counts the cells it ends inside of, which it splits too when
// `split_partial` (the parts stay glued into one body) and leaves whole if not.
std::size_t cut_with(Work& w, std::size_t index, const Fracture3& f, bool split_partial, std::size_t& partial) {
  const FractureExtent& extent = w.extents[index];
  const int h = w.add_plane(f.normal, f.offset(), extent.bounded() ? detail3::PlaneRole::Finite : detail3::PlaneRole::Persistent,
                            static_cast<int>(index));
  std::vector<std::int8_t> sides;
  std::vector<cell::Cell> added;
  std::size_t splits = 0;
  for (auto& c : w.cells) {
    if (extent.bounded() && !boxes_meet(c.bounds, extent.bounds())) continue;
    if (cell::bounds_side(c, w.table[h]) != 0) continue;
    if (detail3::classify(w, c, h, sides) != 0) continue;
    if (extent.bounded()) {
      const Coverage cov = extent.coverage(cell::section_points(c, w.table, h, sides));
      if (cov == Coverage::None) continue;
      if (cov == Coverage::Partial) {
        ++partial;
        if (!split_partial) continue;
      }
    }
    cell::Cell below, above;
    detail3::split(w, c, h, sides, f.set, below, above);
    c = std::move(below);
    added.push_back(std::move(above));
    ++splits;
  }
  for (auto& c : added) w.cells.push_back(std::move(c));
  return splits;
}

}  // namespace

Cut3dResult cut_blocks_3d(const FractureModel& in, const Cut3dOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  check_input(in);
  Work w;
  w.snap = options.snap_tolerance > 0 ? options.snap_tolerance : 1e-9 * (in.domain.hi - in.domain.lo).norm();
  {
    const ConvexRegion box = box_region(in.domain);
    for (int i = 0; i < 6; ++i)
      w.boundary_planes[i] = w.add_plane(box.half_spaces[i].normal, box.half_spaces[i].offset, detail3::PlaneRole::Boundary);
    w.cells.push_back(cell::make_box(w.table, w.boundary_planes, kBoundarySet));
  }
  for (const Fracture3& f : in.fractures) w.extents.emplace_back(f);

  std::vector<std::size_t> persistent, finite;
  for (std::size_t i = 0; i < in.fractures.size(); ++i)
    (in.fractures[i].shape == FractureShape::Plane ? persistent : finite).push_back(i);

  std::size_t partial = 0;
  for (std::size_t i : persistent) w.splits += cut_with(w, i, in.fractures[i], false, partial);

  int passes = 0;
  std::size_t unfinished_cells = 0, unfinished_through = 0;
  const bool glue = options.finite_fractures == FiniteFractures::Glue;
  if (glue) {
    // Every fracture splits every block its disc or polygon reaches into;
    // where it ends inside, the parts stay glued (cut3d_bodies.cpp).
    passes = finite.empty() ? 0 : 1;
    for (std::size_t i : finite) w.splits += cut_with(w, i, in.fractures[i], true, unfinished_cells);
  } else {
    // Pass after pass over the fractures that still end inside some block,
    // until a pass cuts nothing.
    std::vector<std::size_t> pending = finite;
    while (!pending.empty()) {
      ++passes;
      std::vector<std::size_t> still;
      std::size_t cut_this_pass = 0;
      unfinished_cells = 0;
      for (std::size_t i : pending) {
        std::size_t part = 0;
        cut_this_pass += cut_with(w, i, in.fractures[i], false, part);
        if (part > 0) still.push_back(i);
        unfinished_cells += part;
      }
      w.splits += cut_this_pass;
      unfinished_through = still.size();
      if (cut_this_pass == 0 || still.empty()) break;
      pending = std::move(still);
    }
  }
  // The rock inside a domain surface; the rest of the box was never rock,
  // so it is not counted as excavated.
  detail3::SurfaceCut domain_cut;
  if (in.domain_surface) {
    domain_cut = detail3::cut_by_surface(w, *in.domain_surface, true);
    w.surface_splits += domain_cut.splits;
    w.domain_surface_planes = domain_cut.on_surface;
  }
  const std::size_t blocks_before_excavation = w.cells.size();

  detail3::excavate(w, in.excavations);

  Cut3dResult result;
  std::size_t removed_by_holes = 0, unfinished_fractures = 0;
  detail3::build_output(w, in, options, result.model, removed_by_holes, unfinished_fractures);
  if (!glue) unfinished_fractures = unfinished_through;  // they left blocks whole rather than glued
  result.model.unfinished_cuts = static_cast<int>(unfinished_fractures);

  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  auto& r = result.report;
  r["persistent_planes"] = persistent.size();
  r["finite_fractures"] = finite.size();
  r["splits"] = w.splits;
  r["snap_tolerance"] = w.snap;
  r["finite_fractures_mode"] = glue ? "glue" : "through";
  r["finite_passes"] = passes;
  r["unfinished_fractures"] = unfinished_fractures;
  r["partial_block_crossings"] = unfinished_cells;
  r["domain_surface_triangles"] = in.domain_surface ? in.domain_surface->triangles.size() : 0;
  r["outside_domain_surface_volume"] = domain_cut.removed_volume;
  r["surface_splits"] = w.surface_splits;
  r["blocks_before_excavation"] = blocks_before_excavation;
  r["excavated_volume"] = w.excavated_volume;
  r["removed_by_hole_points"] = removed_by_holes;
  r["blocks"] = result.model.blocks.size();
  r["bodies"] = result.model.bodies.size();
  r["seconds"] = seconds;
  return result;
}

}  // namespace dda::dc
