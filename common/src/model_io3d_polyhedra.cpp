// The 3D blocks file (`dda-blocks3d`): DC's 3D output. Layout in
// docs/formats.md; keep the two in step.
//
// Block vertices and faces are two levels of CSR: /blocks/vertex_offsets
// slices /blocks/vertices per block, /blocks/face_offsets slices the faces
// per block, and /faces/offsets slices /faces/vertices per face. Face vertex
// ids stay local to their block (as in Polyhedron), so a block can be read
// alone.
#include <cmath>
#include <limits>

#include "dda/common/atomic_file.hpp"
#include "dda/common/origin_h5.hpp"
#include "dda/common/model_io3d.hpp"
#include "dda/common/model_io3d_h5.hpp"
#include "model_io_detail.hpp"

namespace dda {
namespace {

constexpr const char* kRemovabilityCodes =
    "0 not_exposed, 1 tapered, 2 removable, 3 falls, 4 slides_one_face, 5 slides_two_faces";
constexpr long long kIntMax = std::numeric_limits<int>::max();

std::size_t as_index(std::int64_t v) { return static_cast<std::size_t>(v); }

void write_blocks(h5::Writer& w, const std::vector<Polyhedron>& blocks, const std::string& at) {
  std::vector<Vec3> vertices, centroid, face_normal;
  std::vector<std::int64_t> vertex_offsets{0}, face_offsets{0}, face_vertex_offsets{0};
  std::vector<std::int32_t> face_vertices, face_set, body, layer;
  std::vector<double> volume, moment;
  for (const Polyhedron& b : blocks) {
    vertices.insert(vertices.end(), b.vertices.begin(), b.vertices.end());
    vertex_offsets.push_back(static_cast<std::int64_t>(vertices.size()));
    for (const PolyFace& f : b.faces) {
      face_vertices.insert(face_vertices.end(), f.vertices.begin(), f.vertices.end());
      face_vertex_offsets.push_back(static_cast<std::int64_t>(face_vertices.size()));
      face_normal.push_back(f.normal);
      face_set.push_back(f.set);
    }
    face_offsets.push_back(static_cast<std::int64_t>(face_normal.size()));
    volume.push_back(b.volume);
    centroid.push_back(b.centroid);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) moment.push_back(b.second_moment(i, j));
    body.push_back(b.body);
    layer.push_back(b.layer);
  }
  const hsize_t nb = blocks.size(), nf = face_normal.size();
  {
    h5::Id g = w.group(at + "blocks");
    w.f64(g.get(), "vertices", io::flatten(vertices), {vertices.size(), 3}, "m",
          "vertices x, y, z of all blocks, one block after another");
    w.i64(g.get(), "vertex_offsets", vertex_offsets, "",
          "block i has vertices[vertex_offsets[i]:vertex_offsets[i+1]]; B+1 entries");
    w.i64(g.get(), "face_offsets", face_offsets, "",
          "block i has the faces face_offsets[i] .. face_offsets[i+1]-1 of /faces; B+1 entries");
    w.f64(g.get(), "volume", volume, {nb}, "m^3", "volume of block i");
    w.f64(g.get(), "centroid", io::flatten(centroid), {nb, 3}, "m", "centroid x, y, z of block i");
    w.f64(g.get(), "second_moment", moment, {nb, 3, 3}, "m^5",
          "integral of (x-c)(x-c)^T over block i, c its centroid (a symmetric 3 x 3 matrix)");
    w.i32(g.get(), "body", body, "", "rock body block i is a convex part of (index into /bodies)");
    w.i32(g.get(), "layer", layer, "", "bed containing the centroid of block i, -1 if not layered");
  }
  {
    h5::Id g = w.group(at + "faces");
    w.i32(g.get(), "vertices", face_vertices, "",
          "vertex ids of all faces, each counter-clockwise seen from outside its block; ids are "
          "local to the block (0 is its first vertex)");
    w.i64(g.get(), "offsets", face_vertex_offsets, "",
          "face j has vertices[offsets[j]:offsets[j+1]]; F+1 entries");
    w.f64(g.get(), "normal", io::flatten(face_normal), {nf, 3}, "1",
          "unit outward normal x, y, z of face j");
    w.i32(g.get(), "set", face_set, "", std::string("joint set of face j: ") + io::kSetCodes);
  }
}

void write_bodies(h5::Writer& w, const std::vector<Body3>& bodies, const std::string& at) {
  h5::Id g = w.group(at + "bodies");
  std::vector<std::int32_t> parts, removability;
  std::vector<std::int64_t> offsets{0};
  std::vector<double> volume;
  std::vector<Vec3> sliding;
  for (const Body3& b : bodies) {
    parts.insert(parts.end(), b.parts.begin(), b.parts.end());
    offsets.push_back(static_cast<std::int64_t>(parts.size()));
    volume.push_back(b.volume);
    removability.push_back(static_cast<std::int32_t>(b.removability));
    sliding.push_back(b.sliding_direction);
  }
  const hsize_t n = bodies.size();
  w.i32(g.get(), "parts", parts, "",
        "block ids of the convex parts of all bodies, body after body");
  w.i64(g.get(), "offsets", offsets, "", "body k is parts[offsets[k]:offsets[k+1]]; N+1 entries");
  w.f64(g.get(), "volume", volume, {n}, "m^3", "volume of body k");
  w.i32(g.get(), "removability", removability, "",
        std::string("block-theory class of body k: ") + kRemovabilityCodes);
  w.f64(g.get(), "sliding_direction", io::flatten(sliding), {n, 3}, "1",
        "unit direction x, y, z in which body k leaves under gravity (falls or slides), else 0");
}

// The blocks without `body` checked against the bodies (read later).
std::vector<Polyhedron> read_blocks(const h5::Reader& r, long long nsets, long long nlayers, const std::string& at) {
  const std::string bg = "/" + at + "blocks/", fg = "/" + at + "faces/";
  std::size_t nv = 0, nf = 0;
  const std::vector<double> xyz = io::read_table(r, bg + "vertices", 3, nv);
  const std::vector<std::int64_t> voff =
      io::read_offsets(r, bg + "vertex_offsets", nv, 4, "block");
  const std::size_t nb = voff.size() - 1;
  const std::vector<double> normal = io::read_table(r, fg + "normal", 3, nf);
  const std::vector<std::int64_t> foff =
      io::read_offsets(r, bg + "face_offsets", nf, 4, "block");
  if (foff.size() != nb + 1)
    r.fail("dataset " + bg + "face_offsets has " + std::to_string(foff.size()) +
           " entries, expected " + std::to_string(nb + 1) + ", as many as /blocks/vertex_offsets");
  const std::vector<int> fv = io::read_int_list(r, fg + "vertices", 0, kIntMax);
  const std::vector<std::int64_t> fvoff =
      io::read_offsets(r, fg + "offsets", fv.size(), 3, "face");
  if (fvoff.size() != nf + 1)
    r.fail("dataset /faces/offsets has " + std::to_string(fvoff.size()) + " entries, expected " +
           std::to_string(nf + 1) + ", one more than the rows of /faces/normal");
  const std::vector<int> fset =
      io::read_ints(r, fg + "set", nf, "face", kArtificialSet, nsets - 1);
  const std::vector<double> volume = io::read_vector(r, bg + "volume", nb, "block");
  const std::vector<double> centroid = io::read_rows(r, bg + "centroid", nb, 3, "block");
  const std::vector<double> moment = io::read_fixed(r, bg + "second_moment", {nb, 3, 3});
  const std::vector<int> body = io::read_ints(r, bg + "body", nb, "block", -1, kIntMax);
  const std::vector<int> layer = io::read_ints(r, bg + "layer", nb, "block", -1, nlayers - 1);

  std::vector<Polyhedron> out(nb);
  for (std::size_t i = 0; i < nb; ++i) {
    Polyhedron& b = out[i];
    for (std::size_t k = as_index(voff[i]); k < as_index(voff[i + 1]); ++k)
      b.vertices.push_back(io::row3(xyz, k));
    for (std::size_t j = as_index(foff[i]); j < as_index(foff[i + 1]); ++j) {
      PolyFace f;
      for (std::size_t k = as_index(fvoff[j]); k < as_index(fvoff[j + 1]); ++k) {
        if (static_cast<std::size_t>(fv[k]) >= b.vertices.size())
          r.fail("dataset /faces/vertices entry " + std::to_string(k) + " is " +
                 std::to_string(fv[k]) + ", but the block of face " + std::to_string(j) + " has " +
                 std::to_string(b.vertices.size()) + " vertices");
        f.vertices.push_back(fv[k]);
      }
      f.normal = io::row3(normal, j);
      f.set = fset[j];
      b.faces.push_back(std::move(f));
    }
    b.volume = volume[i];
    b.centroid = io::row3(centroid, i);
    using RowMajor3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;
    b.second_moment = Eigen::Map<const RowMajor3>(&moment[9 * i]);  // as written, row by row
    b.body = body[i];
    b.layer = layer[i];
  }
  return out;
}

std::vector<Body3> read_bodies(const h5::Reader& r, std::size_t nblocks, const std::string& at) {
  std::vector<Body3> out;
  const std::string g = "/" + at + "bodies/";
  if (!r.exists("/" + at + "bodies")) return out;
  const std::vector<int> parts =
      io::read_int_list(r, g + "parts", 0, static_cast<long long>(nblocks) - 1);
  const std::vector<std::int64_t> off =
      io::read_offsets(r, g + "offsets", parts.size(), 1, "body");
  const std::size_t n = off.size() - 1;
  const std::vector<double> volume = io::read_vector(r, g + "volume", n, "body");
  const std::vector<int> removability = io::read_ints(
      r, g + "removability", n, "body", 0, static_cast<long long>(Removability::SlidesTwo));
  const std::vector<double> sliding = io::read_rows(r, g + "sliding_direction", n, 3, "body");
  out.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    out[k].parts.assign(parts.begin() + off[k], parts.begin() + off[k + 1]);
    out[k].volume = volume[k];
    out[k].removability = static_cast<Removability>(removability[k]);
    out[k].sliding_direction = io::row3(sliding, k);
  }
  return out;
}

