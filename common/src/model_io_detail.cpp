// Shared pieces of the 3D HDF5 files; see model_io_detail.hpp.
#include "model_io_detail.hpp"

#include <cmath>
#include <ctime>

#include "dda/common/error.hpp"

namespace dda {

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

}  // namespace dda

namespace dda::io {
namespace {

std::string per(std::size_t n, const std::string& what) {
  return std::to_string(n) + ",), one value per " + what;
}

}  // namespace

std::string shape_text(const std::vector<hsize_t>& dims) {
  std::string s = "(";
  for (std::size_t i = 0; i < dims.size(); ++i) s += (i ? ", " : "") + std::to_string(dims[i]);
  return s + (dims.size() == 1 ? ",)" : ")");
}

void check_finite(const h5::Reader& r, const std::string& ds, const std::vector<double>& v) {
  for (double x : v)
    if (!std::isfinite(x)) r.fail("dataset " + ds + " holds a value that is not a finite number");
}

// ------------------------------------------------------------------ writing

void write_root_attributes(h5::Writer& w, const char* format, const char* units, const Provenance& p, hid_t root) {
  if (root < 0) root = w.file();
  w.attr_text(root, "format", format);
  w.attr_i32(root, "format_version", kFormatVersion);
  w.attr_text(root, "units", units);
  w.attr_text(root, "program_version",
              p.program_version.empty() ? std::string(version_string()) : p.program_version);
  w.attr_text(root, "scenario_path", p.scenario_path);
  w.attr_text(root, "scenario", p.scenario_text);
  w.attr_u64(root, "seed", p.seed);
  w.attr_text(root, "created_utc", p.created_utc.empty() ? utc_now() : p.created_utc);
}

std::vector<double> flatten(const std::vector<Vec3>& v) {
  std::vector<double> xyz;
  xyz.reserve(3 * v.size());
  for (const Vec3& p : v) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  return xyz;
}

void write_domain(h5::Writer& w, const Box3& box, const std::string& at) {
  h5::Id g = w.group(at + "domain");
  w.f64(g.get(), "box", flatten({box.lo, box.hi}), {2, 3}, "m",
        "domain box: row 0 the lower corner x, y, z, row 1 the upper corner");
}

void write_sets(h5::Writer& w, const std::vector<JointSetInfo>& sets, const std::string& at) {
  h5::Id g = w.group(at + "sets");
  std::vector<std::string> names, origins;
  for (const JointSetInfo& s : sets) {
    names.push_back(s.name);
    origins.push_back(s.origin);
  }
  w.strings(g.get(), "name", names, "", "name of joint set i (UTF-8); index = set id");
  w.strings(g.get(), "origin", origins, "",
            "how set i was made: statistical, layered, user, csv, geo or bedding");
}

void write_points(h5::Writer& w, const std::vector<ModelPoint3>& points, const std::string& at) {
  h5::Id g = w.group(at + "points");
  std::vector<std::string> names;
  std::vector<std::int32_t> kinds;
  std::vector<Vec3> xyz;
  for (const ModelPoint3& p : points) {
    names.push_back(p.name);
    kinds.push_back(static_cast<std::int32_t>(p.kind));
    xyz.push_back(p.p);
  }
  w.strings(g.get(), "name", names, "", "name of point i (UTF-8)");
  w.i32(g.get(), "kind", kinds, "", "kind of point i: 0 fixed, 1 load, 2 measurement, 3 hole");
  w.f64(g.get(), "xyz", flatten(xyz), {points.size(), 3}, "m", "coordinates x, y, z of point i");
}

h5::Id write_layer_table(h5::Writer& w, const std::vector<Layer>& layers, const std::string& coordinate,
                         const std::string& generated, const std::string& at) {
  h5::Id g = w.group(at + "layers");
  std::vector<double> bottom, top, target, realised;
  for (const Layer& l : layers) {
    bottom.push_back(l.bottom);
    top.push_back(l.top);
    target.push_back(l.target_fsi);
    realised.push_back(l.realised_fsi);
  }
  const hsize_t n = layers.size();
  const std::string coord = " of bed i" + coordinate;
  w.f64(g.get(), "bottom", bottom, {n}, "m", "lower boundary" + coord);
  w.f64(g.get(), "top", top, {n}, "m", "upper boundary" + coord);
  w.f64(g.get(), "target_fsi", target, {n}, "1",
        "fracture spacing index asked for (bed thickness / median joint spacing), 0 if none");
  w.f64(g.get(), "realised_fsi", realised, {n}, "1", "fracture spacing index of the " + generated + " generated in bed i");
  return g;
}

void write_layers(h5::Writer& w, const std::vector<Layer>& layers, const Vec3& bed_normal, const std::string& at) {
  h5::Id g = write_layer_table(w, layers, ", as the coordinate along the bed normal (normal . x)", "fractures", at);
  w.f64(g.get(), "normal", flatten({bed_normal}), {3}, "1",
        "normal of the beds x, y, z (written even when there are no beds)");
}

// ------------------------------------------------------------------ reading

void check_format(const h5::Reader& r, const std::string& expected) {
  const auto format = r.attr_text(r.file(), "format", "the file");
  if (!format)
    r.fail("is an HDF5 file but not one written by dda (no format attribute), expected a " +
           expected + " file");
  if (*format != expected) r.fail("is a " + *format + " file, expected a " + expected + " file");
  const auto version = r.attr_int(r.file(), "format_version", "the file");
  if (!version) r.fail("has no format_version attribute");
  if (*version < 1 || *version > kFormatVersion)
    r.fail("has format_version " + std::to_string(*version) + ", this dda reads version " +
           std::to_string(kFormatVersion) + " (a newer dda wrote it?)");
}

Provenance read_provenance(const h5::Reader& r, hid_t f) {
  Provenance p;
  if (f < 0) f = r.file();
  p.program_version = r.attr_text(f, "program_version", "the file").value_or("");
  p.scenario_path = r.attr_text(f, "scenario_path", "the file").value_or("");
  p.scenario_text = r.attr_text(f, "scenario", "the file").value_or("");
  p.seed = r.attr_u64(f, "seed", "the file").value_or(0);
  p.created_utc = r.attr_text(f, "created_utc", "the file").value_or("");
  return p;
}

double root_number(const h5::Reader& r, const char* name) {
  const double v = r.attr_f64(r.file(), name, "the file").value_or(0.0);
  if (!std::isfinite(v)) r.fail(std::string("attribute ") + name + " is not a finite number");
  return v;
}

std::vector<double> read_table(const h5::Reader& r, const std::string& ds, std::size_t cols,
                               std::size_t& rows) {
  h5::Array<double> a = r.f64(ds);
  if (a.dims.size() != 2 || a.dims[1] != cols)
    r.fail("dataset " + ds + " has shape " + shape_text(a.dims) + ", expected (N, " +
           std::to_string(cols) + ")");
  rows = a.dims[0];
  check_finite(r, ds, a.data);
  return std::move(a.data);
}

std::vector<double> read_rows(const h5::Reader& r, const std::string& ds, std::size_t n,
                              std::size_t cols, const std::string& what) {
  h5::Array<double> a = r.f64(ds);
  if (a.dims.size() != 2 || a.dims[0] != n || a.dims[1] != cols)
    r.fail("dataset " + ds + " has shape " + shape_text(a.dims) + ", expected (" +
           std::to_string(n) + ", " + std::to_string(cols) + "), one row per " + what);
  check_finite(r, ds, a.data);
  return std::move(a.data);
}

std::vector<double> read_vector(const h5::Reader& r, const std::string& ds, std::size_t n,
                                const std::string& what) {
  h5::Array<double> a = r.f64(ds);
  if (a.dims.size() != 1 || a.dims[0] != n)
    r.fail("dataset " + ds + " has shape " + shape_text(a.dims) + ", expected (" + per(n, what));
  check_finite(r, ds, a.data);
  return std::move(a.data);
}

std::vector<double> read_fixed(const h5::Reader& r, const std::string& ds,
                               const std::vector<hsize_t>& dims) {
  h5::Array<double> a = r.f64(ds);
  if (a.dims != dims)
    r.fail("dataset " + ds + " has shape " + shape_text(a.dims) + ", expected " +
           shape_text(dims));
  check_finite(r, ds, a.data);
  return std::move(a.data);
}

namespace {

std::vector<int> ints_in_range(const h5::Reader& r, const std::string& ds,
                               const std::vector<std::int64_t>& v, long long lo, long long hi) {
  std::vector<int> out;
  out.reserve(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (v[i] < lo || v[i] > hi)
      r.fail("dataset " + ds + " entry " + std::to_string(i) + " is " + std::to_string(v[i]) +
             ", must be between " + std::to_string(lo) + " and " + std::to_string(hi));
    out.push_back(static_cast<int>(v[i]));
  }
  return out;
}

}  // namespace

std::vector<int> read_ints(const h5::Reader& r, const std::string& ds, std::size_t n,
                           const std::string& what, long long lo, long long hi) {
  h5::Array<std::int64_t> a = r.i64(ds);
  if (a.dims.size() != 1 || a.dims[0] != n)
    r.fail("dataset " + ds + " has shape " + shape_text(a.dims) + ", expected (" + per(n, what));
  return ints_in_range(r, ds, a.data, lo, hi);
}

std::vector<int> read_int_list(const h5::Reader& r, const std::string& ds, long long lo,
                               long long hi) {
  h5::Array<std::int64_t> a = r.i64(ds);
  if (a.dims.size() != 1)
    r.fail("dataset " + ds + " has shape " + shape_text(a.dims) + ", expected (N,)");
  return ints_in_range(r, ds, a.data, lo, hi);
}

std::vector<std::string> read_strings(const h5::Reader& r, const std::string& ds, std::size_t n,
                                      const std::string& what) {
  std::vector<std::string> s = r.strings(ds);
  if (s.size() != n)
    r.fail("dataset " + ds + " has " + std::to_string(s.size()) + " entries, expected " +
           std::to_string(n) + ", one per " + what);
  return s;
}

std::vector<std::int64_t> read_offsets(const h5::Reader& r, const std::string& ds,
                                       std::size_t total, long long min_step,
                                       const std::string& item) {
  return r.offsets(ds, total, min_step, item);
}

Box3 read_domain(const h5::Reader& r, const std::string& at) {
  Box3 box;
  if (!r.exists("/" + at + "domain")) return box;
  const std::vector<double> v = read_fixed(r, "/" + at + "domain/box", {2, 3});
  box.lo = row3(v, 0);
  box.hi = row3(v, 1);
  // A zero box (nothing set) is allowed; an inside-out one is not.
  if ((box.hi.array() < box.lo.array()).any())
    r.fail("dataset /" + at + "domain/box has an upper corner below its lower corner");
  return box;
}

std::vector<JointSetInfo> read_sets(const h5::Reader& r, const std::string& at) {
  std::vector<JointSetInfo> sets;
  const std::string g = "/" + at + "sets";
  if (!r.exists(g)) return sets;
  std::vector<std::string> names = r.strings(g + "/name");
  std::vector<std::string> origins = read_strings(r, g + "/origin", names.size(), "set");
  for (std::size_t i = 0; i < names.size(); ++i) sets.push_back({names[i], origins[i]});
  return sets;
}

std::vector<ModelPoint3> read_points(const h5::Reader& r, const std::string& at) {
  std::vector<ModelPoint3> points;
  const std::string g = "/" + at + "points";
  if (!r.exists(g)) return points;
  std::vector<std::string> names = r.strings(g + "/name");
  const std::size_t n = names.size();
  std::vector<int> kinds = read_ints(r, g + "/kind", n, "point", 0, 3);
  std::vector<double> xyz = read_rows(r, g + "/xyz", n, 3, "point");
  for (std::size_t i = 0; i < n; ++i)
    points.push_back({names[i], static_cast<PointKind>(kinds[i]), row3(xyz, i)});
  return points;
}

std::vector<Layer> read_layers(const h5::Reader& r, Vec3& bed_normal, const std::string& at) {
  const std::string g = "/" + at + "layers";
  std::vector<Layer> layers;
  bed_normal = Vec3(0, 0, 1);
  if (!r.exists(g)) return layers;
  h5::Array<double> bottom = r.f64(g + "/bottom");
  if (bottom.dims.size() != 1)
    r.fail("dataset " + g + "/bottom has shape " + shape_text(bottom.dims) + ", expected (N,)");
  check_finite(r, g + "/bottom", bottom.data);
  const std::size_t n = bottom.data.size();
  std::vector<double> top = read_vector(r, g + "/top", n, "layer");
  std::vector<double> target = read_vector(r, g + "/target_fsi", n, "layer");
  std::vector<double> realised = read_vector(r, g + "/realised_fsi", n, "layer");
  for (std::size_t i = 0; i < n; ++i) {
    if (top[i] < bottom.data[i])
      r.fail("layer " + std::to_string(i) + " has top " + std::to_string(top[i]) +
             " below its bottom " + std::to_string(bottom.data[i]) + " (" + g + ")");
    layers.push_back({bottom.data[i], top[i], target[i], realised[i]});
  }
  bed_normal = row3(read_fixed(r, g + "/normal", {3}), 0);
  return layers;
}

}  // namespace dda::io
