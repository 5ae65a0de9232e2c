#pragma once
// The blocks file: what DC writes and DF reads.
#include <string>
#include <vector>

#include "dda/common/geometry.hpp"
#include "dda/common/line_model.hpp"
#include "dda/common/provenance.hpp"

namespace dda {

struct Block {
  Polygon2 vertices;            // counter-clockwise, no repeated closing vertex
  std::vector<int> edge_set;    // edge i runs vertices[i] -> vertices[i+1]; its joint set
                                // (>= 0) or kBoundarySet / kExcavationSet / kArtificialSet
  double area = 0;              // m^2
  Vec2 centroid{0, 0};          // m
  double sxx = 0, syy = 0, sxy = 0;  // second moments about the centroid, m^4
  int layer = -1;               // bed containing the centroid, -1 if not layered
};

struct LocatedPoint {
  ModelPoint point;
  int block = -1;               // index of the block containing the point
};

struct BlockModel {
  std::vector<Block> blocks;
  std::vector<JointSetInfo> sets;       // carried over from the lines file
  std::vector<LocatedPoint> points;     // fixed, load and measurement points (hole points consumed)
  std::vector<Layer> layers;            // carried over from the lines file
  double bedding_dip_deg = 0;
  double domain_area = 0;               // area of the domain polygon, m^2
  double excavated_area = 0;            // area removed by excavations and hole points, m^2
  Vec2 origin{0, 0};                    // local origin: user coordinates = position + origin (local_origin.hpp)
  Provenance provenance;
};

}  // namespace dda
