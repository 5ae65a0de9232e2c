#pragma once
// The 3D blocks file: what DC writes in 3D (and DF will read).
//
// A block is a convex polyhedron. A rock body that is not convex (a block
// wrapped round a tunnel, a block cut by a fracture that stops inside it is
// not split at all) is stored as several convex parts glued along faces
// marked kArtificialSet, all carrying the same `body` index.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "dda/common/fracture_model.hpp"  // ModelPoint3
#include "dda/common/geometry3d.hpp"
#include "dda/common/line_model.hpp"
#include "dda/common/provenance.hpp"

namespace dda {

struct PolyFace {
  std::vector<int> vertices;    // indices into Polyhedron::vertices, counter-clockwise seen from outside
  Vec3 normal{0, 0, 1};         // unit, outward
  int set = kBoundarySet;       // joint set (>= 0), kBoundarySet, kExcavationSet or kArtificialSet
};

struct Polyhedron {
  std::vector<Vec3> vertices;
  std::vector<PolyFace> faces;
  double volume = 0;            // m^3
  Vec3 centroid{0, 0, 0};       // m
  Eigen::Matrix3d second_moment = Eigen::Matrix3d::Zero();  // integral of (x-c)(x-c)^T dV, m^5
  int body = 0;                 // index into PolyhedronModel::bodies
  int layer = -1;               // bed containing the centroid, -1 if not layered
};

// How a body can leave the rock mass into the excavation (block theory,
// Goodman & Shi 1985), judged from the normals of the faces it shares with
// other rock: a body is removable if some translation opens or slides on
// every one of those faces; gravity then picks the mode.
enum class Removability : int {
  NotExposed = 0,    // no face on the excavation or free surface
  Tapered = 1,       // exposed but locked in by its neighbours
  Removable = 2,     // free to move, but gravity alone holds it (it would have to lift up)
  Falls = 3,         // removable, gravity lifts it off every face
  SlidesOne = 4,     // removable, slides on one face under gravity
  SlidesTwo = 5,     // removable, slides along the line of two faces under gravity
};
const char* to_string(Removability r);
// The inverse of to_string ("not_exposed", "tapered", "removable", "falls",
// "slides_one_face", "slides_two_faces"); anything else is an InputError
// naming the word, prefixed by `where` when that is not empty.
Removability removability_from_string(const std::string& word, const std::string& where = "");

struct Body3 {
  std::vector<int> parts;       // indices into PolyhedronModel::blocks
  double volume = 0;
  Removability removability = Removability::NotExposed;
  Vec3 sliding_direction{0, 0, 0};  // unit, for Falls / SlidesOne / SlidesTwo
};

struct PolyhedronModel {
  std::vector<Polyhedron> blocks;
  std::vector<Body3> bodies;
  std::vector<JointSetInfo> sets;   // carried over from the fractures file
  std::vector<ModelPoint3> points;
  std::vector<Layer> layers;
  Vec3 bed_normal{0, 0, 1};
  Box3 domain;
  double domain_volume = 0;
  double excavated_volume = 0;
  int unfinished_cuts = 0;          // finite fractures that ended inside a block (left it whole)
  Vec3 origin{0, 0, 0};             // local origin: user coordinates = position + origin (local_origin.hpp)
  Provenance provenance;
};

}  // namespace dda