// Everything but the file's own identity: the blocks file is this at the
// root, the 3D results file the same below /model.
void write_content(h5::Writer& w, const PolyhedronModel& model, const std::string& at, hid_t attrs) {
  w.attr_f64(attrs, "domain_volume", model.domain_volume);
  w.attr_f64(attrs, "excavated_volume", model.excavated_volume);
  w.attr_i32(attrs, "unfinished_cuts", model.unfinished_cuts);
  io::write_origin(w, attrs, model.origin);
  io::write_domain(w, model.domain, at);
  write_blocks(w, model.blocks, at);
  write_bodies(w, model.bodies, at);
  io::write_sets(w, model.sets, at);
  io::write_points(w, model.points, at);
  io::write_layers(w, model.layers, model.bed_normal, at);
}

PolyhedronModel read_content(const h5::Reader& r, const std::string& at, hid_t attrs) {
  PolyhedronModel m;
  m.provenance = io::read_provenance(r, attrs);
  const std::string where = at.empty() ? "the file" : "/" + at;
  auto number = [&](const char* name) {
    const double v = r.attr_f64(attrs, name, where).value_or(0.0);
    if (!std::isfinite(v)) r.fail(std::string("attribute ") + name + " is not a finite number");
    return v;
  };
  m.domain_volume = number("domain_volume");
  m.excavated_volume = number("excavated_volume");
  m.origin = io::read_origin3(r, attrs, where);
  const auto unfinished = r.attr_int(attrs, "unfinished_cuts", where).value_or(0);
  if (unfinished < 0 || unfinished > kIntMax)
    r.fail("attribute unfinished_cuts is " + std::to_string(unfinished) + ", must be 0 or more");
  m.unfinished_cuts = static_cast<int>(unfinished);
  m.domain = io::read_domain(r, at);
  m.sets = io::read_sets(r, at);
  m.points = io::read_points(r, at);
  m.layers = io::read_layers(r, m.bed_normal, at);
  m.blocks = read_blocks(r, static_cast<long long>(m.sets.size()),
                         static_cast<long long>(m.layers.size()), at);
  m.bodies = read_bodies(r, m.blocks.size(), at);
  // A block names its body once bodies are recorded (-1: none); without
  // bodies the index is kept as written.
  if (!m.bodies.empty())
    for (std::size_t i = 0; i < m.blocks.size(); ++i)
      if (m.blocks[i].body >= static_cast<int>(m.bodies.size()))
        r.fail("dataset /" + at + "blocks/body entry " + std::to_string(i) + " is " +
               std::to_string(m.blocks[i].body) + ", must be between -1 and " +
               std::to_string(m.bodies.size() - 1));
  return m;
}

}  // namespace

