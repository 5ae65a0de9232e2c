// The 3D results file (format "dda-results3d"). Layout, dataset by dataset,
// in docs/formats.md; keep the two in step. Root attributes and dataset
// readers are the 2D file's (results_h5_util.hpp), the blocks the 3D blocks
// file's (model_io3d_h5.hpp), the checkpoint is checkpoint3d_h5.cpp.
#include <cstdint>

#include "io/bolts_h5.hpp"
#include "io/checkpoint3d_h5.hpp"
#include "dda/common/atomic_file.hpp"
#include "dda/common/error.hpp"
#include "dda/common/model_io3d_h5.hpp"
#include "dda/common/origin_h5.hpp"
#include "dda/df/io/results3d.hpp"
#include "io/results_h5_util.hpp"

namespace dda::df3 {
namespace {

using df::h5io::flat;
using df::h5io::series_times;
using df::h5io::write_points;
using df::h5io::length;
using df::h5io::read_f64;
using df::h5io::read_i64;

constexpr const char* kUnits =
    "SI: lengths m, volumes m^3, time s, velocity m/s, rotation rad, stress Pa, force N";
constexpr const char* kStressColumns = "sx sy sz tyz tzx txy, tension positive";
constexpr const char* kVelocityColumns =
    "u v w rx ry rz ex ey ez gyz gzx gxy rates at the centroid (m/s, rad/s, 1/s)";

std::vector<double> flat6(const std::vector<Vector6d>& v) {
  std::vector<double> out;
  for (const Vector6d& x : v) out.insert(out.end(), x.data(), x.data() + 6);
  return out;
}

std::vector<double> flat12(const std::vector<Vector12d>& v) {
  std::vector<double> out;
  for (const Vector12d& x : v) out.insert(out.end(), x.data(), x.data() + kDofs);
  return out;
}

void write_series(h5::Writer& w, const Simulation3& sim) {
  const auto& hs = sim.histories();
  {
    std::vector<std::string> names;
    std::vector<std::int32_t> blocks;
    std::vector<Vec3> initial;
    for (const MeasurementPoint3& p : sim.model().measurements) {
      names.push_back(p.name);
      blocks.push_back(p.block);
      initial.push_back(p.position);
    }
    write_points(w, names, blocks, flat(initial), 3);
  }
  h5::Id g = w.group("series");
  w.attr_text(g.get(), "description",
              "measurement point time series: sample 0 is the start of the run, then one sample per step");
  const std::size_t np = hs.size();
  const std::vector<double> time = series_times(hs, sim.log(), sim.time());
  const std::size_t ns = time.size();
  std::vector<Vec3> pos, disp, vel;
  std::vector<Vector6d> stress;
  for (std::size_t s = 0; s < ns && np > 0; ++s)
    for (std::size_t p = 0; p < np; ++p) {
      const MeasurementSample3& m = hs[p][s];
      pos.push_back(m.position);
      disp.push_back(m.displacement);
      vel.push_back(m.velocity);
      stress.push_back(m.stress);
    }
  w.f64(g.get(), "time", time, {ns}, "s", "time of each sample");
  w.f64(g.get(), "position", flat(pos), {ns, np, 3}, "m", "x y z of each point");
  w.f64(g.get(), "displacement", flat(disp), {ns, np, 3}, "m", "ux uy uz from the start of the run");
  w.f64(g.get(), "velocity", flat(vel), {ns, np, 3}, "m/s", "vx vy vz at the end of the step");
  w.f64(g.get(), "stress", flat6(stress), {ns, np, 6}, "Pa",
        std::string("stress of the block the point lies in: ") + kStressColumns);
}

void write_steps(h5::Writer& w, const std::vector<StepRecord3>& log) {
  h5::Id g = w.group("steps");
  w.attr_text(g.get(), "description", "one row per accepted step");
  df::h5io::write_step_columns(w, g.get(), log, [](const StepRecord3& r) { return r.iterations; });
}

void write_frames(h5::Writer& w, const std::vector<Frame3>& frames, std::size_t nv, std::size_t nb) {
  h5::Id g = w.group("frames");
  w.attr_text(g.get(), "description", "block states at the output interval; frame 0 is the start of the run");
  std::vector<std::int32_t> step;
  std::vector<double> time, verts, vel, stress;
  for (const Frame3& f : frames) {
    step.push_back(f.step);
    time.push_back(f.time);
    const std::vector<double> v = flat(f.vertices), u = flat12(f.velocity), s = flat6(f.stress);
    verts.insert(verts.end(), v.begin(), v.end());
    vel.insert(vel.end(), u.begin(), u.end());
    stress.insert(stress.end(), s.begin(), s.end());
  }
  const std::size_t nf = frames.size();
  w.i32(g.get(), "step", step, "", "step of each frame (0: the start)");
  w.f64(g.get(), "time", time, {nf}, "s", "time of each frame");
  w.f64(g.get(), "vertices", verts, {nf, nv, 3}, "m", "block vertices, block after block as /model/blocks/vertices");
  w.f64(g.get(), "velocity", vel, {nf, nb, kDofs}, "m/s, rad/s, 1/s",
        std::string("end velocity of each block: ") + kVelocityColumns);
  w.f64(g.get(), "stress", stress, {nf, nb, 6}, "Pa", std::string("stress of each block: ") + kStressColumns);
}

// --------------------------------------------------------------- reading

void read_series(const h5::Reader& r, Results3& out) {
  out.point_names = r.strings("/points/name");
  const std::size_t np = out.point_names.size();
  for (std::int64_t b : read_i64(r, "/points/block", np)) out.point_blocks.push_back(static_cast<int>(b));
  const std::size_t ns = length(r, "/series/time");
  const auto time = read_f64(r, "/series/time", {ns});
  const auto pos = read_f64(r, "/series/position", {ns, np, 3});
  const auto disp = read_f64(r, "/series/displacement", {ns, np, 3});
  const auto vel = read_f64(r, "/series/velocity", {ns, np, 3});
  const auto stress = read_f64(r, "/series/stress", {ns, np, 6});
  out.histories.assign(np, std::vector<MeasurementSample3>(ns));
  for (std::size_t s = 0; s < ns; ++s)
    for (std::size_t p = 0; p < np; ++p) {
      MeasurementSample3& m = out.histories[p][s];
      const std::size_t k = s * np + p;
      m.time = time[s];
      m.position = Vec3(pos[3 * k], pos[3 * k + 1], pos[3 * k + 2]);
      m.displacement = Vec3(disp[3 * k], disp[3 * k + 1], disp[3 * k + 2]);
      m.velocity = Vec3(vel[3 * k], vel[3 * k + 1], vel[3 * k + 2]);
      m.stress = Eigen::Map<const Vector6d>(stress.data() + 6 * k);
    }
}

void read_log(const h5::Reader& r, Results3& out) {
  df::h5io::read_step_columns(r, out.log, [](StepRecord3& s, int n) { s.iterations = n; });
}

void read_frames(const h5::Reader& r, Results3& out) {
  df::h5io::read_frame_series(r, out.blocks.blocks, out.frames);
}

}  // namespace

void write_results3_h5(const std::string& path, const Results3& results, const Simulation3& sim, bool complete) {
  AtomicOutput out(path);
  h5::Writer w(path, out.temp_path());
  df::h5io::write_root(w, kResults3dFormat, kUnits, results.source, results.output, complete, sim.time(),
                       static_cast<int>(sim.log().size()));
  // The origin at the root too, where readers of the series alone find it.
  io::write_origin(w, w.file(), sim.model().origin);
  write_polyhedra_group(w, "model", results.blocks);
  std::vector<std::int32_t> fixed;
  for (const bool f : sim.model().fixed) fixed.push_back(f ? 1 : 0);
  w.i32(w.file(), "fixed", fixed, "", "1 for a block held fixed in the run (no unknowns), one per block of /model");
  write_series(w, sim);
  write_steps(w, sim.log());
  df::h5io::write_energy(w, sim.energy_log(), "J");
  if (!sim.model().bolts.empty()) {  // a run without bolts writes the file it wrote before them
    std::vector<std::string> names;
    for (const Bolt3& b : sim.model().bolts) names.push_back(b.name);
    df::h5io::write_bolt_series(w, names, sim.bolt_histories(), "axial force, tension positive");
  }
  std::size_t nv = 0;
  for (const Polyhedron& b : sim.blocks()) nv += b.vertices.size();
  write_frames(w, results.frames, nv, sim.blocks().size());
  write_checkpoint3(w, sim.state());
  w.close();
  out.commit();
}

Results3 read_results3_h5(const std::string& path, const df::ResultsParts& parts) {
  h5::Reader r(path);
  const df::h5io::RootInfo root = df::h5io::read_root(r, kResults3dFormat);
  Results3 out;
  out.source = root.source;
  out.output = root.output;
  out.complete = root.complete;
  const Vec3 origin = io::read_origin3(r, r.file());
  out.blocks.origin = origin;
  if (parts.series) read_series(r, out);
  if (parts.log) read_log(r, out);
  // Files written before the 3D energy ledger have none.
  if (parts.energy && r.exists("/energy/time")) out.energy = df::h5io::read_energy(r);
  if (parts.bolts && r.exists("/bolts/name")) df::h5io::read_bolt_series(r, out.bolt_names, out.bolt_histories);
  const std::size_t nb = length(r, "/fixed");
  for (const std::int64_t f : read_i64(r, "/fixed", nb)) out.fixed.push_back(f != 0);
  if (!parts.frames) return out;
  out.blocks = read_polyhedra_group(r, "model");
  out.blocks.origin = origin;
  if (out.blocks.blocks.size() != nb) r.fail("dataset /fixed must have one value per block of /model");
  read_frames(r, out);
  if (!parts.checkpoint) return out;
  std::vector<std::size_t> counts;
  for (const Polyhedron& b : out.blocks.blocks) counts.push_back(b.vertices.size());
  SimulationState3 s = read_checkpoint3(r, counts);
  s.log = out.log;
  s.histories = out.histories;
  s.energy_log = out.energy;
  s.bolt_histories = out.bolt_histories;
  out.checkpoint = std::move(s);
  return out;
}

}  // namespace dda::df3
