#pragma once
// The fractures file: what DL writes in 3D and DC reads to cut polyhedra.
//
// A FractureModel is the whole 3D geometry before cutting: the domain box
// (or a closed surface inside it), the excavations (convex regions or closed
// surfaces), every fracture with the set it belongs to, the beds of a
// layered rock mass and the named points.
#include <optional>
#include <string>
#include <vector>

#include "dda/common/geometry3d.hpp"
#include "dda/common/line_model.hpp"  // JointSetInfo, LineKind, Layer, PointKind, set ids
#include "dda/common/provenance.hpp"
#include "dda/common/triangle_mesh.hpp"

namespace dda {

enum class FractureShape : int {
  Plane = 0,    // unbounded: cuts through the whole domain (persistent, bedding)
  Disc = 1,     // a disc of `radius` about `centre`
  Polygon = 2,  // a convex polygon `vertices`
};
const char* to_string(FractureShape s);
// "plane", "disc" or "polygon"; anything else is an InputError naming the
// word, prefixed by `where` (a file and key, say) when that is not empty.
FractureShape fracture_shape_from_string(const std::string& word, const std::string& where = "");

// A planar fracture: the plane normal . x = normal . centre, bounded by a
// disc, a convex polygon or nothing.
struct Fracture3 {
  FractureShape shape = FractureShape::Disc;
  Vec3 normal{0, 0, 1};         // unit, upper hemisphere
  Vec3 centre{0, 0, 0};         // on the plane: disc centre, polygon centroid, or any point
  double radius = 0;            // Disc only
  std::vector<Vec3> vertices;   // Polygon only: convex, in the plane, counter-clockwise about normal
  int set = 0;                  // index into FractureModel::sets
  LineKind kind = LineKind::Joint;
  int layer = -1;               // bed the fracture was generated in, -1 if none
  double offset() const { return normal.dot(centre); }
};

struct ModelPoint3 {
  std::string name;
  PointKind kind = PointKind::Measurement;
  Vec3 p{0, 0, 0};
};

// The opened volume is what lies inside the region (if it has half-spaces)
// or inside the surface (if there is one): their union.
struct Excavation3 {
  std::string name;
  ConvexRegion region;
  std::optional<TriangleMesh> surface{};  // closed, triangles facing out of the opening
};

struct FractureModel {
  Box3 domain;
  // The rock is what lies inside this closed surface (triangles facing out
  // of the rock), when given; `domain` then holds it (its bounding box).
  std::optional<TriangleMesh> domain_surface{};
  std::vector<Excavation3> excavations;
  std::vector<Fracture3> fractures;
  std::vector<JointSetInfo> sets;   // index = Fracture3::set
  std::vector<ModelPoint3> points;
  // Beds of a layered rock mass, bottom to top, as coordinates along the bed
  // normal (bed_normal . x); empty if not layered.
  std::vector<Layer> layers;
  Vec3 bed_normal{0, 0, 1};
  // Every position above is about this local origin: the user's coordinates
  // are position + origin (local_origin.hpp); zero unless the model lies far
  // from the origin for its size.
  Vec3 origin{0, 0, 0};
  Provenance provenance;
};

}  // namespace dda
