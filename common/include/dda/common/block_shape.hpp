#pragma once
// A block made from its outline, with the integrals every stage reads
// (area, centroid, second moments) filled in: what tests, benchmarks and
// fuzz targets build by hand, where the cutter (DC) would make it.
#include "dda/common/block_model.hpp"
#include "dda/common/geometry.hpp"

namespace dda {

// Every edge carries joint set `set`; the outline is taken as given
// (counter-clockwise, simple).
inline Block make_block(const Polygon2& vertices, int set = 0) {
  Block b;
  b.vertices = vertices;
  b.edge_set.assign(vertices.size(), set);
  const PolygonMoments m = polygon_moments(vertices);
  b.area = m.area;
  b.centroid = m.centroid;
  b.sxx = m.sxx;
  b.syy = m.syy;
  b.sxy = m.sxy;
  return b;
}

}  // namespace dda
