// Lines and blocks files in HDF5 (C API). The layout is documented, dataset
// by dataset, in docs/formats.md; keep the two in step.
#include "dda/common/model_io.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "dda/common/atomic_file.hpp"
#include "dda/common/error.hpp"
#include "dda/common/h5_util.hpp"
#include "dda/common/origin_h5.hpp"
#include "model_io_detail.hpp"

namespace dda {
namespace {

// The helpers every HDF5 file of the pipeline shares (model_io_detail.hpp).
using io::check_finite;
using io::check_format;
using io::read_ints;
using io::read_provenance;
using io::read_sets;
using io::read_strings;
using io::read_vector;
using io::root_number;
using io::shape_text;
using io::write_root_attributes;
using io::write_sets;

constexpr const char* kLinesFormat = "dda-lines";
constexpr const char* kBlocksFormat = "dda-blocks";
constexpr const char* kUnits = "SI: lengths m, areas m^2, second moments m^4, angles deg";
constexpr const char* kPointKindCodes = "0 fixed, 1 load, 2 measurement, 3 hole";
constexpr const char* kLineKindCodes = "0 joint, 1 bedding";
constexpr const char* kSetCodes =
    "joint set index (0, 1, ...; see /sets), -1 domain boundary, -2 excavation outline, "
    "-3 artificial cut";

// ------------------------------------------------------------------ writing

std::vector<double> flatten(const Polygon2& poly) {
  std::vector<double> xy;
  xy.reserve(2 * poly.size());
  for (const Vec2& v : poly) {
    xy.push_back(v.x());
    xy.push_back(v.y());
  }
  return xy;
}

// `blocks` is empty for a lines file (no /points/block dataset then).
void write_points(h5::Writer& w, const std::vector<ModelPoint>& points,
                  const std::vector<int>* blocks) {
  h5::Id g = w.group("points");
  std::vector<std::string> names;
  std::vector<std::int32_t> kinds;
  std::vector<double> xy;
  for (const ModelPoint& p : points) {
    names.push_back(p.name);
    kinds.push_back(static_cast<std::int32_t>(p.kind));
    xy.push_back(p.p.x());
    xy.push_back(p.p.y());
  }
  w.strings(g.get(), "name", names, "", "name of point i (UTF-8)");
  w.i32(g.get(), "kind", kinds, "", std::string("kind of point i: ") + kPointKindCodes);
  w.f64(g.get(), "xy", xy, {points.size(), 2}, "m", "coordinates x, y of point i");
  if (blocks) {
    std::vector<std::int32_t> b(blocks->begin(), blocks->end());
    w.i32(g.get(), "block", b, "", "index of the block containing point i, -1 if none");
  }
}

void write_layers(h5::Writer& w, const std::vector<Layer>& layers) {
  io::write_layer_table(w, layers, " (elevation y for horizontal beds, else coordinate along the bed normal)", "joints");
}

// ------------------------------------------------------------------ reading

// An n x cols matrix of doubles; returns the number of rows.
std::vector<double> read_matrix(const h5::Reader& r, const std::string& ds, hsize_t cols,
                                std::size_t& rows, const char* rows_name) {
  h5::Array<double> a = r.f64(ds);
  if (a.dims.size() != 2 || a.dims[1] != cols)
    r.fail("dataset " + ds + " has shape " + shape_text(a.dims) + ", expected (" + rows_name +
           ", " + std::to_string(cols) + ")");
  rows = a.dims[0];
  check_finite(r, ds, a.data);
  return std::move(a.data);
}

std::vector<Polygon2> read_polygons(const h5::Reader& r, const std::string& group,
                                    std::vector<double>* flat_out = nullptr) {
  std::size_t nv = 0;
  std::vector<double> xy = read_matrix(r, group + "/vertices", 2, nv, "V");
  // Validated against the vertex count: every index below is in range.
  const std::vector<std::int64_t> off = r.offsets(group + "/offsets", nv, 3, "polygon");
  std::vector<Polygon2> polys(off.size() - 1);
  for (std::size_t i = 0; i + 1 < off.size(); ++i) {
    const auto a = static_cast<std::size_t>(off[i]), b = static_cast<std::size_t>(off[i + 1]);
    Polygon2& p = polys[i];
    p.reserve(b - a);
    for (std::size_t k = a; k < b; ++k) p.emplace_back(xy[2 * k], xy[2 * k + 1]);
  }
  if (flat_out) *flat_out = std::move(xy);
  return polys;
}

std::vector<ModelPoint> read_points(const h5::Reader& r) {
  std::vector<ModelPoint> points;
  if (!r.exists("/points")) return points;
  std::vector<std::string> names = r.strings("/points/name");
  const std::size_t n = names.size();
  std::vector<int> kinds = read_ints(r, "/points/kind", n, "point", 0, 3);
  std::size_t rows = 0;
  std::vector<double> xy = read_matrix(r, "/points/xy", 2, rows, "P");
  if (rows != n)
    r.fail("dataset /points/xy has " + std::to_string(rows) + " rows, expected " +
           std::to_string(n) + ", one per point");
  for (std::size_t i = 0; i < n; ++i)
    points.push_back({names[i], static_cast<PointKind>(kinds[i]), Vec2(xy[2 * i], xy[2 * i + 1])});
  return points;
}

std::vector<Layer> read_layers(const h5::Reader& r) {
  std::vector<Layer> layers;
  if (!r.exists("/layers")) return layers;
  h5::Array<double> bottom = r.f64("/layers/bottom");
  if (bottom.dims.size() != 1)
    r.fail("dataset /layers/bottom has shape " + shape_text(bottom.dims) + ", expected (N,)");
  const std::size_t n = bottom.data.size();
  std::vector<double> top = read_vector(r, "/layers/top", n, "layer");
  std::vector<double> target = read_vector(r, "/layers/target_fsi", n, "layer");
  std::vector<double> realised = read_vector(r, "/layers/realised_fsi", n, "layer");
  check_finite(r, "/layers/bottom", bottom.data);
  check_finite(r, "/layers/top", top);
  for (std::size_t i = 0; i < n; ++i) {
    if (top[i] < bottom.data[i])
      r.fail("layer " + std::to_string(i) + " has top " + std::to_string(top[i]) +
             " below its bottom " + std::to_string(bottom.data[i]) + " (/layers)");
    layers.push_back({bottom.data[i], top[i], target[i], realised[i]});
  }
  return layers;
}

constexpr long long kIntMax = std::numeric_limits<int>::max();

}  // namespace

// ==================================================================== lines

void write_lines_h5(const std::string& path, const LineModel& model) {
  AtomicOutput out(path);
  {
    h5::Writer w(path, out.temp_path());
    write_root_attributes(w, kLinesFormat, kUnits, model.provenance);
    w.attr_f64(w.file(), "bedding_dip_deg", model.bedding_dip_deg);
    io::write_origin(w, w.file(), model.origin);
    {
      h5::Id g = w.group("domain");
      w.f64(g.get(), "vertices", flatten(model.domain), {model.domain.size(), 2}, "m",
            "domain boundary, counter-clockwise, not closed; zero rows if there is no domain");
    }
    {
      h5::Id g = w.group("excavations");
      std::vector<double> xy;
      std::vector<std::int64_t> offsets{0};
      for (const Polygon2& e : model.excavations) {
        const std::vector<double> f = flatten(e);
        xy.insert(xy.end(), f.begin(), f.end());
        offsets.push_back(static_cast<std::int64_t>(xy.size() / 2));
      }
      w.f64(g.get(), "vertices", xy, {xy.size() / 2, 2}, "m",
            "vertices of all excavation outlines, counter-clockwise, one after another");
      w.i64(g.get(), "offsets", offsets, "",
            "excavation i is vertices[offsets[i]:offsets[i+1]]; E+1 entries");
    }
    {
      h5::Id g = w.group("lines");
      std::vector<double> ends;
      std::vector<std::int32_t> set, kind, layer;
      ends.reserve(4 * model.lines.size());
      for (const JointLine& l : model.lines) {
        ends.insert(ends.end(), {l.a.x(), l.a.y(), l.b.x(), l.b.y()});
        set.push_back(l.set);
        kind.push_back(static_cast<std::int32_t>(l.kind));
        layer.push_back(l.layer);
      }
      w.f64(g.get(), "endpoints", ends, {model.lines.size(), 4}, "m",
            "line i from (x1, y1) to (x2, y2): columns x1 y1 x2 y2");
      w.i32(g.get(), "set", set, "", std::string("joint set of line i: ") + kSetCodes);
      w.i32(g.get(), "kind", kind, "", std::string("kind of line i: ") + kLineKindCodes);
      w.i32(g.get(), "layer", layer, "", "bed line i was generated in (index into /layers), -1 if none");
    }
    write_sets(w, model.sets);
    write_points(w, model.points, nullptr);
    write_layers(w, model.layers);
    w.close();
  }
  out.commit();
}

LineModel read_lines_h5(const std::string& path) {
  h5::Reader r(path);
  check_format(r, kLinesFormat);
  LineModel m;
  m.provenance = read_provenance(r);
  m.bedding_dip_deg = root_number(r, "bedding_dip_deg");
  m.origin = io::read_origin2(r, r.file());
  m.sets = read_sets(r);
  m.points = read_points(r);
  m.layers = read_layers(r);

  if (r.exists("/domain")) {
    std::size_t n = 0;
    std::vector<double> xy = read_matrix(r, "/domain/vertices", 2, n, "N");
    if (n != 0 && n < 3)
      r.fail("dataset /domain/vertices has " + std::to_string(n) +
             " vertices, a domain needs at least 3 (or none)");
    for (std::size_t i = 0; i < n; ++i) m.domain.emplace_back(xy[2 * i], xy[2 * i + 1]);
  }
  if (r.exists("/excavations")) m.excavations = read_polygons(r, "/excavations");

  std::size_t n = 0;
  std::vector<double> ends = read_matrix(r, "/lines/endpoints", 4, n, "L");
  const long long nsets = static_cast<long long>(m.sets.size());
  const long long nlayers = static_cast<long long>(m.layers.size());
  std::vector<int> set = read_ints(r, "/lines/set", n, "line", kArtificialSet, nsets - 1);
  std::vector<int> kind = read_ints(r, "/lines/kind", n, "line", 0, 1);
  std::vector<int> layer = read_ints(r, "/lines/layer", n, "line", -1, nlayers - 1);
  m.lines.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    JointLine& l = m.lines[i];
    l.a = Vec2(ends[4 * i], ends[4 * i + 1]);
    l.b = Vec2(ends[4 * i + 2], ends[4 * i + 3]);
    l.set = set[i];
    l.kind = static_cast<LineKind>(kind[i]);
    l.layer = layer[i];
  }
  return m;
}