void write_polyhedra_h5(const std::string& path, const PolyhedronModel& model) {
  AtomicOutput out(path);
  {
    h5::Writer w(path, out.temp_path());
    io::write_root_attributes(w, kBlocks3dFormat, io::kUnits3d, model.provenance);
    write_content(w, model, "", w.file());
    w.close();
  }
  out.commit();
}

PolyhedronModel read_polyhedra_h5(const std::string& path) {
  h5::Reader r(path);
  io::check_format(r, kBlocks3dFormat);
  return read_content(r, "", r.file());
}

void write_polyhedra_group(h5::Writer& w, const std::string& group, const PolyhedronModel& model) {
  h5::Id g = w.group(group);
  io::write_root_attributes(w, kBlocks3dFormat, io::kUnits3d, model.provenance, g.get());
  write_content(w, model, group + "/", g.get());
}

PolyhedronModel read_polyhedra_group(const h5::Reader& r, const std::string& group) {
  if (!r.exists("/" + group)) r.fail("has no /" + group + " group (the blocks the run started from)");
  h5::Id g(H5Gopen2(r.file(), ("/" + group).c_str(), H5P_DEFAULT), H5Gclose);
  if (!g.valid()) r.fail("/" + group + " is not a group");
  return read_content(r, group + "/", g.get());
}

}  // namespace dda
