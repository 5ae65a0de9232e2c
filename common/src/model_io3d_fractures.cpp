// The fractures file (`dda-fractures`): DL's 3D output. Layout in
// docs/formats.md; keep the two in step.

#include <limits>

#include "dda/common/atomic_file.hpp"
#include "dda/common/error.hpp"
#include "dda/common/model_io3d.hpp"
#include "dda/common/origin_h5.hpp"
#include "model_io_detail.hpp"

namespace dda {
namespace {

// An (n, 3) int32 dataset of vertex ids.
void write_triangles(h5::Writer& w, hid_t loc, const std::string& name,
                     const std::vector<std::int32_t>& ids, const std::string& description) {
  w.i32(loc, name, ids, {ids.size() / 3, 3}, "", description);
}

void append_mesh(const TriangleMesh& m, std::vector<Vec3>& vertices, std::vector<std::int32_t>& ids) {
  vertices.insert(vertices.end(), m.vertices.begin(), m.vertices.end());
  for (const auto& t : m.triangles) ids.insert(ids.end(), t.begin(), t.end());
}

// Written only with a surface: an absent group is a box domain.
void write_domain_surface(h5::Writer& w, const std::optional<TriangleMesh>& surface) {
  if (!surface) return;
  h5::Id g = w.group("domain/surface");
  std::vector<Vec3> vertices;
  std::vector<std::int32_t> ids;
  append_mesh(*surface, vertices, ids);
  w.f64(g.get(), "vertices", io::flatten(vertices), {vertices.size(), 3}, "m",
        "vertices x, y, z of the closed surface that bounds the rock");
  write_triangles(w, g.get(), "triangles", ids,
                  "vertex ids (rows of vertices, from 0) of each triangle, counter-clockwise seen from outside the rock");
}

void write_excavations(h5::Writer& w, const std::vector<Excavation3>& excavations) {
  h5::Id g = w.group("excavations");
  std::vector<std::string> names;
  std::vector<double> planes;
  std::vector<std::int64_t> offsets{0}, vertex_offsets{0}, triangle_offsets{0};
  std::vector<Vec3> mesh_vertices;
  std::vector<std::int32_t> mesh_ids;
  for (const Excavation3& e : excavations) {
    names.push_back(e.name);
    for (const HalfSpace& h : e.region.half_spaces)
      planes.insert(planes.end(), {h.normal.x(), h.normal.y(), h.normal.z(), h.offset});
    offsets.push_back(static_cast<std::int64_t>(planes.size() / 4));
    if (e.surface) append_mesh(*e.surface, mesh_vertices, mesh_ids);
    vertex_offsets.push_back(static_cast<std::int64_t>(mesh_vertices.size()));
    triangle_offsets.push_back(static_cast<std::int64_t>(mesh_ids.size() / 3));
  }
  w.strings(g.get(), "name", names, "", "name of excavation i (UTF-8)");
  w.f64(g.get(), "half_spaces", planes, {planes.size() / 4, 4}, "m",
        "half-spaces nx ny nz d (n . x <= d; n outward, any length) of all excavations, "
        "one excavation after another; the excavation is their intersection");
  w.i64(g.get(), "offsets", offsets, "",
        "excavation i is half_spaces[offsets[i]:offsets[i+1]]; E+1 entries");
  w.f64(g.get(), "mesh_vertices", io::flatten(mesh_vertices), {mesh_vertices.size(), 3}, "m",
        "vertices of the closed surfaces of the excavations that have one, one excavation after another");
  w.i64(g.get(), "mesh_vertex_offsets", vertex_offsets, "",
        "excavation i has mesh_vertices[mesh_vertex_offsets[i]:mesh_vertex_offsets[i+1]]; E+1 entries");
  write_triangles(w, g.get(), "mesh_triangles", mesh_ids,
                  "triangles of the excavations' surfaces: vertex ids local to the excavation's mesh_vertices "
                  "(from 0), counter-clockwise seen from outside the opening");
  w.i64(g.get(), "mesh_triangle_offsets", triangle_offsets, "",
        "excavation i has mesh_triangles[mesh_triangle_offsets[i]:mesh_triangle_offsets[i+1]] "
        "(none: no surface); E+1 entries");
}

void write_fractures(h5::Writer& w, const std::vector<Fracture3>& fractures) {
  h5::Id g = w.group("fractures");
  std::vector<std::int32_t> shape, set, kind, layer;
  std::vector<Vec3> normal, centre, vertices;
  std::vector<double> radius;
  std::vector<std::int64_t> offsets{0};
  for (const Fracture3& f : fractures) {
    shape.push_back(static_cast<std::int32_t>(f.shape));
    normal.push_back(f.normal);
    centre.push_back(f.centre);
    radius.push_back(f.radius);
    vertices.insert(vertices.end(), f.vertices.begin(), f.vertices.end());
    offsets.push_back(static_cast<std::int64_t>(vertices.size()));
    set.push_back(f.set);
    kind.push_back(static_cast<std::int32_t>(f.kind));
    layer.push_back(f.layer);
  }
  const hsize_t n = fractures.size();
  w.i32(g.get(), "shape", shape, "", "shape of fracture i: 0 plane, 1 disc, 2 polygon");
  w.f64(g.get(), "normal", io::flatten(normal), {n, 3}, "1",
        "unit normal x, y, z of fracture i (upper hemisphere)");
  w.f64(g.get(), "centre", io::flatten(centre), {n, 3}, "m",
        "a point of the plane of fracture i: the disc centre, polygon centroid, or any point");
  w.f64(g.get(), "radius", radius, {n}, "m", "radius of a disc fracture (0 for other shapes)");
  w.f64(g.get(), "vertices", io::flatten(vertices), {vertices.size(), 3}, "m",
        "vertices of the polygon fractures, counter-clockwise about the normal, one after another");
  w.i64(g.get(), "offsets", offsets, "",
        "fracture i has vertices[offsets[i]:offsets[i+1]] (none unless a polygon); F+1 entries");
  w.i32(g.get(), "set", set, "", std::string("joint set of fracture i: ") + io::kSetCodes);
  w.i32(g.get(), "kind", kind, "", "kind of fracture i: 0 joint, 1 bedding");
  w.i32(g.get(), "layer", layer, "",
        "bed fracture i was generated in (index into /layers), -1 if none");
}

// An (n, 3) integer dataset of vertex ids.
std::vector<std::array<int, 3>> read_triangles(const h5::Reader& r, const std::string& ds) {
  const h5::Array<std::int64_t> a = r.i64(ds);
  if (a.dims.size() != 2 || a.dims[1] != 3)
    r.fail("dataset " + ds + " must have shape (N, 3), one row of vertex ids per triangle");
  std::vector<std::array<int, 3>> out(a.dims[0]);
  for (std::size_t i = 0; i < a.data.size(); ++i) {
    if (a.data[i] < 0 || a.data[i] > std::numeric_limits<int>::max())
      r.fail("dataset " + ds + " has the vertex id " + std::to_string(a.data[i]) + ", which cannot be one");
    out[i / 3][i % 3] = static_cast<int>(a.data[i]);
  }
  return out;
}

// A surface as stored must be closed (the cutter's inside test needs it);
// it is turned outward here, so the file may hold it either way round.
TriangleMesh checked_mesh(const h5::Reader& r, TriangleMesh m, const std::string& what) {
  try {
    check_closed_surface(m, what);
  } catch (const InputError& e) {
    std::string s = e.what();
    if (!s.empty() && s.back() == '.') s.pop_back();
    r.fail(s);
  }
  orient_outward(m);
  return m;
}

std::optional<TriangleMesh> read_domain_surface(const h5::Reader& r) {
  if (!r.exists("/domain/surface")) return std::nullopt;
  TriangleMesh m;
  std::size_t nv = 0;
  const std::vector<double> xyz = io::read_table(r, "/domain/surface/vertices", 3, nv);
  for (std::size_t i = 0; i < nv; ++i) m.vertices.push_back(io::row3(xyz, i));
  m.triangles = read_triangles(r, "/domain/surface/triangles");
  return checked_mesh(r, std::move(m), "the domain surface in /domain/surface");
}

std::vector<Excavation3> read_excavations(const h5::Reader& r) {
  std::vector<Excavation3> out;
  if (!r.exists("/excavations")) return out;
  std::vector<std::string> names = r.strings("/excavations/name");
  std::size_t nh = 0;
  const std::vector<double> planes = io::read_table(r, "/excavations/half_spaces", 4, nh);
  // An excavation may be a surface alone; files without meshes (older ones)
  // need a half-space for each.
  const bool meshes = r.exists("/excavations/mesh_triangles");
  const std::vector<std::int64_t> off =
      io::read_offsets(r, "/excavations/offsets", nh, meshes ? 0 : 1, "excavation");
  if (off.size() != names.size() + 1)
    r.fail("dataset /excavations/offsets has " + std::to_string(off.size()) +
           " entries, expected " + std::to_string(names.size() + 1) +
           ", one more than /excavations/name");
  std::size_t nv = 0;
  std::vector<double> xyz;
  std::vector<std::array<int, 3>> tris;
  std::vector<std::int64_t> voff(names.size() + 1, 0), toff(names.size() + 1, 0);
  if (meshes) {
    xyz = io::read_table(r, "/excavations/mesh_vertices", 3, nv);
    tris = read_triangles(r, "/excavations/mesh_triangles");
    voff = io::read_offsets(r, "/excavations/mesh_vertex_offsets", nv, 0, "excavation");
    toff = io::read_offsets(r, "/excavations/mesh_triangle_offsets", tris.size(), 0, "excavation");
    if (voff.size() != names.size() + 1 || toff.size() != names.size() + 1)
      r.fail("datasets /excavations/mesh_vertex_offsets and /excavations/mesh_triangle_offsets must have " +
             std::to_string(names.size() + 1) + " entries, one more than /excavations/name");
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    Excavation3 e;
    e.name = names[i];
    for (auto k = static_cast<std::size_t>(off[i]); k < static_cast<std::size_t>(off[i + 1]); ++k)
      e.region.half_spaces.push_back(
          {Vec3(planes[4 * k], planes[4 * k + 1], planes[4 * k + 2]), planes[4 * k + 3]});
    if (toff[i + 1] > toff[i]) {
      TriangleMesh m;
      for (auto k = static_cast<std::size_t>(voff[i]); k < static_cast<std::size_t>(voff[i + 1]); ++k)
        m.vertices.push_back(io::row3(xyz, k));
      m.triangles.assign(tris.begin() + toff[i], tris.begin() + toff[i + 1]);
      e.surface = checked_mesh(r, std::move(m), "the surface of excavation " + std::to_string(i) + " ('" + e.name + "')");
    } else if (e.region.half_spaces.empty()) {
      r.fail("excavation " + std::to_string(i) + " ('" + e.name + "') has neither half-spaces nor a surface");
    }
    out.push_back(std::move(e));
  }
  return out;
}

std::vector<Fracture3> read_fractures(const h5::Reader& r, long long nsets, long long nlayers) {
  const std::vector<int> shape = io::read_int_list(r, "/fractures/shape", 0, 2);
  const std::size_t n = shape.size();
  const std::vector<double> normal = io::read_rows(r, "/fractures/normal", n, 3, "fracture");
  const std::vector<double> centre = io::read_rows(r, "/fractures/centre", n, 3, "fracture");
  const std::vector<double> radius = io::read_vector(r, "/fractures/radius", n, "fracture");
  std::size_t nv = 0;
  const std::vector<double> xyz = io::read_table(r, "/fractures/vertices", 3, nv);
  const std::vector<std::int64_t> off =
      io::read_offsets(r, "/fractures/offsets", nv, 0, "fracture");
  if (off.size() != n + 1)
    r.fail("dataset /fractures/offsets has " + std::to_string(off.size()) + " entries, expected " +
           std::to_string(n + 1) + ", one more than the fractures");
  const std::vector<int> set =
      io::read_ints(r, "/fractures/set", n, "fracture", kArtificialSet, nsets - 1);
  const std::vector<int> kind = io::read_ints(r, "/fractures/kind", n, "fracture", 0, 1);
  const std::vector<int> layer =
      io::read_ints(r, "/fractures/layer", n, "fracture", -1, nlayers - 1);

  std::vector<Fracture3> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    Fracture3& f = out[i];
    f.shape = static_cast<FractureShape>(shape[i]);
    f.normal = io::row3(normal, i);
    f.centre = io::row3(centre, i);
    f.radius = radius[i];
    const auto a = static_cast<std::size_t>(off[i]), b = static_cast<std::size_t>(off[i + 1]);
    // A polygon needs an outline; a plane or disc has none.
    const bool polygon = f.shape == FractureShape::Polygon;
    if (polygon ? b - a < 3 : b != a)
      r.fail("fracture " + std::to_string(i) + " is a " + to_string(f.shape) + " with " +
             std::to_string(b - a) + " vertices in /fractures/offsets (" +
             (polygon ? "a polygon needs at least 3" : "only polygons have vertices") + ")");
    if (f.radius < 0)
      r.fail("fracture " + std::to_string(i) + " has a negative radius in /fractures/radius");
    for (std::size_t k = a; k < b; ++k) f.vertices.push_back(io::row3(xyz, k));
    f.set = set[i];
    f.kind = static_cast<LineKind>(kind[i]);
    f.layer = layer[i];
  }
  return out;
}

}  // namespace

