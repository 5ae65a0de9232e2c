#pragma once
// What the 2D and the 3D results files (results_h5.cpp, results3d_h5.cpp)
// and their checkpoints share: the root attributes (format, provenance,
// schedule, how far the run got) and strict readers of datasets of a known
// shape. Private to DF; layouts in docs/formats.md.
#include <cstdint>
#include <string>
#include <vector>

#include "dda/common/geometry.hpp"
#include "dda/common/geometry3d.hpp"
#include "dda/common/h5_util.hpp"
#include "dda/df/core/energy.hpp"
#include "dda/df/core/linear_solver.hpp"
#include "dda/df/io/results.hpp"

namespace dda::df::h5io {

constexpr int kResultsFormatVersion = 1;

// Rows of x y (z), for an (n, 2) or (n, 3) dataset.
std::vector<double> flat(const std::vector<Vec2>& v);
std::vector<double> flat(const std::vector<Vec3>& v);

// /points: name, block and initial position ((n, dim) flat rows) of every
// measurement point, in the order of the /series columns.
void write_points(h5::Writer& w, const std::vector<std::string>& names, const std::vector<std::int32_t>& blocks,
                  const std::vector<double>& initial, hsize_t dim);

// The times of the /series samples: those of the first point's history, or
// with no points the start and the end of every step of the log.
template <class Histories, class Log>
std::vector<double> series_times(const Histories& histories, const Log& log, double now) {
  std::vector<double> time;
  if (!histories.empty()) {
    for (const auto& m : histories[0]) time.push_back(m.time);
  } else {
    time.push_back(log.empty() ? now : log.front().time - log.front().dt);
    for (const auto& s : log) time.push_back(s.time);
  }
  return time;
}

// The step-log columns both dimensions have (step, time, dt, iterations,
// dt_cuts, converged, open, sliding, locked, max_displacement) into group g;
// `iterations` reads the open-close count of a record.
template <class Record, class Iterations>
void write_step_columns(h5::Writer& w, hid_t g, const std::vector<Record>& log, Iterations iterations) {
  auto ints = [&log](auto get) {
    std::vector<std::int32_t> v;
    v.reserve(log.size());
    for (const Record& r : log) v.push_back(static_cast<std::int32_t>(get(r)));
    return v;
  };
  auto reals = [&log](auto get) {
    std::vector<double> v;
    v.reserve(log.size());
    for (const Record& r : log) v.push_back(get(r));
    return v;
  };
  const std::vector<hsize_t> n{log.size()};
  w.i32(g, "step", ints([](const Record& r) { return r.step; }), "", "step number (1, 2, ...)");
  w.f64(g, "time", reals([](const Record& r) { return r.time; }), n, "s", "time at the end of the step");
  w.f64(g, "dt", reals([](const Record& r) { return r.dt; }), n, "s", "time step taken");
  w.i32(g, "iterations", ints(iterations), "", "open-close iterations of the accepted attempt");
  w.i32(g, "dt_cuts", ints([](const Record& r) { return r.dt_cuts; }), "", "attempts redone with a smaller dt");
  w.i32(g, "converged", ints([](const Record& r) { return r.converged ? 1 : 0; }), "",
        "0: accepted at the smallest dt without the contact states settling");
  w.i32(g, "open", ints([](const Record& r) { return r.open; }), "", "open contacts");
  w.i32(g, "sliding", ints([](const Record& r) { return r.sliding; }), "", "sliding contacts");
  w.i32(g, "locked", ints([](const Record& r) { return r.locked; }), "", "locked contacts");
  w.f64(g, "max_displacement", reals([](const Record& r) { return r.max_displacement; }), n, "m",
        "largest vertex displacement of the step");
}

// /energy: the energy ledger, one column per EnergyRecord field (energy.hpp);
// `unit` is how its energies are counted ("J per unit thickness" in 2D).
void write_energy(h5::Writer& w, const std::vector<EnergyRecord>& log, const std::string& unit);
// The inverse (a file without /energy/radiation, written before viscous
// boundaries existed, reads zero radiation).
std::vector<EnergyRecord> read_energy(const h5::Reader& r);

// <checkpoint>/solver: an iterative solver's warm start (its last solution
// and the step it was for; empty for direct solvers), which a resumed run
// needs to reproduce the uninterrupted one bit for bit.
void write_warm_start(h5::Writer& w, hid_t checkpoint, const LinearSolver::WarmStart& start);
// The inverse; an empty start if the checkpoint has no solver group (files
// written before the 3D solver had PCG).
LinearSolver::WarmStart read_warm_start(const h5::Reader& r, const std::string& checkpoint);

// A group below `parent`.
h5::Id subgroup(hid_t parent, const std::string& name);

// format, format_version, units, provenance (program version and time
// filled in), input_kind, blocks_path, output_interval, output_every,
// complete, time, steps.
void write_root(h5::Writer& w, const char* format, const char* units, const ResultsSource& source,
                const OutputSchedule& output, bool complete, double time, int steps);

struct RootInfo {
  ResultsSource source;
  OutputSchedule output;
  bool complete = false;
};
// Checks `format` and its version, and reads the rest of write_root's attributes.
RootInfo read_root(const h5::Reader& r, const char* format);

// A float64 dataset of exactly this shape.
std::vector<double> read_f64(const h5::Reader& r, const std::string& name, const std::vector<hsize_t>& dims);
// An integer dataset of exactly n values.
std::vector<std::int64_t> read_i64(const h5::Reader& r, const std::string& name, std::size_t n);
// The first dimension of a dataset (an error for a scalar).
std::size_t length(const h5::Reader& r, const std::string& name);
// The first dimension of a dataset, 0 for a scalar.
std::size_t rows_of(const h5::Reader& r, const std::string& name);

// /frames of a results file into `frames` (Frame or Frame3): `blocks` gives
// the vertex count of every frame; the vertex, velocity and stress types of
// the frame give the row widths (2 or 3; 6 or 12; 3 or 6).
template <class Frame, class Blocks>
void read_frame_series(const h5::Reader& r, const Blocks& blocks, std::vector<Frame>& frames) {
  using Vertex = typename decltype(Frame::vertices)::value_type;
  using Velocity = typename decltype(Frame::velocity)::value_type;
  using Stress = typename decltype(Frame::stress)::value_type;
  constexpr hsize_t dim = Vertex::RowsAtCompileTime, nvel = Velocity::RowsAtCompileTime,
                    nstress = Stress::RowsAtCompileTime;
  std::size_t nv = 0;
  for (const auto& b : blocks) nv += b.vertices.size();
  const std::size_t nb = blocks.size();
  const std::size_t nf = length(r, "/frames/time");
  const auto step = read_i64(r, "/frames/step", nf);
  const auto time = read_f64(r, "/frames/time", {nf});
  const auto verts = read_f64(r, "/frames/vertices", {nf, nv, dim});
  const auto vel = read_f64(r, "/frames/velocity", {nf, nb, nvel});
  const auto stress = read_f64(r, "/frames/stress", {nf, nb, nstress});
  frames.resize(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    Frame& fr = frames[f];
    fr.step = static_cast<int>(step[f]);
    fr.time = time[f];
    for (std::size_t v = 0; v < nv; ++v) fr.vertices.push_back(Eigen::Map<const Vertex>(verts.data() + dim * (f * nv + v)));
    for (std::size_t b = 0; b < nb; ++b) {
      fr.velocity.push_back(Eigen::Map<const Velocity>(vel.data() + nvel * (f * nb + b)));
      fr.stress.push_back(Eigen::Map<const Stress>(stress.data() + nstress * (f * nb + b)));
    }
  }
}

// The inverse of write_step_columns: `log` gets one record per row of
// /steps, `set_iterations(record, n)` stores the open-close count.
template <class Record, class SetIterations>
void read_step_columns(const h5::Reader& r, std::vector<Record>& log, SetIterations set_iterations) {
  const std::size_t n = length(r, "/steps/time");
  const auto step = read_i64(r, "/steps/step", n), it = read_i64(r, "/steps/iterations", n),
             cuts = read_i64(r, "/steps/dt_cuts", n), conv = read_i64(r, "/steps/converged", n),
             open = read_i64(r, "/steps/open", n), sliding = read_i64(r, "/steps/sliding", n),
             locked = read_i64(r, "/steps/locked", n);
  const auto time = read_f64(r, "/steps/time", {n}), dt = read_f64(r, "/steps/dt", {n}),
             maxd = read_f64(r, "/steps/max_displacement", {n});
  log.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    Record& s = log[i];
    s.step = static_cast<int>(step[i]);
    s.time = time[i];
    s.dt = dt[i];
    set_iterations(s, static_cast<int>(it[i]));
    s.dt_cuts = static_cast<int>(cuts[i]);
    s.converged = conv[i] != 0;
    s.open = static_cast<int>(open[i]);
    s.sliding = static_cast<int>(sliding[i]);
    s.locked = static_cast<int>(locked[i]);
    s.max_displacement = maxd[i];
  }
}

}  // namespace dda::df::h5io
