// Shared pieces of the 2D and 3D results files (results_h5_util.hpp).
#include "io/results_h5_util.hpp"

#include "dda/common/error.hpp"

namespace dda::df::h5io {

std::vector<double> flat(const std::vector<Vec2>& v) {
  std::vector<double> out;
  out.reserve(2 * v.size());
  for (const Vec2& p : v) out.insert(out.end(), {p.x(), p.y()});
  return out;
}

std::vector<double> flat(const std::vector<Vec3>& v) {
  std::vector<double> out;
  out.reserve(3 * v.size());
  for (const Vec3& p : v) out.insert(out.end(), {p.x(), p.y(), p.z()});
  return out;
}

h5::Id subgroup(hid_t parent, const std::string& name) {
  h5::Id g(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (!g.valid()) throw InputError("cannot create HDF5 group " + name + ".");
  return g;
}

void write_root(h5::Writer& w, const char* format, const char* units, const ResultsSource& source,
                const OutputSchedule& output, bool complete, double time, int steps) {
  const hid_t root = w.file();
  const Provenance& p = source.provenance;
  w.attr_text(root, "format", format);
  w.attr_i32(root, "format_version", kResultsFormatVersion);
  w.attr_text(root, "units", units);
  w.attr_text(root, "program_version", p.program_version.empty() ? std::string(version_string()) : p.program_version);
  w.attr_text(root, "scenario_path", p.scenario_path);
  w.attr_text(root, "scenario", p.scenario_text);
  w.attr_u64(root, "seed", p.seed);
  w.attr_text(root, "created_utc", utc_now());
  w.attr_text(root, "input_kind", source.input_kind);
  w.attr_text(root, "blocks_path", source.blocks_path);
  w.attr_f64(root, "output_interval", output.interval);
  w.attr_i32(root, "output_every", output.every);
  w.attr_i32(root, "complete", complete ? 1 : 0);
  w.attr_f64(root, "time", time);
  w.attr_i32(root, "steps", steps);
}

RootInfo read_root(const h5::Reader& r, const char* format) {
  const hid_t root = r.file();
  const auto found = r.attr_text(root, "format", "the file");
  if (!found) r.fail(std::string("has no format attribute, so it was not written by dda (expected a ") + format + " file)");
  if (*found != format) r.fail("is a " + *found + " file, expected a " + format + " file");
  const auto version = r.attr_int(root, "format_version", "the file");
  if (!version || *version > kResultsFormatVersion)
    r.fail("has results format version " + (version ? std::to_string(*version) : std::string("(none)")) +
           "; this dda reads version " + std::to_string(kResultsFormatVersion));
  RootInfo out;
  Provenance& p = out.source.provenance;
  p.program_version = r.attr_text(root, "program_version", "the file").value_or("");
  p.scenario_path = r.attr_text(root, "scenario_path", "the file").value_or("");
  p.scenario_text = r.attr_text(root, "scenario", "the file").value_or("");
  p.seed = r.attr_u64(root, "seed", "the file").value_or(0);
  p.created_utc = r.attr_text(root, "created_utc", "the file").value_or("");
  out.source.input_kind = r.attr_text(root, "input_kind", "the file").value_or("scenario");
  out.source.blocks_path = r.attr_text(root, "blocks_path", "the file").value_or("");
  out.output.interval = r.attr_f64(root, "output_interval", "the file").value_or(0);
  out.output.every = static_cast<int>(r.attr_int(root, "output_every", "the file").value_or(0));
  out.complete = r.attr_int(root, "complete", "the file").value_or(0) != 0;
  return out;
}

std::vector<double> read_f64(const h5::Reader& r, const std::string& name, const std::vector<hsize_t>& dims) {
  h5::Array<double> a = r.f64(name);
  if (a.dims != dims) {
    std::string want = "(";
    for (std::size_t i = 0; i < dims.size(); ++i) want += (i ? ", " : "") + std::to_string(dims[i]);
    r.fail("dataset " + name + " has an unexpected shape, expected " + want + (dims.size() == 1 ? ",)" : ")"));
  }
  return std::move(a.data);
}

std::vector<std::int64_t> read_i64(const h5::Reader& r, const std::string& name, std::size_t n) {
  h5::Array<std::int64_t> a = r.i64(name);
  if (a.dims != std::vector<hsize_t>{n})
    r.fail("dataset " + name + " has an unexpected shape, expected (" + std::to_string(n) + ",)");
  return std::move(a.data);
}

std::size_t length(const h5::Reader& r, const std::string& name) {
  const h5::Array<double> a = r.f64(name);
  if (a.dims.empty()) r.fail("dataset " + name + " must be an array");
  return a.dims[0];
}

std::size_t rows_of(const h5::Reader& r, const std::string& name) {
  const h5::Array<double> a = r.f64(name);
  return a.dims.empty() ? 0 : a.dims[0];
}

void write_warm_start(h5::Writer& w, hid_t checkpoint, const LinearSolver::WarmStart& start) {
  h5::Id sg = subgroup(checkpoint, "solver");
  const Eigen::VectorXd& x = start.x;
  w.f64(sg.get(), "warm_start", std::vector<double>(x.data(), x.data() + x.size()), {static_cast<hsize_t>(x.size())},
        "m, rad, 1", "last solution of an iterative solver (its next start vector); empty for direct solvers");
  w.attr_f64(sg.get(), "warm_start_dt", start.dt);
}

LinearSolver::WarmStart read_warm_start(const h5::Reader& r, const std::string& checkpoint) {
  LinearSolver::WarmStart start;
  const std::string group = checkpoint + "/solver";
  if (!r.exists(group)) return start;
  const h5::Array<double> x = r.f64(group + "/warm_start");
  if (x.dims.size() != 1) r.fail("dataset " + group + "/warm_start must be one-dimensional");
  start.x = Eigen::Map<const Eigen::VectorXd>(x.data.data(), static_cast<Eigen::Index>(x.data.size()));
  h5::Id g(H5Gopen2(r.file(), group.c_str(), H5P_DEFAULT), H5Gclose);
  start.dt = r.attr_f64(g.get(), "warm_start_dt", group).value_or(0);
  return start;
}

void write_points(h5::Writer& w, const std::vector<std::string>& names, const std::vector<std::int32_t>& blocks,
                  const std::vector<double>& initial, hsize_t dim) {
  h5::Id g = w.group("points");
  w.strings(g.get(), "name", names, "", "measurement point names, in the order of the /series columns");
  w.i32(g.get(), "block", blocks, "", "block each point rides with");
  w.f64(g.get(), "initial", initial, {names.size(), dim}, "m", "position at the start of the run");
}

void write_energy(h5::Writer& w, const std::vector<EnergyRecord>& log, const std::string& unit) {
  h5::Id g = w.group("energy");
  w.attr_text(g.get(), "description",
              "energy ledger (" + unit + "): record 0 is the start of the run, then one per step; "
              "stored energies at the end of the step, work and losses cumulative (see df/core/energy.hpp)");
  const std::vector<hsize_t> n{log.size()};
  auto col = [&](const char* name, auto get, const char* what) {
    std::vector<double> v;
    v.reserve(log.size());
    for (const EnergyRecord& e : log) v.push_back(get(e));
    w.f64(g.get(), name, v, n, std::string(name) == "time" ? "s" : "J", what);
  };
  col("time", [](const EnergyRecord& e) { return e.time; }, "time of the record");
  col("kinetic", [](const EnergyRecord& e) { return e.kinetic; }, "kinetic energy of the start velocities of the next step");
  col("elastic", [](const EnergyRecord& e) { return e.elastic; }, "block strain energy");
  col("contact", [](const EnergyRecord& e) { return e.contact; }, "energy in the contact penalty springs");
  col("fixed", [](const EnergyRecord& e) { return e.fixed; }, "energy in the fixed-point springs");
  col("bolts", [](const EnergyRecord& e) { return e.bolts; }, "energy in the bolts");
  col("gravity_work", [](const EnergyRecord& e) { return e.gravity_work; }, "work of gravity, cumulative");
  col("load_work", [](const EnergyRecord& e) { return e.load_work; },
      "work of point loads and moving fixed points, cumulative");
  col("friction", [](const EnergyRecord& e) { return e.friction; }, "friction dissipation, cumulative");
  col("damping", [](const EnergyRecord& e) { return e.damping; }, "kinetic energy removed by dynamic < 1 and work of the viscous damping (control.damping), cumulative");
  col("breakage", [](const EnergyRecord& e) { return e.breakage; }, "energy released by broken bolts (and in 3D joint bonds), cumulative");
  col("radiation", [](const EnergyRecord& e) { return e.radiation; },
      "energy absorbed by the viscous boundaries, cumulative");
  col("residual", [](const EnergyRecord& e) { return e.residual; },
      "input - change of stored - friction - damping - breakage - radiation: what the integrator and penalties "
      "dissipate");
}

std::vector<EnergyRecord> read_energy(const h5::Reader& r) {
  const std::size_t n = length(r, "/energy/time");
  auto col = [&](const char* name) { return read_f64(r, std::string("/energy/") + name, {n}); };
  const auto time = col("time"), kinetic = col("kinetic"), elastic = col("elastic"), contact = col("contact"),
             fixed = col("fixed"), bolts = col("bolts"), gravity = col("gravity_work"), load = col("load_work"),
             friction = col("friction"), damping = col("damping"), breakage = col("breakage"),
             residual = col("residual");
  const auto radiation = r.exists("/energy/radiation") ? col("radiation") : std::vector<double>(n, 0.0);
  std::vector<EnergyRecord> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    EnergyRecord& e = out[i];
    e.time = time[i];
    e.kinetic = kinetic[i];
    e.elastic = elastic[i];
    e.contact = contact[i];
    e.fixed = fixed[i];
    e.bolts = bolts[i];
    e.gravity_work = gravity[i];
    e.load_work = load[i];
    e.friction = friction[i];
    e.damping = damping[i];
    e.breakage = breakage[i];
    e.radiation = radiation[i];
    e.residual = residual[i];
  }
  return out;
}

}  // namespace dda::df::h5io