// =================================================================== blocks

void write_blocks_h5(const std::string& path, const BlockModel& model) {
  AtomicOutput out(path);
  {
    h5::Writer w(path, out.temp_path());
    write_root_attributes(w, kBlocksFormat, kUnits, model.provenance);
    w.attr_f64(w.file(), "bedding_dip_deg", model.bedding_dip_deg);
    io::write_origin(w, w.file(), model.origin);
    w.attr_f64(w.file(), "domain_area", model.domain_area);
    w.attr_f64(w.file(), "excavated_area", model.excavated_area);
    {
      h5::Id g = w.group("blocks");
      const std::size_t nb = model.blocks.size();
      std::size_t nv = 0;
      for (const Block& b : model.blocks) {
        if (b.edge_set.size() != b.vertices.size())
          throw InternalError("write_blocks_h5: a block has " + std::to_string(b.vertices.size()) +
                              " vertices but " + std::to_string(b.edge_set.size()) + " edge sets");
        nv += b.vertices.size();
      }
      std::vector<double> xy, area, centroid, moments;
      std::vector<std::int64_t> offsets{0};
      std::vector<std::int32_t> edge_set, layer;
      xy.reserve(2 * nv);
      edge_set.reserve(nv);
      for (const Block& b : model.blocks) {
        for (const Vec2& v : b.vertices) xy.insert(xy.end(), {v.x(), v.y()});
        edge_set.insert(edge_set.end(), b.edge_set.begin(), b.edge_set.end());
        offsets.push_back(static_cast<std::int64_t>(xy.size() / 2));
        area.push_back(b.area);
        centroid.insert(centroid.end(), {b.centroid.x(), b.centroid.y()});
        moments.insert(moments.end(), {b.sxx, b.syy, b.sxy});
        layer.push_back(b.layer);
      }
      w.f64(g.get(), "vertices", xy, {nv, 2}, "m",
            "vertices of all blocks, each block counter-clockwise, one block after another");
      w.i64(g.get(), "offsets", offsets, "",
            "block i is vertices[offsets[i]:offsets[i+1]]; B+1 entries");
      w.i32(g.get(), "edge_set", edge_set, "",
            std::string("per vertex k: set of the edge from vertex k to the next vertex of its "
                        "block: ") + kSetCodes);
      w.f64(g.get(), "area", area, {nb}, "m^2", "area of block i");
      w.f64(g.get(), "centroid", centroid, {nb, 2}, "m", "centroid x, y of block i");
      w.f64(g.get(), "second_moments", moments, {nb, 3}, "m^4",
            "second moments of area of block i about its centroid: columns sxx syy sxy "
            "(integrals of (x-x0)^2, (y-y0)^2, (x-x0)(y-y0) over the block)");
      w.i32(g.get(), "layer", layer, "", "bed containing the centroid of block i, -1 if not layered");
    }
    write_sets(w, model.sets);
    std::vector<ModelPoint> points;
    std::vector<int> where;
    for (const LocatedPoint& p : model.points) {
      points.push_back(p.point);
      where.push_back(p.block);
    }
    write_points(w, points, &where);
    write_layers(w, model.layers);
    w.close();
  }
  out.commit();
}

