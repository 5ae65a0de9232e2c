#pragma once
// 3D fractures as the fractures file stores them (dda::Fracture3): disc and
// polygon sets from the DFN generator, deterministic planes, persistent sets,
// polygons given by their vertices, and the area of any of them in a box.
//
// Conventions as in dfn3d.hpp: x east, y north, z up; dip and dip direction
// in degrees; stored normals are the upper-hemisphere ones; polygon vertices
// are counter-clockwise about the normal.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dda/common/fracture_model.hpp"
#include "dda/dl/dfn3d.hpp"
#include "dda/dl/polygon3d.hpp"
#include "dda/dl/random.hpp"

namespace dda::dl {

// ---- discs and polygon sets (fractures3d_sets.cpp) ----------------------

// The disc as a Fracture3 of shape Disc (same centre, normal, radius, set).
Fracture3 to_fracture(const Disc& disc);

// The regular n-gon (n >= 3) with the disc's centre, normal and set and the
// disc's area pi r^2: circumradius R = r sqrt(2 pi / (n sin(2 pi / n))). Its
// first vertex is at angle `rotation_rad` from plane_basis(normal).first,
// towards .second; vertices counter-clockwise about the normal.
Fracture3 regular_polygon(const Disc& disc, int sides, double rotation_rad);

// One set as fractures: discs, or regular polygons (spec.polygon_sides >= 3)
// turned by the angle generate_disc_set draws for each, in the same order.
std::vector<Fracture3> generate_fracture_set(const DiscSetSpec& spec, int set, const Box3& domain, double margin,
                                             Stream& rng);
// All sets; set i draws from Stream(seed, "dfn3d.set", i), like generate_dfn
// (so a disc set gives the very discs of generate_dfn), and its fractures
// carry set index first_set + i.
std::vector<Fracture3> generate_fractures(const std::vector<DiscSetSpec>& sets, const Box3& domain, double margin,
                                          std::uint64_t seed, int first_set = 0);

// ---- deterministic planes and persistent sets (fractures3d_planes.cpp) --

struct PlaneSpec {
  double dip_deg = 0;
  double dip_direction_deg = 0;
  Vec3 point{0, 0, 0};           // a point of the plane
  std::optional<double> radius;  // extent: a disc of this radius about `point`; none: unbounded
};

// A Plane fracture through `point` (centre = point), or a Disc if a radius is
// given; InputError for a bad dip or a radius that is not a finite number > 0.
Fracture3 make_plane(const PlaneSpec& spec, int set);

struct PersistentSetSpec {
  std::string name;
  double dip_deg = 0;
  double dip_direction_deg = 0;
  double spacing = 1;             // m > 0, normal distance between consecutive planes
  std::optional<Vec3> point;      // one plane passes through it; default the domain's lo corner
  double randomness = 0;          // [0, 1): each spacing is spacing * (1 + r X), X uniform on [-1, 1)
};

// Most planes one persistent set may have (more could not be cut into blocks).
inline constexpr double kMaxPersistentPlanes = 1e6;
// Farthest a persistent set's point may lie from the domain, in spacings:
// its planes are placed to about 1e9 x 2.2e-16 = 2e-7 of a spacing.
inline constexpr double kMaxSpacingsToPoint = 1e9;
// How many spacings the set's point (default the domain's lo corner) lies
// outside the domain along the set's normal: 0 inside. For a spec whose
// dip and spacing generate_persistent_set accepts.
double spacings_to_point(const PersistentSetSpec& spec, const Box3& domain);

// Every plane of the set that crosses the domain, as Plane fractures ordered
// by offset, each `centre` the centroid of the plane's section of the domain
// (so inside it). Without randomness the planes are exactly
// point + k spacing normal, k integer. With randomness the planes are walked
// from the point upwards (along the normal) and then downwards, one draw
// per spacing, so the set is one fixed realisation per stream. Planes that
// only touch the domain (at a face, an edge or a corner, within 1e-9 times
// its diagonal) are left out: they would cut no rock.
std::vector<Fracture3> generate_persistent_set(const PersistentSetSpec& spec, int set, const Box3& domain,
                                               Stream& rng);
// All sets; set i draws from Stream(seed, "persistent3d.set", i) and its
// planes carry set index first_set + i.
std::vector<Fracture3> generate_persistent_sets(const std::vector<PersistentSetSpec>& sets, const Box3& domain,
                                                std::uint64_t seed, int first_set = 0);

// ---- polygons from vertices (fractures3d_polygon.cpp) -------------------

// Relative tolerances of polygon_fracture: out-of-plane distance and the
// inward turn at a vertex, relative to the polygon's size (its largest
// vertex distance from the centroid). Loose enough for coordinates written
// with six significant digits, tight enough to refuse a warped quadrilateral.
inline constexpr double kPolygonPlanarityTolerance = 1e-4;

// A Polygon fracture from its vertices (either orientation; a last vertex
// repeating the first is dropped): the normal fitted by Newell's method and
// turned to the upper hemisphere (the vertices reversed if need be, so they
// are counter-clockwise about it), the vertices projected onto the fitted
// plane, the centre their area centroid. InputError "<where> <what is
// wrong>." for fewer than three vertices, a non-finite coordinate, two
// consecutive vertices at the same point, no area (collinear vertices), a
// vertex off the plane by more than `planarity` times the size, or a polygon
// that is not convex (a vertex turning inwards, or one winding more than once).
Fracture3 polygon_fracture(std::vector<Vec3> vertices, int set, const std::string& where,
                           double planarity = kPolygonPlanarityTolerance);

// ---- measures (fractures3d_measures.cpp) --------------------------------

// Area of the fracture inside the box, exactly: a disc by disc_area_in_box,
// a polygon clipped to the box, a plane by its section of the box.
double fracture_area_in_box(const Fracture3& f, const Box3& box);
// Sum of fracture_area_in_box over the fractures divided by the box volume.
double p32_in_box(const std::vector<Fracture3>& fractures, const Box3& box);

}  // namespace dda::dl
