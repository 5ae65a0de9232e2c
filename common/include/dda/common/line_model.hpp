#pragma once
// The lines file: what DL writes and DC reads.
//
// A LineModel is the whole 2D geometry before cutting: the domain boundary,
// the excavations, every joint trace with the set it belongs to, the beds of
// a layered rock mass, and the named points (fixed, load, measurement, hole).
#include <string>
#include <vector>

#include "dda/common/geometry.hpp"
#include "dda/common/provenance.hpp"

namespace dda {

// Reserved joint-set ids for edges that do not come from a joint set. Joint
// sets defined by the user are numbered 0, 1, 2, ... (index into set_names).
constexpr int kBoundarySet = -1;    // the domain boundary
constexpr int kExcavationSet = -2;  // the outline of an excavation
constexpr int kArtificialSet = -3;  // a cut DC adds to make a block simply connected

enum class LineKind : int {
  Joint = 0,    // a statistical, layered, imported or user joint
  Bedding = 1,  // a bed boundary of a layered rock mass
};

struct JointLine {
  Vec2 a{0, 0};
  Vec2 b{0, 0};
  int set = 0;               // index into LineModel::set_names
  LineKind kind = LineKind::Joint;
  int layer = -1;            // bed the joint was generated in, -1 if none
};

enum class PointKind : int { Fixed = 0, Load = 1, Measurement = 2, Hole = 3 };
const char* to_string(PointKind k);

struct ModelPoint {
  std::string name;
  PointKind kind = PointKind::Measurement;
  Vec2 p{0, 0};
};

// A bed of a layered rock mass, between two bed boundaries. For horizontal
// beds `bottom` and `top` are elevations (y); for dipping beds they are
// coordinates along the bed normal (see LineModel::bedding_dip_deg).
struct Layer {
  double bottom = 0;
  double top = 0;
  double target_fsi = 0;     // fracture spacing index asked for (0 if none)
  double realised_fsi = 0;   // thickness / median spacing of what was generated
  double thickness() const { return top - bottom; }
};

struct JointSetInfo {
  std::string name;
  std::string origin;  // "statistical", "layered", "user", "csv", "geo", "bedding"
};

struct LineModel {
  Polygon2 domain;                    // counter-clockwise, closed implicitly
  std::vector<Polygon2> excavations;  // counter-clockwise outlines of openings
  std::vector<JointLine> lines;       // joints and bedding, clipped to the domain
  std::vector<JointSetInfo> sets;     // index = JointLine::set
  std::vector<ModelPoint> points;
  std::vector<Layer> layers;          // bottom to top; empty if not layered
  double bedding_dip_deg = 0;         // dip of the beds (0 = horizontal)
  // Every position above is about this local origin: the user's coordinates
  // are position + origin (local_origin.hpp). (0, 0) unless the model lies
  // far from the origin for its size.
  Vec2 origin{0, 0};
  Provenance provenance;
};

}  // namespace dda
