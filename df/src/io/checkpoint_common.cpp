// The parts of the 2D and 3D checkpoints that are the same (checkpoint_common.hpp).
#include "io/checkpoint_common.hpp"

#include "io/results_h5_util.hpp"

namespace dda::df::h5io {

void write_checkpoint_clock(h5::Writer& w, hid_t g, double time, double dt, int step_count, bool started) {
  w.attr_f64(g, "time", time);
  w.attr_f64(g, "dt", dt);
  w.attr_i32(g, "step_count", step_count);
  w.attr_i32(g, "started", started ? 1 : 0);
}

CheckpointClock read_checkpoint_clock(const h5::Reader& r, bool with_step_count) {
  if (!r.exists("/checkpoint")) r.fail("has no /checkpoint group, so the run cannot be resumed");
  h5::Id g(H5Gopen2(r.file(), "/checkpoint", H5P_DEFAULT), H5Gclose);
  if (!g.valid()) r.fail("/checkpoint is not a group");
  const auto time = r.attr_f64(g.get(), "time", "/checkpoint");
  const auto dt = r.attr_f64(g.get(), "dt", "/checkpoint");
  CheckpointClock c;
  if (with_step_count) {
    const auto steps = r.attr_int(g.get(), "step_count", "/checkpoint");
    if (!time || !dt || !steps) r.fail("/checkpoint lacks one of its attributes time, dt, step_count");
    c.step_count = static_cast<int>(*steps);
  } else if (!time || !dt) {
    r.fail("/checkpoint lacks one of its attributes time, dt");
  }
  c.time = *time;
  c.dt = *dt;
  // Files written before the attribute existed come from runs that had no
  // initial equilibrium to make: they have started.
  c.started = r.attr_int(g.get(), "started", "/checkpoint").value_or(1) != 0;
  return c;
}

std::vector<double> checkpoint_table(const h5::Reader& r, const std::string& name, std::size_t n, std::size_t cols) {
  const h5::Array<double> a = r.f64(name);
  const bool ok = cols == 1 ? a.dims == std::vector<hsize_t>{n} : a.dims == std::vector<hsize_t>{n, cols};
  if (!ok)
    r.fail("dataset " + name + " must have shape (" + std::to_string(n) +
           (cols == 1 ? ",)" : ", " + std::to_string(cols) + ")") + " for this model");
  return a.data;
}

std::vector<Vec2> read_points2(const h5::Reader& r, const std::string& name, std::size_t n) {
  const std::vector<double> v = checkpoint_table(r, name, n, 2);
  std::vector<Vec2> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = Vec2(v[2 * i], v[2 * i + 1]);
  return out;
}

std::vector<Vec2> read_points2(const h5::Reader& r, const std::string& name) {
  return read_points2(r, name, rows_of(r, name));
}

std::vector<Vec3> read_points3(const h5::Reader& r, const std::string& name) {
  const std::size_t n = rows_of(r, name);
  const std::vector<double> v = checkpoint_table(r, name, n, 3);
  std::vector<Vec3> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) out.emplace_back(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
  return out;
}

std::vector<std::vector<double>> read_ragged(const h5::Reader& r, const std::string& dir,
                                             const std::vector<std::int64_t>& counts, const std::string& count_name,
                                             const std::string& values_name, std::int64_t min_count) {
  const std::vector<double> all = r.f64(dir + values_name).data;
  std::vector<std::vector<double>> out(counts.size());
  std::size_t pos = 0;
  for (std::size_t k = 0; k < counts.size(); ++k) {
    if (counts[k] < min_count || pos + static_cast<std::size_t>(counts[k]) > all.size())
      r.fail("dataset " + dir + values_name + " holds fewer values than " + count_name + " asks for");
    out[k].assign(all.begin() + static_cast<long>(pos), all.begin() + static_cast<long>(pos + counts[k]));
    pos += static_cast<std::size_t>(counts[k]);
  }
  if (pos != all.size()) r.fail("dataset " + dir + values_name + " holds more values than " + count_name);
  return out;
}

}  // namespace dda::df::h5io
