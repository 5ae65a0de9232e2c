// The results file (format "dda-results"). Layout, dataset by dataset, in
// docs/formats.md; keep the two in step.
#include <cmath>
#include <cstdint>

#include "io/checkpoint_h5.hpp"
#include "io/bolts_h5.hpp"
#include "io/results_h5_util.hpp"
#include "dda/common/atomic_file.hpp"
#include "dda/common/error.hpp"
#include "dda/common/origin_h5.hpp"
#include "dda/df/io/results.hpp"

namespace dda::df {
namespace {

constexpr const char* kFormat = "dda-results";
constexpr const char* kUnits =
    "SI: lengths m, time s, velocity m/s, rotation rad, stress Pa, force N and energy J per unit thickness";

using h5io::flat;
using h5io::series_times;
using h5io::write_points;
using h5io::length;

void write_model(h5::Writer& w, const Results& r, const Model& model) {
  h5::Id g = w.group("model");
  w.attr_text(g.get(), "description", "the blocks, joint sets and points the run started from");
  const BlockModel& bm = r.blocks;
  {
    h5::Id b = h5io::subgroup(g.get(), "blocks");
    std::vector<Vec2> verts;
    std::vector<std::int64_t> offsets{0};
    std::vector<std::int32_t> edge_set, layer, material;
    for (std::size_t i = 0; i < bm.blocks.size(); ++i) {
      const Block& blk = bm.blocks[i];
      verts.insert(verts.end(), blk.vertices.begin(), blk.vertices.end());
      offsets.push_back(static_cast<std::int64_t>(verts.size()));
      for (std::size_t k = 0; k < blk.vertices.size(); ++k)
        edge_set.push_back(k < blk.edge_set.size() ? blk.edge_set[k] : kBoundarySet);
      layer.push_back(blk.layer);
      material.push_back(i < model.block_material.size() ? model.block_material[i] : 0);
    }
    w.f64(b.get(), "vertices", flat(verts), {verts.size(), 2}, "m", "initial block vertices, ragged, counter-clockwise");
    w.i64(b.get(), "offsets", offsets, "", "block i is vertices[offsets[i]:offsets[i+1]]");
    w.i32(b.get(), "edge_set", edge_set, "", "joint set of the edge from each vertex to the next (as in blocks files)");
    w.i32(b.get(), "layer", layer, "", "bed of the block, -1 if not layered");
    w.i32(b.get(), "material", material, "", "material index of the block (see /model/materials)");
  }
  {
    h5::Id s = h5io::subgroup(g.get(), "sets");
    std::vector<std::string> names, origins;
    for (const JointSetInfo& js : bm.sets) names.push_back(js.name), origins.push_back(js.origin);
    w.strings(s.get(), "name", names, "", "joint set names (index = set id)");
    w.strings(s.get(), "origin", origins, "", "where each set came from");
  }
  {
    h5::Id p = h5io::subgroup(g.get(), "points");
    std::vector<std::string> names;
    std::vector<std::int32_t> kinds, blocks;
    std::vector<Vec2> xy;
    for (const LocatedPoint& lp : bm.points) {
      names.push_back(lp.point.name);
      kinds.push_back(static_cast<std::int32_t>(lp.point.kind));
      blocks.push_back(lp.block);
      xy.push_back(lp.point.p);
    }
    w.strings(p.get(), "name", names, "", "point names");
    w.i32(p.get(), "kind", kinds, "", "0 fixed, 1 load, 2 measurement, 3 hole");
    w.f64(p.get(), "xy", flat(xy), {xy.size(), 2}, "m", "initial positions");
    w.i32(p.get(), "block", blocks, "", "block containing the point");
  }
  {
    h5::Id l = h5io::subgroup(g.get(), "layers");
    std::vector<double> bottom, top;
    for (const Layer& layer : bm.layers) bottom.push_back(layer.bottom), top.push_back(layer.top);
    w.f64(l.get(), "bottom", bottom, {bottom.size()}, "m", "lower boundary of each bed");
    w.f64(l.get(), "top", top, {top.size()}, "m", "upper boundary of each bed");
  }
  {
    h5::Id m = h5io::subgroup(g.get(), "materials");
    std::vector<double> props;
    for (const Material& mat : model.materials)
      props.insert(props.end(), {mat.density, mat.young, mat.poisson, mat.plane == PlaneMode::Strain ? 1.0 : 0.0});
    w.f64(m.get(), "properties", props, {model.materials.size(), 4}, "kg/m^3, Pa, 1, -",
          "density, young, poisson, plane (0 stress, 1 strain) of each material");
  }
}

void write_series(h5::Writer& w, const Simulation& sim) {
  const auto& hs = sim.histories();
  const Model& model = sim.model();
  {
    std::vector<std::string> names;
    std::vector<std::int32_t> blocks;
    std::vector<Vec2> initial;
    for (const MeasurementPoint& p : model.measurements) {
      names.push_back(p.name);
      blocks.push_back(p.block);
      initial.push_back(p.position);
    }
    write_points(w, names, blocks, flat(initial), 2);
  }
  h5::Id g = w.group("series");
  w.attr_text(g.get(), "description",
              "measurement point time series: sample 0 is the start of the run, then one sample per step");
  const std::size_t np = hs.size();
  const std::vector<double> time = series_times(hs, sim.log(), sim.time());
  const std::size_t ns = time.size();
  std::vector<double> pos, disp, vel, acc, stress;
  pos.reserve(ns * np * 2);
  for (std::size_t s = 0; s < ns; ++s)
    for (std::size_t p = 0; p < np; ++p) {
      const MeasurementSample& m = hs[p][s];
      pos.insert(pos.end(), {m.position.x(), m.position.y()});
      disp.insert(disp.end(), {m.displacement.x(), m.displacement.y()});
      vel.insert(vel.end(), {m.velocity.x(), m.velocity.y()});
      acc.insert(acc.end(), {m.acceleration.x(), m.acceleration.y()});
      stress.insert(stress.end(), {m.stress[0], m.stress[1], m.stress[2]});
    }
  w.f64(g.get(), "time", time, {ns}, "s", "time of each sample");
  w.f64(g.get(), "position", pos, {ns, np, 2}, "m", "x y of each point");
  w.f64(g.get(), "displacement", disp, {ns, np, 2}, "m", "ux uy from the start of the run");
  w.f64(g.get(), "velocity", vel, {ns, np, 2}, "m/s", "vx vy at the end of the step");
  w.f64(g.get(), "acceleration", acc, {ns, np, 2}, "m/s^2",
        "ax ay during the step that ended at the sample (constant within a DDA step; 0 at the start)");
  w.f64(g.get(), "stress", stress, {ns, np, 3}, "Pa", "sxx syy sxy of the block the point lies in");
}

void write_steps(h5::Writer& w, const std::vector<StepRecord>& log) {
  h5::Id g = w.group("steps");
  w.attr_text(g.get(), "description", "one row per accepted step");
  h5io::write_step_columns(w, g.get(), log, [](const StepRecord& r) { return r.open_close_iterations; });
  auto reals = [&log](auto get) {
    std::vector<double> v;
    v.reserve(log.size());
    for (const StepRecord& r : log) v.push_back(get(r));
    return v;
  };
  const std::vector<hsize_t> n{log.size()};
  w.f64(g.get(), "kinetic_energy", reals([](const StepRecord& r) { return r.kinetic_energy; }), n, "J",
        "kinetic energy at the end of the step (per unit thickness)");
  w.f64(g.get(), "elastic_energy", reals([](const StepRecord& r) { return r.elastic_energy; }), n, "J",
        "strain energy of the blocks (per unit thickness)");
}

void write_bolts(h5::Writer& w, const Simulation& sim) {
  std::vector<std::string> names;
  for (const Bolt& b : sim.model().bolts) names.push_back(b.name);
  h5io::write_bolt_series(w, names, sim.bolt_histories(), "axial force, tension positive (per unit thickness)");
}

void write_frames(h5::Writer& w, const std::vector<Frame>& frames, std::size_t nv, std::size_t nb) {
  h5::Id g = w.group("frames");
  w.attr_text(g.get(), "description", "block states at the output interval; frame 0 is the start of the run");
  std::vector<std::int32_t> step;
  std::vector<double> time, verts, vel, stress;
  for (const Frame& f : frames) {
    step.push_back(f.step);
    time.push_back(f.time);
    for (const Vec2& v : f.vertices) verts.insert(verts.end(), {v.x(), v.y()});
    for (const Vector6d& v : f.velocity) vel.insert(vel.end(), v.data(), v.data() + kDofs);
    for (const Vector3d& s : f.stress) stress.insert(stress.end(), s.data(), s.data() + 3);
  }
  const std::size_t nf = frames.size();
  w.i32(g.get(), "step", step, "", "step of each frame (0: the start)");
  w.f64(g.get(), "time", time, {nf}, "s", "time of each frame");
  w.f64(g.get(), "vertices", verts, {nf, nv, 2}, "m", "block vertices, ragged as /model/blocks");
  w.f64(g.get(), "velocity", vel, {nf, nb, kDofs}, "m/s, rad/s, 1/s",
        "end velocity of each block: u v r ex ey gxy rates at its centroid");
  w.f64(g.get(), "stress", stress, {nf, nb, 3}, "Pa", "sx sy txy of each block, tension positive");
}

// --------------------------------------------------------------- reading

std::vector<double> f64(const h5::Reader& r, const std::string& name, const std::vector<hsize_t>& dims) {
  return h5io::read_f64(r, name, dims);
}

std::vector<std::int64_t> i64(const h5::Reader& r, const std::string& name, std::size_t n) {
  return h5io::read_i64(r, name, n);
}

void read_model(const h5::Reader& r, Results& out) {
  BlockModel& bm = out.blocks;
  const std::size_t nv = length(r, "/model/blocks/vertices");
  const std::vector<double> xy = f64(r, "/model/blocks/vertices", {nv, 2});
  const std::size_t nb1 = out.block_count + 1;
  const std::vector<std::int64_t> off = r.offsets("/model/blocks/offsets", nv, 3, "block");
  if (off.size() != nb1)
    r.fail("dataset /model/blocks/offsets has " + std::to_string(off.size()) + " entries, expected " +
           std::to_string(nb1) + ", one more than the blocks");
  const std::size_t nb = nb1 - 1;
  const std::vector<std::int64_t> es = i64(r, "/model/blocks/edge_set", nv);
  const std::vector<std::int64_t> layer = i64(r, "/model/blocks/layer", nb);
  for (std::size_t i = 0; i < nb; ++i) {
    Block b;
    for (auto k = static_cast<std::size_t>(off[i]); k < static_cast<std::size_t>(off[i + 1]); ++k) {
      b.vertices.emplace_back(xy[2 * k], xy[2 * k + 1]);
      b.edge_set.push_back(static_cast<int>(es[k]));
    }
    const PolygonMoments m = polygon_moments(b.vertices);
    b.area = m.area;
    b.centroid = m.centroid;
    b.sxx = m.sxx;
    b.syy = m.syy;
    b.sxy = m.sxy;
    b.layer = static_cast<int>(layer[i]);
    bm.blocks.push_back(std::move(b));
  }
  const std::vector<std::string> names = r.strings("/model/sets/name");
  const std::vector<std::string> origins = r.strings("/model/sets/origin");
  if (names.size() != origins.size()) r.fail("datasets /model/sets/name and /model/sets/origin differ in length");
  for (std::size_t i = 0; i < names.size(); ++i) bm.sets.push_back({names[i], origins[i]});
  const std::vector<std::string> pnames = r.strings("/model/points/name");
  const std::size_t np = pnames.size();
  const std::vector<std::int64_t> kinds = i64(r, "/model/points/kind", np);
  const std::vector<std::int64_t> pblocks = i64(r, "/model/points/block", np);
  const std::vector<double> pxy = f64(r, "/model/points/xy", {np, 2});
  for (std::size_t i = 0; i < np; ++i) {
    if (kinds[i] < 0 || kinds[i] > 3) r.fail("dataset /model/points/kind holds an unknown point kind");
    if (pblocks[i] < -1 || pblocks[i] >= static_cast<std::int64_t>(nb))
      r.fail("dataset /model/points/block refers to a block that does not exist");
    LocatedPoint lp;
    lp.point = {pnames[i], static_cast<PointKind>(kinds[i]), Vec2(pxy[2 * i], pxy[2 * i + 1])};
    lp.block = static_cast<int>(pblocks[i]);
    bm.points.push_back(lp);
  }
  const std::size_t nl = length(r, "/model/layers/bottom");
  const std::vector<double> bottom = f64(r, "/model/layers/bottom", {nl});
  const std::vector<double> top = f64(r, "/model/layers/top", {nl});
  for (std::size_t i = 0; i < nl; ++i) {
    Layer l;
    l.bottom = bottom[i];
    l.top = top[i];
    bm.layers.push_back(l);
  }
  // Set and bed ids index tables later on: out of range, they are damage.
  for (std::size_t k = 0; k < nv; ++k)
    if (es[k] < kArtificialSet || es[k] >= static_cast<std::int64_t>(bm.sets.size()))
      r.fail("dataset /model/blocks/edge_set entry " + std::to_string(k) + " is " + std::to_string(es[k]) +
             ", not a joint set of the file");
  for (std::size_t i = 0; i < nb; ++i)
    if (layer[i] < -1 || layer[i] >= static_cast<std::int64_t>(nl))
      r.fail("dataset /model/blocks/layer entry " + std::to_string(i) + " is " + std::to_string(layer[i]) +
             ", not a bed of the file");
}

void read_log(const h5::Reader& r, Results& out) {
  h5io::read_step_columns(r, out.log, [](StepRecord& s, int n) { s.open_close_iterations = n; });
  const std::size_t n = out.log.size();
  const auto ke = f64(r, "/steps/kinetic_energy", {n}), ee = f64(r, "/steps/elastic_energy", {n});
  for (std::size_t i = 0; i < n; ++i) {
    out.log[i].kinetic_energy = ke[i];
    out.log[i].elastic_energy = ee[i];
  }
}

void read_series(const h5::Reader& r, Results& out) {
  out.point_names = r.strings("/points/name");
  const std::size_t np = out.point_names.size();
  for (std::int64_t b : i64(r, "/points/block", np)) out.point_blocks.push_back(static_cast<int>(b));
  const std::size_t ns = length(r, "/series/time");
  const auto time = f64(r, "/series/time", {ns});
  const auto pos = f64(r, "/series/position", {ns, np, 2});
  const auto disp = f64(r, "/series/displacement", {ns, np, 2});
  const auto vel = f64(r, "/series/velocity", {ns, np, 2});
  // Files written before receivers had accelerations have none.
  out.has_acceleration = r.exists("/series/acceleration");
  const auto acc = out.has_acceleration ? f64(r, "/series/acceleration", {ns, np, 2}) : std::vector<double>(2 * ns * np);
  const auto stress = f64(r, "/series/stress", {ns, np, 3});
  out.histories.assign(np, std::vector<MeasurementSample>(ns));
  for (std::size_t s = 0; s < ns; ++s)
    for (std::size_t p = 0; p < np; ++p) {
      MeasurementSample& m = out.histories[p][s];
      const std::size_t k = s * np + p;
      m.time = time[s];
      m.position = Vec2(pos[2 * k], pos[2 * k + 1]);
      m.displacement = Vec2(disp[2 * k], disp[2 * k + 1]);
      m.velocity = Vec2(vel[2 * k], vel[2 * k + 1]);
      m.acceleration = Vec2(acc[2 * k], acc[2 * k + 1]);
      m.stress = Vector3d(stress[3 * k], stress[3 * k + 1], stress[3 * k + 2]);
    }
}

void read_bolts(const h5::Reader& r, Results& out) {
  h5io::read_bolt_series(r, out.bolt_names, out.bolt_histories);
}

void read_frames(const h5::Reader& r, Results& out) {
  h5io::read_frame_series(r, out.blocks.blocks, out.frames);
}

}  // namespace

Frame make_frame(const Simulation& sim) {
  Frame f;
  f.step = sim.log().empty() ? 0 : sim.log().back().step;
  f.time = sim.time();
  for (const BlockState& b : sim.blocks()) {
    f.vertices.insert(f.vertices.end(), b.vertices.begin(), b.vertices.end());
    f.velocity.push_back(b.velocity_end);
    f.stress.push_back(b.stress);
  }
  return f;
}

void write_results_h5(const std::string& path, const Results& results, const Simulation& sim, bool complete) {
  AtomicOutput out(path);
  h5::Writer w(path, out.temp_path());
  h5io::write_root(w, kFormat, kUnits, results.source, results.output, complete, sim.time(),
                   static_cast<int>(sim.log().size()));
  w.attr_text(w.file(), "solver", results.solver);
  io::write_origin(w, w.file(), sim.model().origin);

  write_model(w, results, sim.model());
  write_series(w, sim);
  write_steps(w, sim.log());
  h5io::write_energy(w, sim.energy_log(), "J per unit thickness");
  write_bolts(w, sim);
  std::size_t nv = 0;
  for (const BlockState& b : sim.blocks()) nv += b.vertices.size();
  write_frames(w, results.frames, nv, sim.blocks().size());
  write_checkpoint(w, sim.state());
  w.close();
  out.commit();
}

Results read_results_h5(const std::string& path, const ResultsParts& parts) {
  h5::Reader r(path);
  const h5io::RootInfo root = h5io::read_root(r, kFormat);
  Results out;
  out.source = root.source;
  out.output = root.output;
  out.complete = root.complete;
  out.solver = r.attr_text(r.file(), "solver", "the file").value_or("auto");
  const Vec2 origin = io::read_origin2(r, r.file());
  out.blocks.origin = origin;

  const std::size_t offsets = length(r, "/model/blocks/offsets");
  if (offsets < 1) r.fail("dataset /model/blocks/offsets is empty");
  out.block_count = offsets - 1;
  if (parts.series) read_series(r, out);
  if (parts.log) read_log(r, out);
  if (parts.energy) out.energy = h5io::read_energy(r);
  if (parts.bolts) read_bolts(r, out);
  if (!parts.frames) return out;
  read_model(r, out);
  out.blocks.origin = origin;
  read_frames(r, out);
  if (!parts.checkpoint) return out;
  std::vector<std::size_t> counts;
  for (const Block& b : out.blocks.blocks) counts.push_back(b.vertices.size());
  SimulationState s;
  read_checkpoint(r, counts, s);
  s.log = out.log;
  s.histories = out.histories;
  s.energy_log = out.energy;
  s.bolt_histories = out.bolt_histories;
  out.checkpoint = std::move(s);
  return out;
}

}  // namespace dda::df
