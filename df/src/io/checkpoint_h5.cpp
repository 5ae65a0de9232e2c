// /checkpoint of a results file: block states, contacts with their states,
// reference points and friction memory, point positions, time, dt and the
// step count. Everything is float64 or int32, so it reads back bit for bit.
#include "io/checkpoint_h5.hpp"

#include <cstdint>
#include <string>

#include "io/bolts_h5.hpp"
#include "io/checkpoint_common.hpp"
#include "dda/df/2d/block_kinematics.hpp"
#include "io/results_h5_util.hpp"

namespace dda::df {
namespace {

using h5io::checkpoint_table;
using h5io::contact_ints;
using h5io::contact_reals;
using h5io::flat;
using h5io::read_points2;
using h5io::rows_of;

}  // namespace

void write_checkpoint(h5::Writer& w, const SimulationState& s) {
  h5::Id g = w.group("checkpoint");
  h5io::write_checkpoint_clock(w, g.get(), s.time, s.dt, s.step_count, s.started);
  w.attr_text(g.get(), "description",
              "complete simulation state after step step_count; with /steps (the log) and /series (the "
              "histories) it is what `dda df --resume` continues from");

  const std::size_t nb = s.blocks.size();
  std::vector<Vec2> verts;
  std::vector<double> vel, vel_end, acc, stress;
  for (const BlockState& b : s.blocks) {
    verts.insert(verts.end(), b.vertices.begin(), b.vertices.end());
    for (int k = 0; k < kDofs; ++k) vel.push_back(b.velocity[k]);
    for (int k = 0; k < kDofs; ++k) vel_end.push_back(b.velocity_end[k]);
    for (int k = 0; k < kDofs; ++k) acc.push_back(b.acceleration[k]);
    for (int k = 0; k < 3; ++k) stress.push_back(b.stress[k]);
  }
  h5::Id bg(H5Gcreate2(g.get(), "blocks", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  w.f64(bg.get(), "vertices", flat(verts), {verts.size(), 2}, "m", "current vertices, ragged as /model/blocks");
  w.f64(bg.get(), "velocity", vel, {nb, kDofs}, "m/s, rad/s, 1/s",
        "start velocity of the next step (dynamic * end velocity): u v r ex ey gxy rates at the centroid");
  w.f64(bg.get(), "velocity_end", vel_end, {nb, kDofs}, "m/s, rad/s, 1/s", "end velocity of the last step");
  w.f64(bg.get(), "acceleration", acc, {nb, kDofs}, "m/s2, rad/s2, 1/s2",
        "acceleration of the last step (the next step's first solve starts from the motion it predicts)");
  w.f64(bg.get(), "stress", stress, {nb, 3}, "Pa", "sx sy txy, tension positive");

  const std::vector<Contact>& cs = s.contacts;
  h5::Id cg(H5Gcreate2(g.get(), "contacts", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  const hid_t c = cg.get();
  w.i32(c, "vertex_block", contact_ints(cs, [](const Contact& x) { return x.vblock; }), "", "block of the vertex P1");
  w.i32(c, "vertex", contact_ints(cs, [](const Contact& x) { return x.vertex; }), "", "vertex index in its block");
  w.i32(c, "edge_block", contact_ints(cs, [](const Contact& x) { return x.eblock; }), "", "block of the edge");
  w.i32(c, "edge", contact_ints(cs, [](const Contact& x) { return x.edge; }), "", "edge index (from vertex edge to the next)");
  w.i32(c, "joint", contact_ints(cs, [](const Contact& x) { return x.joint; }), "", "joint index (joint sets, then default)");
  w.i32(c, "state", contact_ints(cs, [](const Contact& x) { return static_cast<int>(x.state); }), "",
        "0 open, 1 sliding, 2 locked");
  w.i32(c, "slip_sign", contact_ints(cs, [](const Contact& x) { return x.slip_sign; }), "", "+1/-1 slip direction along the edge");
  w.i32(c, "bonded", contact_ints(cs, [](const Contact& x) { return x.bonded ? 1 : 0; }), "", "1: intact cohesive/tensile bond");
  w.i32(c, "broke", contact_ints(cs, [](const Contact& x) { return x.broke ? 1 : 0; }), "", "1: bond broke in the last iterate");
  w.i32(c, "friction_settled", contact_ints(cs, [](const Contact& x) { return x.friction_settled ? 1 : 0; }), "",
        "1: friction force settled in the last iterate");
  w.f64(c, "ref_ratio", contact_reals(cs, [](const Contact& x) { return x.ref_ratio; }), {cs.size()}, "1",
        "shear reference point on the edge (0 at its first vertex, 1 at its second)");
  w.f64(c, "normal_force", contact_reals(cs, [](const Contact& x) { return x.normal_force; }), {cs.size()}, "N",
        "compression positive");
  w.f64(c, "shear_force", contact_reals(cs, [](const Contact& x) { return x.shear_force; }), {cs.size()}, "N",
        "on the vertex along the edge");
  w.f64(c, "slip_velocity", contact_reals(cs, [](const Contact& x) { return x.slip_velocity; }), {cs.size()}, "m/s",
        "relative sliding speed");
  w.f64(c, "length", contact_reals(cs, [](const Contact& x) { return x.length; }), {cs.size()}, "m",
        "joint length the contact stands for");
  w.f64(c, "friction_theta", contact_reals(cs, [](const Contact& x) { return x.friction.theta; }), {cs.size()}, "s",
        "rate-and-state variable");
  w.f64(c, "friction_slip", contact_reals(cs, [](const Contact& x) { return x.friction.slip; }), {cs.size()}, "m",
        "cumulative slip");
  // further law-specific memory (FrictionState::extra), ragged
  h5io::write_ragged(w, c, cs, [](const Contact& x) -> const std::vector<double>& { return x.friction.extra; },
                     "friction_extra_count",
                     "number of law-specific friction variables of each contact (in friction_extra)",
                     "friction_extra",
                     "law-specific friction variables of all contacts, in contact order (e.g. degradation: reversals, "
                     "last slip sign)");

  h5::Id pg(H5Gcreate2(g.get(), "points", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  w.f64(pg.get(), "fixed_anchor", flat(s.fixed_anchor), {s.fixed_anchor.size(), 2}, "m",
        "where each fixed point is held");
  w.f64(pg.get(), "fixed_position", flat(s.fixed_pos), {s.fixed_pos.size(), 2}, "m", "current material position");
  w.f64(pg.get(), "load_position", flat(s.load_pos), {s.load_pos.size(), 2}, "m", "current load point positions");
  w.f64(pg.get(), "measurement_position", flat(s.measurement_pos), {s.measurement_pos.size(), 2}, "m",
        "current measurement point positions");

  h5io::write_bolt_states(w, g.get(), s.bolts);

  h5io::write_warm_start(w, g.get(), s.solver_warm_start);
}

void read_checkpoint(const h5::Reader& r, const std::vector<std::size_t>& vertex_counts, SimulationState& s) {
  const h5io::CheckpointClock clock = h5io::read_checkpoint_clock(r, true);
  s.time = clock.time;
  s.dt = clock.dt;
  s.step_count = clock.step_count;
  s.started = clock.started;

  const std::size_t nb = vertex_counts.size();
  std::size_t nv = 0;
  for (std::size_t n : vertex_counts) nv += n;
  const std::vector<Vec2> verts = read_points2(r, "/checkpoint/blocks/vertices", nv);
  const std::vector<double> vel = checkpoint_table(r, "/checkpoint/blocks/velocity", nb, kDofs);
  const std::vector<double> vel_end = checkpoint_table(r, "/checkpoint/blocks/velocity_end", nb, kDofs);
  // Files written before it was saved lack it: it only sets where the
  // iterative solver starts, so they resume to within its tolerance.
  const bool has_acc = r.exists("/checkpoint/blocks/acceleration");
  const std::vector<double> acc =
      has_acc ? checkpoint_table(r, "/checkpoint/blocks/acceleration", nb, kDofs) : std::vector<double>(nb * kDofs, 0.0);
  const std::vector<double> stress = checkpoint_table(r, "/checkpoint/blocks/stress", nb, 3);
  s.blocks.assign(nb, BlockState{});
  std::size_t at = 0;
  for (std::size_t i = 0; i < nb; ++i) {
    BlockState& b = s.blocks[i];
    b.vertices.assign(verts.begin() + static_cast<long>(at), verts.begin() + static_cast<long>(at + vertex_counts[i]));
    at += vertex_counts[i];
    b.geometry = block_geometry(b.vertices);
    for (int k = 0; k < kDofs; ++k) b.velocity[k] = vel[kDofs * i + k];
    for (int k = 0; k < kDofs; ++k) b.velocity_end[k] = vel_end[kDofs * i + k];
    for (int k = 0; k < kDofs; ++k) b.acceleration[k] = acc[kDofs * i + k];
    for (int k = 0; k < 3; ++k) b.stress[k] = stress[3 * i + k];
  }

  const std::string c = "/checkpoint/contacts/";
  const std::size_t nc = rows_of(r, c + "normal_force");
  auto ivec = [&](const std::string& name) {
    const h5::Array<std::int64_t> a = r.i64(c + name);
    if (a.dims.size() != 1 || a.dims[0] != nc) r.fail("dataset " + c + name + " must have one value per contact");
    return a.data;
  };
  auto rvec = [&](const std::string& name) {
    const h5::Array<double> a = r.f64(c + name);
    if (a.dims.size() != 1 || a.dims[0] != nc) r.fail("dataset " + c + name + " must have one value per contact");
    return a.data;
  };
  const auto vb = ivec("vertex_block"), vx = ivec("vertex"), eb = ivec("edge_block"), ed = ivec("edge"),
             jt = ivec("joint"), st = ivec("state"), sg = ivec("slip_sign"), bo = ivec("bonded"), br = ivec("broke"),
             fs = ivec("friction_settled");
  const auto rr = rvec("ref_ratio"), nf = rvec("normal_force"), sf = rvec("shear_force"), sv = rvec("slip_velocity"),
             ln = rvec("length"), th = rvec("friction_theta"), sl = rvec("friction_slip");
  s.contacts.assign(nc, Contact{});
  for (std::size_t k = 0; k < nc; ++k) {
    Contact& x = s.contacts[k];
    x.vblock = static_cast<int>(vb[k]);
    x.vertex = static_cast<int>(vx[k]);
    x.eblock = static_cast<int>(eb[k]);
    x.edge = static_cast<int>(ed[k]);
    x.joint = static_cast<int>(jt[k]);
    if (st[k] < 0 || st[k] > 2) r.fail("dataset " + c + "state holds an unknown contact state");
    x.state = static_cast<ContactState>(st[k]);
    x.slip_sign = static_cast<int>(sg[k]);
    x.bonded = bo[k] != 0;
    x.broke = br[k] != 0;
    x.friction_settled = fs[k] != 0;
    x.ref_ratio = rr[k];
    x.normal_force = nf[k];
    x.shear_force = sf[k];
    x.slip_velocity = sv[k];
    x.length = ln[k];
    x.friction.theta = th[k];
    x.friction.slip = sl[k];
  }
  // Law-specific friction memory; files written before it existed have none.
  if (r.exists(c + "friction_extra_count")) {
    std::vector<std::vector<double>> extra =
        h5io::read_ragged(r, c, ivec("friction_extra_count"), "friction_extra_count", "friction_extra", 0);
    for (std::size_t k = 0; k < nc; ++k) s.contacts[k].friction.extra = std::move(extra[k]);
  }

  const std::string p = "/checkpoint/points/";
  s.fixed_anchor = read_points2(r, p + "fixed_anchor");
  s.fixed_pos = read_points2(r, p + "fixed_position");
  s.load_pos = read_points2(r, p + "load_position");
  s.measurement_pos = read_points2(r, p + "measurement_position");

  s.bolts = h5io::read_bolt_states<2>(r, "/checkpoint/bolts/");

  s.solver_warm_start = h5io::read_warm_start(r, "/checkpoint");
}

}  // namespace dda::df
