// From working cells to the blocks file: convex parts with outward faces,
// their moments and bed, the bodies they form, and each body's removability.
#include <cmath>

#include "cut3d_internal.hpp"
#include "dda/common/error.hpp"
#include "dda/dc/removability.hpp"

namespace dda::dc::detail3 {

int boundary_index(const std::string& name) {
  static const char* names[6] = {"x-", "x+", "y-", "y+", "z-", "z+"};
  for (int i = 0; i < 6; ++i)
    if (name == names[i]) return i;
  return -1;
}

namespace {

bool contains(const cell::Cell& c, const cell::PlaneTable& t, const Vec3& p) {
  for (const auto& f : c.faces) {
    const auto& pl = t[f.plane];
    const double tol = 1e-9 * (pl.n.norm() * (c.bounds.hi - c.bounds.lo).norm());
    if (f.sense * pl.value_at(p) > tol) return false;
  }
  return true;
}

Polyhedron to_polyhedron(const cell::Cell& c, const cell::PlaneTable& t) {
  Polyhedron p;
  for (const auto& v : c.vertices) p.vertices.push_back(v.x);
  for (const auto& f : c.faces) {
    PolyFace out;
    out.vertices = f.loop;
    out.normal = (f.sense * t[f.plane].n).normalized();
    out.set = f.tag;
    p.faces.push_back(std::move(out));
  }
  const PolyhedronMoments m = cell::moments(c);
  p.volume = m.volume;
  p.centroid = m.centroid;
  p.second_moment = m.second_moment;
  return p;
}

}  // namespace

void build_output(Work& w, const FractureModel& in, const Cut3dOptions& options, PolyhedronModel& out,
                  std::size_t& removed_by_holes, std::size_t& unfinished_fractures) {
  bool free_plane[6] = {false, false, false, false, false, false};
  bool free_surface = false;
  for (const auto& name : options.free_boundaries) {
    if (name == "surface") {
      free_surface = true;
      continue;
    }
    const int i = boundary_index(name);
    if (i < 0)
      throw InputError("cutting.free_boundaries: '" + name + "' is not one of x-, x+, y-, y+, z-, z+, surface");
    free_plane[i] = true;
  }
  // A domain surface usually shapes the ground (a slope face, benches): its
  // faces off the box are free when "surface" is listed (the default); on
  // the box they follow the box face's name.
  auto is_free_boundary = [&](const cell::Face& f) {
    for (int i = 0; i < 6; ++i)
      if (f.plane == w.boundary_planes[i]) return free_plane[i];
    const auto p = static_cast<std::size_t>(f.plane);
    return free_surface && p < w.domain_surface_planes.size() && w.domain_surface_planes[p];
  };

  int body_count = 0;
  std::vector<std::vector<std::uint8_t>> finite_contact;
  std::vector<int> body = glue_bodies(w, body_count, unfinished_fractures, finite_contact);

  // Hole points remove the body they fall in.
  std::vector<bool> body_removed(static_cast<std::size_t>(body_count), false);
  for (const auto& pt : in.points) {
    if (pt.kind != PointKind::Hole) {
      out.points.push_back(pt);
      continue;
    }
    for (std::size_t i = 0; i < w.cells.size(); ++i)
      if (contains(w.cells[i], w.table, pt.p)) body_removed[static_cast<std::size_t>(body[i])] = true;
  }

  std::vector<int> new_index(static_cast<std::size_t>(body_count), -1);
  std::vector<std::vector<Vec3>> contact_normals;
  std::vector<bool> exposed;
  removed_by_holes = 0;
  double hole_volume = 0;
  for (std::size_t i = 0; i < w.cells.size(); ++i) {
    const auto b = static_cast<std::size_t>(body[i]);
    Polyhedron p = to_polyhedron(w.cells[i], w.table);
    if (body_removed[b]) {
      hole_volume += p.volume;
      ++removed_by_holes;
      continue;
    }
    if (new_index[b] < 0) {
      new_index[b] = static_cast<int>(out.bodies.size());
      out.bodies.emplace_back();
      contact_normals.emplace_back();
      exposed.push_back(false);
    }
    const auto nb = static_cast<std::size_t>(new_index[b]);
    p.body = new_index[b];
    const double level = p.centroid.dot(in.bed_normal.normalized());
    for (std::size_t l = 0; l < in.layers.size(); ++l)
      if (level >= in.layers[l].bottom && level <= in.layers[l].top) p.layer = static_cast<int>(l);
    bool free_face = w.cells[i].exposed;
    for (std::size_t f = 0; f < p.faces.size(); ++f) {
      const auto& cf = w.cells[i].faces[f];
      const bool finite = w.role[static_cast<std::size_t>(cf.plane)] == PlaneRole::Finite;
      if (cf.tag == kBoundarySet && is_free_boundary(cf)) free_face = true;
      else if ((cf.tag >= 0 && (!finite || finite_contact[i][f])) || cf.tag == kBoundarySet)
        contact_normals[nb].push_back(p.faces[f].normal);
    }
    exposed[nb] = exposed[nb] || free_face;
    out.bodies[nb].parts.push_back(static_cast<int>(out.blocks.size()));
    out.bodies[nb].volume += p.volume;
    out.blocks.push_back(std::move(p));
  }
  for (std::size_t b = 0; b < out.bodies.size(); ++b) {
    const RemovabilityResult r = classify_removability(contact_normals[b], exposed[b], options.gravity_direction);
    out.bodies[b].removability = r.mode;
    out.bodies[b].sliding_direction = r.direction;
  }

  out.sets = in.sets;
  out.layers = in.layers;
  out.bed_normal = in.bed_normal;
  out.domain = in.domain;
  out.domain_volume = in.domain_surface ? std::abs(enclosed_volume(*in.domain_surface)) : in.domain.volume();
  out.excavated_volume = w.excavated_volume + hole_volume;
  out.origin = in.origin;
  out.provenance = in.provenance;
}


}  // namespace dda::dc::detail3

namespace dda::dc {

Cut3dOptions parse_cut3d_options(const std::optional<YamlNode>& cutting) {
  Cut3dOptions o;
  if (!cutting) return o;
  cutting->allow({"free_boundaries", "gravity_direction", "snap_tolerance", "finite_fractures"});
  o.finite_fractures = cutting->choice("finite_fractures", {"glue", "through"}, "glue") == "glue"
                           ? FiniteFractures::Glue
                           : FiniteFractures::Through;
  o.snap_tolerance = cutting->number("snap_tolerance", 0.0, Range::non_negative());
  if (cutting->has("free_boundaries")) {
    o.free_boundaries.clear();
    const YamlNode list = cutting->child("free_boundaries");
    for (const auto& item : list.items()) {
      const std::string name = item.as_text();
      if (name != "surface" && detail3::boundary_index(name) < 0)
        item.fail("must be one of x-, x+, y-, y+, z-, z+, surface, got '" + name + "'");
      o.free_boundaries.push_back(name);
    }
  }
  if (cutting->has("gravity_direction")) {
    const auto v = cutting->child("gravity_direction").as_numbers();
    if (v.size() != 3 || Vec3(v[0], v[1], v[2]).norm() == 0)
      cutting->fail_key("gravity_direction", "must be three numbers, not all zero");
    o.gravity_direction = Vec3(v[0], v[1], v[2]).normalized();
  }
  return o;
}

}  // namespace dda::dc
