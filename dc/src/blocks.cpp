// Block faces (vertex indices into rounded points) -> Blocks.
//
// Conventions:
//  * A vertex is removed when its two edges lie on one common input segment
//    and have the same set (decided exactly in the arrangement, not on the
//    rounded points). This also removes T-junction vertices where only a
//    neighbour has a corner: DDA contacts are vertex-to-edge, so the
//    neighbour's corner still meets this block's edge. Where two collinear
//    edges have different sets the vertex stays, so each edge keeps its set.
//  * Rounded vertices that coincide are merged (the zero-length edge goes).
//  * Each polygon starts at its lowest vertex (then leftmost) and runs CCW.
//  * A block that is not a simple polygon with positive area after rounding
//    is not emitted; it is listed as degenerate in the report.
//  * Blocks are ordered by centroid: y, then x.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "cut_internal.hpp"

namespace dda::dc::detail {

int layer_of(const Vec2& p, const std::vector<Layer>& layers, double dip_deg) {
  if (layers.empty()) return -1;
  const double d = deg2rad(dip_deg);
  const double s = dip_deg == 0 ? p.y() : -std::sin(d) * p.x() + std::cos(d) * p.y();
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const bool last = i + 1 == layers.size();
    if (s >= layers[i].bottom && (s < layers[i].top || (last && s <= layers[i].top)))
      return static_cast<int>(i);
  }
  return -1;
}

namespace {

struct Built {
  Block block;
  bool ok = false;
  std::string reason;
  long long collinear = 0, duplicates = 0;
};

Built build_one(const RawFace& f, const std::vector<Vec2>& pts, const std::vector<Layer>& layers,
                double dip_deg) {
  Built out;
  if (f.has_holes) out.reason = "the face still has a hole";
  if (f.repeated_vertex) out.reason = "the face boundary touches itself at a vertex";
  const std::size_t n = f.vertex.size();
  // 1. drop straight vertices
  std::vector<std::size_t> keep;
  for (std::size_t i = 0; i < n; ++i)
    if (!f.straight[i]) keep.push_back(i);
  out.collinear = static_cast<long long>(n - keep.size());
  Polygon2 poly;
  std::vector<int> sets;
  for (std::size_t i : keep) {
    const Vec2& p = pts[static_cast<std::size_t>(f.vertex[i])];
    if (!poly.empty() && p == poly.back()) {
      sets.back() = f.edge_set[i];  // the zero-length edge was the previous one
      ++out.duplicates;
      continue;
    }
    poly.push_back(p);
    sets.push_back(f.edge_set[i]);
  }
  while (poly.size() > 1 && poly.back() == poly.front()) {
    poly.pop_back();
    sets.pop_back();
    ++out.duplicates;
  }
  // 2. start at the lowest, then leftmost vertex
  if (!poly.empty()) {
    std::size_t s = 0;
    for (std::size_t i = 1; i < poly.size(); ++i)
      if (poly[i].y() < poly[s].y() || (poly[i].y() == poly[s].y() && poly[i].x() < poly[s].x()))
        s = i;
    std::rotate(poly.begin(), poly.begin() + static_cast<std::ptrdiff_t>(s), poly.end());
    std::rotate(sets.begin(), sets.begin() + static_cast<std::ptrdiff_t>(s), sets.end());
  }
  const PolygonMoments m = polygon_moments(poly);
  Block& b = out.block;
  b.vertices = std::move(poly);
  b.edge_set = std::move(sets);
  b.area = m.area;
  b.centroid = m.centroid;
  b.sxx = m.sxx;
  b.syy = m.syy;
  b.sxy = m.sxy;
  if (out.reason.empty()) {
    if (b.vertices.size() < 3)
      out.reason = "fewer than 3 distinct vertices after rounding";
    else if (!(m.area > 0))
      out.reason = "area not positive after rounding";
    else if (!is_simple_polygon(b.vertices))
      out.reason = "not a simple polygon after rounding";
  }
  out.ok = out.reason.empty();
  b.layer = layer_of(b.centroid, layers, dip_deg);
  return out;
}

}  // namespace

BlockBuild build_blocks(const ArrangementResult& ar, const std::vector<Layer>& layers, double dip_deg) {
  const std::size_t nf = ar.faces.size();
  std::vector<Built> built(nf);
#pragma omp parallel for schedule(dynamic, 256)
  for (long long i = 0; i < static_cast<long long>(nf); ++i)
    built[static_cast<std::size_t>(i)] =
        build_one(ar.faces[static_cast<std::size_t>(i)], ar.points, layers, dip_deg);

  BlockBuild out;
  std::vector<std::size_t> good;
  for (std::size_t i = 0; i < nf; ++i) {
    out.collinear_vertices_removed += built[i].collinear;
    out.duplicate_vertices_removed += built[i].duplicates;
    if (built[i].ok) {
      good.push_back(i);
    } else {
      DegenerateBlock d;
      const RawFace& f = ar.faces[i];
      d.near = f.vertex.empty() ? Vec2(0, 0) : ar.points[static_cast<std::size_t>(f.vertex[0])];
      d.vertices = built[i].block.vertices.size();
      d.area = built[i].block.area;
      d.reason = built[i].reason;
      out.degenerate.push_back(d);
    }
  }
  std::stable_sort(good.begin(), good.end(), [&](std::size_t a, std::size_t b) {
    const Vec2& ca = built[a].block.centroid;
    const Vec2& cb = built[b].block.centroid;
    return ca.y() < cb.y() || (ca.y() == cb.y() && ca.x() < cb.x());
  });
  out.face_block.assign(nf, -1);
  out.blocks.reserve(good.size());
  for (std::size_t k = 0; k < good.size(); ++k) {
    out.face_block[good[k]] = static_cast<int>(k);
    out.blocks.push_back(std::move(built[good[k]].block));
  }
  return out;
}

}  // namespace dda::dc::detail
