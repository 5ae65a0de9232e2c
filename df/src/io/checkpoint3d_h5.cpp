// /checkpoint of a 3D results file: block states, every contact with what
// Simulation3::restore needs (state, shear anchor, slip, forces, friction
// memory, the geometry's frame and points), point positions, time and dt.
// Everything is float64 or int32, so it reads back bit for bit.
#include "io/checkpoint3d_h5.hpp"

#include <array>
#include <cstdint>
#include <string>

#include "io/bolts_h5.hpp"
#include "io/checkpoint_common.hpp"
#include "io/results_h5_util.hpp"

namespace dda::df3 {
namespace {

using df::h5io::checkpoint_table;
using df::h5io::contact_ints;
using df::h5io::flat;
using df::h5io::read_points3;
using df::h5io::rows_of;

// One row of `width` numbers per contact.
template <class Get>
std::vector<double> rows(const std::vector<Contact3>& cs, int width, Get get) {
  std::vector<double> out;
  out.reserve(cs.size() * static_cast<std::size_t>(width));
  for (const Contact3& c : cs) {
    const auto v = get(c);
    for (int k = 0; k < width; ++k) out.push_back(v[k]);
  }
  return out;
}

Vec3 row3(const std::vector<double>& v, std::size_t k) { return {v[3 * k], v[3 * k + 1], v[3 * k + 2]}; }
Eigen::Vector2d row2(const std::vector<double>& v, std::size_t k) { return {v[2 * k], v[2 * k + 1]}; }

}  // namespace

void write_checkpoint3(h5::Writer& w, const SimulationState3& s) {
  h5::Id g = w.group("checkpoint");
  df::h5io::write_checkpoint_clock(w, g.get(), s.time, s.dt, static_cast<int>(s.log.size()), s.started);
  w.attr_i32(g.get(), "bonds_placed", s.bonds_placed ? 1 : 0);
  w.attr_text(g.get(), "description",
              "complete 3D simulation state after step step_count; with /steps (the log) and /series (the "
              "histories) it is what `dda df --resume` continues from");

  const std::size_t nb = s.vertices.size();
  std::vector<Vec3> verts;
  for (const auto& b : s.vertices) verts.insert(verts.end(), b.begin(), b.end());
  std::vector<double> vel, stress;
  for (const Vector12d& v : s.velocity) vel.insert(vel.end(), v.data(), v.data() + kDofs);
  for (const Vector6d& v : s.stress) stress.insert(stress.end(), v.data(), v.data() + 6);
  {
    h5::Id b = df::h5io::subgroup(g.get(), "blocks");
    w.f64(b.get(), "vertices", flat(verts), {verts.size(), 3}, "m", "current vertices, block after block as /model");
    w.f64(b.get(), "velocity", vel, {nb, kDofs}, "m/s, rad/s, 1/s", "velocity of each block (the twelve rates)");
    w.f64(b.get(), "stress", stress, {nb, 6}, "Pa", "sx sy sz tyz tzx txy of each block");
  }

  const std::vector<Contact3>& cs = s.contacts;
  const hsize_t nc = cs.size();
  h5::Id cg = df::h5io::subgroup(g.get(), "contacts");
  const hid_t c = cg.get();
  w.i32(c, "i", contact_ints(cs, [](const Contact3& x) { return x.i; }), "", "block i (its vertex or first edge)");
  w.i32(c, "j", contact_ints(cs, [](const Contact3& x) { return x.j; }), "", "block j (its face or second edge)");
  w.i32(c, "kind", contact_ints(cs, [](const Contact3& x) { return static_cast<int>(x.kind); }), "",
        "0 vertex-face, 1 edge-edge");
  std::vector<std::int32_t> ids;
  for (const Contact3& x : cs) ids.insert(ids.end(), x.ids, x.ids + 4);
  w.i32(c, "ids", ids, "",
        "4 per contact, row-major: vertex-face: vertex of i, face of j, -1, -1; edge-edge: edge of i, edge of j");
  w.i32(c, "state", contact_ints(cs, [](const Contact3& x) { return static_cast<int>(x.state); }), "",
        "0 open, 1 sliding, 2 locked");
  w.i32(c, "joint", contact_ints(cs, [](const Contact3& x) { return x.joint; }), "", "joint index (joint sets, then default)");
  auto vec3 = [&](const char* name, auto get, const char* units, const char* what) {
    w.f64(c, name, rows(cs, 3, get), {nc, 3}, units, what);
  };
  auto vec2 = [&](const char* name, auto get, const char* units, const char* what) {
    w.f64(c, name, rows(cs, 2, get), {nc, 2}, units, what);
  };
  auto one = [&](const char* name, auto get, const char* units, const char* what) {
    w.f64(c, name, df::h5io::contact_reals(cs, get), {nc}, units, what);
  };
  vec3("ref_j", [](const Contact3& x) { return x.ref_j; }, "m", "shear-spring anchor on block j");
  vec3("point_now", [](const Contact3& x) { return x.point_now; }, "m", "the contact point carried with block i");
  vec2("slip_dir", [](const Contact3& x) { return x.slip_dir; }, "1", "unit slip direction on (t1, t2) while sliding");
  vec2("slip", [](const Contact3& x) { return x.slip; }, "m", "slip of i relative to j in the last iterate (t1, t2)");
  one("normal_force", [](const Contact3& x) { return x.normal_force; }, "N", "compression positive");
  w.i32(c, "bonded", contact_ints(cs, [](const Contact3& x) { return x.bonded ? 1 : 0; }), "", "1: the joint's bond is intact");
  one("bond_area", [](const Contact3& x) { return x.bond_area; }, "m^2", "share of the face-to-face patch bonded");
  w.i32(c, "glued", contact_ints(cs, [](const Contact3& x) { return x.glued ? 1 : 0; }), "",
        "1: across an artificial cut, locked for ever");
  vec2("shear_force", [](const Contact3& x) { return x.shear_force; }, "N", "shear force on i (t1, t2)");
  one("strength", [](const Contact3& x) { return x.strength; }, "N", "the friction law's shear strength");
  one("slip_velocity", [](const Contact3& x) { return x.slip_velocity; }, "m/s", "slip speed of the last iterate");
  vec3("slip_axis", [](const Contact3& x) { return x.slip_axis; }, "1", "world direction of the first slip");
  vec3("normal", [](const Contact3& x) { return x.geo.normal; }, "1", "unit normal from j to i (geometry)");
  vec3("t1", [](const Contact3& x) { return x.geo.t1; }, "1", "first tangent (geometry)");
  vec3("t2", [](const Contact3& x) { return x.geo.t2; }, "1", "second tangent (geometry)");
  vec3("point_i", [](const Contact3& x) { return x.geo.point_i; }, "m", "contact point on i (geometry)");
  vec3("point_j", [](const Contact3& x) { return x.geo.point_j; }, "m", "contact point on j (geometry)");
  // the friction law's memory (FrictionState::to_vector), ragged
  df::h5io::write_ragged(w, c, cs, [](const Contact3& x) { return x.friction.to_vector(); }, "friction_count",
                         "number of friction-state values of each contact (in friction)", "friction",
                         "friction state of all contacts in contact order (theta, slip, then law-specific values)");

  h5::Id pg = df::h5io::subgroup(g.get(), "points");
  w.f64(pg.get(), "fixed_position", flat(s.fixed_at), {s.fixed_at.size(), 3}, "m", "where each fixed point is now");
  w.f64(pg.get(), "load_position", flat(s.load_at), {s.load_at.size(), 3}, "m", "where each load point is now");
  w.f64(pg.get(), "measurement_position", flat(s.measure_at), {s.measure_at.size(), 3}, "m",
        "where each measurement point is now");
  df::h5io::write_warm_start(w, g.get(), s.solver_warm_start);
  if (!s.bolts.empty()) df::h5io::write_bolt_states(w, g.get(), s.bolts);  // a run without bolts: as before
}

SimulationState3 read_checkpoint3(const h5::Reader& r, const std::vector<std::size_t>& vertex_counts) {
  const df::h5io::CheckpointClock clock = df::h5io::read_checkpoint_clock(r, false);
  SimulationState3 s;
  s.time = clock.time;
  s.dt = clock.dt;
  s.started = clock.started;
  h5::Id g(H5Gopen2(r.file(), "/checkpoint", H5P_DEFAULT), H5Gclose);
  // Files written before bonds had none to place.
  s.bonds_placed = r.attr_int(g.get(), "bonds_placed", "/checkpoint").value_or(1) != 0;

  const std::size_t nb = vertex_counts.size();
  std::size_t nv = 0;
  for (const std::size_t n : vertex_counts) nv += n;
  const std::vector<double> verts = checkpoint_table(r, "/checkpoint/blocks/vertices", nv, 3);
  const std::vector<double> vel = checkpoint_table(r, "/checkpoint/blocks/velocity", nb, kDofs);
  const std::vector<double> stress = checkpoint_table(r, "/checkpoint/blocks/stress", nb, 6);
  std::size_t at = 0;
  for (std::size_t b = 0; b < nb; ++b) {
    std::vector<Vec3> v;
    for (std::size_t k = 0; k < vertex_counts[b]; ++k) v.push_back(row3(verts, at++));
    s.vertices.push_back(std::move(v));
    s.velocity.push_back(Eigen::Map<const Vector12d>(vel.data() + kDofs * b));
    s.stress.push_back(Eigen::Map<const Vector6d>(stress.data() + 6 * b));
  }

  const std::string c = "/checkpoint/contacts/";
  const std::size_t nc = rows_of(r, c + "normal_force");
  auto ivec = [&](const std::string& name, std::size_t per) {
    const h5::Array<std::int64_t> a = r.i64(c + name);
    if (a.data.size() != nc * per) r.fail("dataset " + c + name + " must have " + std::to_string(per) + " values per contact");
    return a.data;
  };
  const auto ci = ivec("i", 1), cj = ivec("j", 1), kind = ivec("kind", 1), ids = ivec("ids", 4),
             state = ivec("state", 1), joint = ivec("joint", 1), fcount = ivec("friction_count", 1);
  const auto ref_j = checkpoint_table(r, c + "ref_j", nc, 3), point_now = checkpoint_table(r, c + "point_now", nc, 3),
             slip_dir = checkpoint_table(r, c + "slip_dir", nc, 2), slip = checkpoint_table(r, c + "slip", nc, 2),
             normal_force = checkpoint_table(r, c + "normal_force", nc, 1), shear = checkpoint_table(r, c + "shear_force", nc, 2),
             strength = checkpoint_table(r, c + "strength", nc, 1), slip_velocity = checkpoint_table(r, c + "slip_velocity", nc, 1),
             slip_axis = checkpoint_table(r, c + "slip_axis", nc, 3), normal = checkpoint_table(r, c + "normal", nc, 3),
             t1 = checkpoint_table(r, c + "t1", nc, 3), t2 = checkpoint_table(r, c + "t2", nc, 3), pi = checkpoint_table(r, c + "point_i", nc, 3),
             pj = checkpoint_table(r, c + "point_j", nc, 3);
  std::vector<std::vector<double>> friction =
      df::h5io::read_ragged(r, c, fcount, "friction_count", "friction", 2);  // at least theta and slip
  // Bonds: none in files written before them.
  const bool has_bonds = r.exists(c + "bonded");
  const auto bonded = has_bonds ? ivec("bonded", 1) : std::vector<std::int64_t>(nc, 0);
  const auto bond_area = has_bonds ? checkpoint_table(r, c + "bond_area", nc, 1) : std::vector<double>(nc, 0.0);
  // Glue: none in files written before it (nothing was glued then).
  const auto glued = r.exists(c + "glued") ? ivec("glued", 1) : std::vector<std::int64_t>(nc, 0);
  for (std::size_t k = 0; k < nc; ++k) {
    Contact3 x;
    x.i = static_cast<int>(ci[k]);
    x.j = static_cast<int>(cj[k]);
    if (kind[k] < 0 || kind[k] > 1) r.fail("dataset " + c + "kind holds an unknown contact kind");
    x.kind = static_cast<ContactKind3>(kind[k]);
    for (int q = 0; q < 4; ++q) x.ids[q] = static_cast<int>(ids[4 * k + static_cast<std::size_t>(q)]);
    if (state[k] < 0 || state[k] > 2) r.fail("dataset " + c + "state holds an unknown contact state");
    x.state = static_cast<ContactState3>(state[k]);
    x.joint = static_cast<int>(joint[k]);
    x.ref_j = row3(ref_j, k);
    x.point_now = row3(point_now, k);
    x.slip_dir = row2(slip_dir, k);
    x.slip = row2(slip, k);
    x.normal_force = normal_force[k];
    x.bonded = bonded[k] != 0;
    x.bond_area = bond_area[k];
    x.glued = glued[k] != 0;
    x.shear_force = row2(shear, k);
    x.strength = strength[k];
    x.slip_velocity = slip_velocity[k];
    x.slip_axis = row3(slip_axis, k);
    x.geo.normal = row3(normal, k);
    x.geo.t1 = row3(t1, k);
    x.geo.t2 = row3(t2, k);
    x.geo.point_i = row3(pi, k);
    x.geo.point_j = row3(pj, k);
    x.friction = df::FrictionState::from_vector(std::move(friction[k]));
    s.contacts.push_back(std::move(x));
  }

  s.fixed_at = read_points3(r, "/checkpoint/points/fixed_position");
  s.load_at = read_points3(r, "/checkpoint/points/load_position");
  s.measure_at = read_points3(r, "/checkpoint/points/measurement_position");
  s.solver_warm_start = df::h5io::read_warm_start(r, "/checkpoint");
  if (r.exists("/checkpoint/bolts")) s.bolts = df::h5io::read_bolt_states<3>(r, "/checkpoint/bolts/");
  return s;
}

}  // namespace dda::df3
