// Section `excavations` in 3D: convex openings (tunnels, boxes, slopes,
// general half-spaces), each a ConvexRegion whose normals point out of the
// opened volume, and openings of any shape given as closed surfaces.
#include <Eigen/Geometry>
#include <cmath>

#include "builder.hpp"
#include "dda/common/scenario.hpp"
#include "dda/common/triangle_mesh.hpp"
#include "dda/dl/dfn3d.hpp"
#include "dda/dl/polygon3d.hpp"
#include "scenario3d_builder.hpp"

namespace dda::dl::detail {

namespace {

HalfSpace unit_half_space(const Vec3& normal, const Vec3& point) {
  const Vec3 n = normal.normalized();
  return {n, n.dot(point)};
}

// Volume of the region's part inside the box, exactly: that part is a convex
// polyhedron whose faces lie on the box's planes and the region's; each face
// is its plane's section clipped by every other half-space, and the volume is
// the sum of (distance of the face's plane from a centre) * area / 3.
double volume_in_box(const ConvexRegion& region, const Box3& box) {
  const double diag = (box.hi - box.lo).norm(), tol = 1e-12 * diag;
  std::vector<HalfSpace> all = box_region(box).half_spaces;
  for (HalfSpace h : region.half_spaces) {
    const double len = h.normal.norm();
    h.normal /= len;
    h.offset /= len;
    all.push_back(h);
  }
  // A plane given twice would count its face twice.
  std::vector<HalfSpace> planes;
  for (const HalfSpace& h : all) {
    bool twice = false;
    for (const HalfSpace& g : planes)
      twice = twice || ((g.normal - h.normal).norm() < 1e-12 && std::abs(g.offset - h.offset) < tol);
    if (!twice) planes.push_back(h);
  }
  const Vec3 centre = 0.5 * (box.lo + box.hi);
  const Box3 wide = box.grown(diag);  // so that the box's own faces have a section
  double volume = 0;
  for (std::size_t j = 0; j < planes.size(); ++j) {
    Polygon3 face = plane_in_box(planes[j].normal, planes[j].offset, wide);
    for (std::size_t k = 0; k < planes.size() && face.size() >= 3; ++k)
      if (k != j) face = clip_polygon(face, planes[k], tol);
    volume += (planes[j].offset - planes[j].normal.dot(centre)) * polygon_area(face) / 3;
  }
  return volume;
}

// Volume of the surface's inside within the box, exactly: the winding
// number at x counts the triangles its upward ray crosses (+1 where it
// leaves, -1 where it enters), so the volume is the sum over triangles of
// +-(the part of the box's columns below the triangle) -- the integral of
// the triangle's height above the box floor, clamped to the box, over its
// shadow on the box's rectangle.
double volume_in_box(const TriangleMesh& mesh, const Box3& box) {
  const double height = box.hi.z() - box.lo.z();
  const std::vector<HalfSpace> column = {
      {-Vec3::UnitX(), -box.lo.x()}, {Vec3::UnitX(), box.hi.x()}, {-Vec3::UnitY(), -box.lo.y()}, {Vec3::UnitY(), box.hi.y()}};
  double volume = 0;
  for (const auto& t : mesh.triangles) {
    Polygon3 p{mesh.vertices[static_cast<std::size_t>(t[0])], mesh.vertices[static_cast<std::size_t>(t[1])],
               mesh.vertices[static_cast<std::size_t>(t[2])]};
    for (const HalfSpace& h : column) p = clip_polygon(p, h);
    // Signed shadow areas (the sign of the normal's z) of the parts between
    // the floor and the roof and above the roof.
    const Polygon3 above_floor = clip_polygon(p, HalfSpace{-Vec3::UnitZ(), -box.lo.z()});
    const Polygon3 between = clip_polygon(above_floor, HalfSpace{Vec3::UnitZ(), box.hi.z()});
    const Polygon3 above_roof = clip_polygon(above_floor, HalfSpace{-Vec3::UnitZ(), -box.hi.z()});
    volume += height * vector_area(above_roof).z();
    for (std::size_t i = 1; i + 1 < between.size(); ++i) {
      const Vec3 &a = between[0], &b = between[i], &c = between[i + 1];
      volume += 0.5 * (b - a).cross(c - a).z() * ((a.z() + b.z() + c.z()) / 3 - box.lo.z());
    }
  }
  return volume;
}

// Unit vectors across a tunnel's axis: `up` is +z made perpendicular to the
// axis (+y for a vertical shaft, where +z is the axis), `side` completes them.
std::pair<Vec3, Vec3> tunnel_frame(const Vec3& axis) {
  Vec3 up = Vec3::UnitZ() - axis.z() * axis;
  if (up.norm() < 1e-9) up = Vec3::UnitY() - axis.y() * axis;
  up.normalize();
  return {up, up.cross(axis).normalized()};
}

ConvexRegion tunnel(const YamlNode& n, nlohmann::json& rep, const Builder3& b) {
  const std::string section = n.choice("section", {"circle", "rectangle"}, "circle");
  if (section == "circle")
    n.allow({"shape", "name", "section", "start", "end", "radius", "sides"});
  else
    n.allow({"shape", "name", "section", "start", "end", "width", "height"});
  const Vec3 start = b.local(point3(n, "start")), end = b.local(point3(n, "end"));
  if (!((end - start).norm() > 0)) n.fail_key("end", "must differ from start (the tunnel has no length)");
  const Vec3 axis = (end - start).normalized();
  const auto [up, side] = tunnel_frame(axis);
  ConvexRegion r;
  r.half_spaces.push_back(unit_half_space(-axis, start));  // the end caps
  r.half_spaces.push_back(unit_half_space(axis, end));
  rep["section"] = section;
  rep["length"] = (end - start).norm();
  if (section == "circle") {
    const double radius = n.number("radius", Range::positive());
    const int sides = static_cast<int>(n.integer("sides", 24, Range::closed(3, 1000)));
    // Vertices on the circle, one at the crown (along `up`): face k faces
    // the angle (k + 1/2) step from up, at the apothem from the axis.
    const double step = 2 * kPi / sides, apothem = radius * std::cos(step / 2);
    for (int k = 0; k < sides; ++k) {
      const double a = (k + 0.5) * step;
      const Vec3 dir = std::cos(a) * up + std::sin(a) * side;
      r.half_spaces.push_back({dir, dir.dot(start) + apothem});
    }
    rep["radius"] = radius;
    rep["sides"] = sides;
  } else {
    const double w = n.number("width", Range::positive()), h = n.number("height", Range::positive());
    for (const auto& [dir, half] :
         {std::pair{up, h / 2}, std::pair{Vec3(-up), h / 2}, std::pair{side, w / 2}, std::pair{Vec3(-side), w / 2}})
      r.half_spaces.push_back({dir, dir.dot(start) + half});
    rep["width"] = w;
    rep["height"] = h;
  }
  return r;
}

ConvexRegion read_region(const YamlNode& n, const std::string& shape, nlohmann::json& rep, const Builder3& b) {
  if (shape == "tunnel") return tunnel(n, rep, b);
  if (shape == "box") {
    n.allow({"shape", "name", "min", "max"});
    const Vec3 lo = b.local(point3(n, "min")), hi = b.local(point3(n, "max"));
    if (!(hi.array() > lo.array()).all()) n.fail_key("max", "must be greater than min in x, y and z");
    return box_region({lo, hi});
  }
  if (shape == "slope") {
    n.allow({"shape", "name", "dip", "dip_direction", "point", "floor"});
    const double dip = read_dip(n, "dip"), dd = read_dip_direction(n, "dip_direction");
    const Vec3 face = normal_from_dip(dip, dd);  // upper normal: it points into the air
    ConvexRegion r{{unit_half_space(-face, b.local(point3(n, "point")))}};
    if (n.has("floor")) {
      const double floor = n.number("floor", Range::any());
      r.half_spaces.push_back({Vec3(0, 0, -1), -(floor - b.model.origin.z())});  // the air above the toe level
      rep["floor"] = floor;
    }
    rep["dip"] = dip;
    rep["dip_direction"] = dd;
    return r;
  }
  n.allow({"shape", "name", "planes"});
  ConvexRegion r;
  const auto planes = n.list("planes");
  if (planes.empty()) n.fail_key("planes", "must list at least one plane {normal, point}");
  for (const YamlNode& p : planes) {
    p.allow({"normal", "point"});
    const Vec3 normal = point3(p, "normal");
    if (!(normal.norm() > 0)) p.fail_key("normal", "must not be the zero vector");
    r.half_spaces.push_back(unit_half_space(normal, b.local(point3(p, "point"))));
  }
  return r;
}

// `{shape: surface, file}`: an opening of any shape, inside a closed STL or
// OBJ surface.
TriangleMesh read_surface(const YamlNode& root, const YamlNode& n, nlohmann::json& rep) {
  n.allow({"shape", "name", "file"});
  // The 2D sections (dl/src/trace_plane.cpp) know only convex openings.
  if (root.has("trace_planes"))
    n.fail_key("shape", "surface cannot be sectioned by trace_planes yet (leave out trace_planes, or use a convex shape)");
  const std::string file = n.text("file");
  TriangleMesh mesh;
  try {
    mesh = read_triangle_mesh(resolve_scenario_path(n, file));
  } catch (const InputError& e) {
    fail_from(n, "file", "names a surface file with an error", e);
  }
  rep["file"] = file;
  rep["triangles"] = mesh.triangles.size();
  rep["volume"] = enclosed_volume(mesh);
  return mesh;
}

}  // namespace

void read_excavations3(const YamlNode& root, Builder3& b) {
  nlohmann::json rep = nlohmann::json::array();
  const auto items = root.list_or_empty("excavations");
  for (std::size_t i = 0; i < items.size(); ++i) {
    const YamlNode& n = items[i];
    if (!n.is_map()) n.fail("must be a mapping with a shape (tunnel, box, slope, half_spaces or surface)");
    const std::string shape = n.choice("shape", {"tunnel", "box", "slope", "half_spaces", "surface"});
    Excavation3 ex;
    ex.name = read_name(n, "E", i);
    for (const Excavation3& other : b.model.excavations)
      if (other.name == ex.name) n.fail_key("name", "'" + ex.name + "' is already the name of another excavation");
    nlohmann::json entry = {{"name", ex.name}, {"shape", shape}};
    if (shape == "surface") {
      ex.surface = read_surface(root, n, entry);
      for (Vec3& v : ex.surface->vertices) v = b.local(v);
    } else {
      ex.region = read_region(n, shape, entry, b);
    }
    const double volume =
        ex.surface ? volume_in_box(*ex.surface, b.model.domain) : volume_in_box(ex.region, b.model.domain);
    if (!(volume > 1e-12 * b.model.domain.volume()))
      n.fail("does not reach into the domain (an excavation must open part of it)");
    entry["half_spaces"] = ex.region.half_spaces.size();
    entry["volume_in_domain"] = volume;
    rep.push_back(entry);
    b.model.excavations.push_back(std::move(ex));
  }
  b.report["excavations"] = rep;
}

}  // namespace dda::dl::detail