BlockModel read_blocks_h5(const std::string& path) {
  h5::Reader r(path);
  check_format(r, kBlocksFormat);
  BlockModel m;
  m.provenance = read_provenance(r);
  m.bedding_dip_deg = root_number(r, "bedding_dip_deg");
  m.origin = io::read_origin2(r, r.file());
  m.domain_area = root_number(r, "domain_area");
  m.excavated_area = root_number(r, "excavated_area");
  m.sets = read_sets(r);
  m.layers = read_layers(r);

  std::vector<Polygon2> polys = read_polygons(r, "/blocks");
  const std::size_t nb = polys.size();
  std::size_t nv = 0;
  for (const Polygon2& p : polys) nv += p.size();
  const long long nsets = static_cast<long long>(m.sets.size());
  std::vector<int> edge_set = read_ints(r, "/blocks/edge_set", nv, "vertex", kArtificialSet, nsets - 1);
  std::vector<double> area = read_vector(r, "/blocks/area", nb, "block");
  std::size_t rows = 0;
  std::vector<double> centroid = read_matrix(r, "/blocks/centroid", 2, rows, "B");
  if (rows != nb)
    r.fail("dataset /blocks/centroid has " + std::to_string(rows) + " rows, expected " +
           std::to_string(nb) + ", one per block");
  std::vector<double> moments = read_matrix(r, "/blocks/second_moments", 3, rows, "B");
  if (rows != nb)
    r.fail("dataset /blocks/second_moments has " + std::to_string(rows) + " rows, expected " +
           std::to_string(nb) + ", one per block");
  std::vector<int> layer =
      read_ints(r, "/blocks/layer", nb, "block", -1, static_cast<long long>(m.layers.size()) - 1);

  m.blocks.resize(nb);
  std::size_t k = 0;
  for (std::size_t i = 0; i < nb; ++i) {
    Block& b = m.blocks[i];
    b.vertices = std::move(polys[i]);
    b.edge_set.assign(edge_set.begin() + static_cast<std::ptrdiff_t>(k),
                      edge_set.begin() + static_cast<std::ptrdiff_t>(k + b.vertices.size()));
    k += b.vertices.size();
    b.area = area[i];
    b.centroid = Vec2(centroid[2 * i], centroid[2 * i + 1]);
    b.sxx = moments[3 * i];
    b.syy = moments[3 * i + 1];
    b.sxy = moments[3 * i + 2];
    b.layer = layer[i];
  }

  std::vector<ModelPoint> points = read_points(r);
  if (!points.empty() || r.exists("/points/block")) {
    std::vector<int> where = read_ints(r, "/points/block", points.size(), "point", -1,
                                       std::min<long long>(static_cast<long long>(nb) - 1, kIntMax));
    for (std::size_t i = 0; i < points.size(); ++i) m.points.push_back({points[i], where[i]});
  }
  return m;
}

// =================================================================== format

std::string h5_format_of(const std::string& path) {
  h5::silence_errors();
  // Missing, unreadable and damaged files are errors; a readable file that
  // is not HDF5, or HDF5 without our `format` attribute, is "not ours".
  std::unique_ptr<h5::Reader> r;
  try {
    r = std::make_unique<h5::Reader>(path);
  } catch (const InputError& e) {
    if (H5Fis_hdf5(path.c_str()) == 0) return "";
    throw;
  }
  try {
    return r->attr_text(r->file(), "format", "the file").value_or("");
  } catch (const h5::DamagedFile&) {
    throw;  // damage is not "another program's file"
  } catch (const InputError&) {
    return "";
  }
}

}  // namespace dda