void write_fractures_h5(const std::string& path, const FractureModel& model) {
  AtomicOutput out(path);
  {
    h5::Writer w(path, out.temp_path());
    io::write_root_attributes(w, kFracturesFormat, io::kUnits3d, model.provenance);
    io::write_origin(w, w.file(), model.origin);
    io::write_domain(w, model.domain);
    write_domain_surface(w, model.domain_surface);
    write_excavations(w, model.excavations);
    write_fractures(w, model.fractures);
    io::write_sets(w, model.sets);
    io::write_points(w, model.points);
    io::write_layers(w, model.layers, model.bed_normal);
    w.close();
  }
  out.commit();
}

FractureModel read_fractures_h5(const std::string& path) {
  h5::Reader r(path);
  io::check_format(r, kFracturesFormat);
  FractureModel m;
  m.provenance = io::read_provenance(r);
  m.origin = io::read_origin3(r, r.file());
  m.domain = io::read_domain(r);
  m.domain_surface = read_domain_surface(r);
  m.sets = io::read_sets(r);
  m.points = io::read_points(r);
  m.layers = io::read_layers(r, m.bed_normal);
  m.excavations = read_excavations(r);
  m.fractures = read_fractures(r, static_cast<long long>(m.sets.size()),
                               static_cast<long long>(m.layers.size()));
  return m;
}

}  // namespace dda
