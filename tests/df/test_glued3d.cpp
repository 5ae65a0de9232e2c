// Glued artificial cuts in 3D (Contact3::glued, on_artificial_cut3;
// docs/solver3d.md "Glued artificial cuts"): two parts of one rock body
// that DC split around an excavation meet on faces of set kArtificialSet
// (-3). Their contacts stay locked with both springs on whatever the
// forces, so the parts move as one body on the springs' stretch; the same
// faces as an ordinary joint open and slide. Each test compares with a hand
// number.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include "dda/df/io/results3d.hpp"
#include "df_io_test_models3d.hpp"
#include "df_test_models3d.hpp"

namespace dda::df3 {
namespace {

using testing::box;

constexpr double kDeg = std::numbers::pi / 180;
constexpr double kRho = 2600, kG = 9.81, kPn = 1e9;
// Faces of testing::box: 0 bottom (z = lo), 1 top (z = hi).
constexpr int kBottom = 0, kTop = 1;

struct Tally {
  int glued = 0, locked = 0, closed = 0;
};

Tally tally(const Simulation3& sim) {
  Tally t;
  for (const Contact3& c : sim.contacts()) {
    t.glued += c.glued ? 1 : 0;
    t.locked += c.state == ContactState3::Locked ? 1 : 0;
    t.closed += c.state != ContactState3::Open ? 1 : 0;
  }
  return t;
}

// ---- A 1 m cube hanging under a fixed 1 m cube, face on face.

// The two cubes meet corner to corner on z = 0: every corner of the cut also
// lies on the side faces of both, where the contact must still be the cut's.
// `upper`, `lower`: the sets of the fixed block's bottom and the cube's top.
// W = rho g (1 m^3) = 25506 N.
Model3 hanging_cube(int upper, int lower, bool initial_equilibrium) {
  Model3 m;
  m.blocks = {box({-0.5, -0.5, 0}, {0.5, 0.5, 1}), box({-0.5, -0.5, -1}, {0.5, 0.5, 0})};
  m.blocks[0].faces[kBottom].set = upper;
  m.blocks[1].faces[kTop].set = lower;
  m.fixed = {true, false};
  m.materials = {{kRho, 1e10, 0.25}};
  m.joint_sets = {df::JointProperties{}};  // set 0: friction 30 degrees, no tension (the defaults)
  m.default_joint.friction_deg = 30;
  m.normal_penalty = m.shear_penalty = kPn;
  m.contact_reach = 0.01;
  m.control.initial_equilibrium = initial_equilibrium;
  return m;
}

// Glued, the cube hangs on its four corner springs, each pulled by W / 4:
// at rest each contact's normal force is -W / 4 = -6376.5 N and the cube's
// top lies W / (4 pn) = 6.3765e-6 m below the fixed block (the gap of a
// corner spring at that force). DC tags one side of an excavation's cut
// artificial and the other an excavation face (-2): each way round is
// glued. As a joint of set 0 (no tensile strength) the faces open and the
// cube falls freely, z = -g t^2 / 2.
TEST(Glued3, CubeHangsOnItsGluedSpringsAndFallsOffAJoint) {
  const double w = kRho * kG, t = 0.2, dt = 1e-3;
  EXPECT_NEAR(w / (4 * kPn), 6.3765e-6, 1e-10);  // the number in the comment
  struct Case {
    int upper, lower;
  };
  for (const Case k : {Case{kArtificialSet, kArtificialSet}, Case{kExcavationSet, kArtificialSet},
                       Case{kArtificialSet, kExcavationSet}}) {
    SCOPED_TRACE(::testing::Message() << "sets " << k.upper << " / " << k.lower);
    Simulation3 sim(hanging_cube(k.upper, k.lower, true));
    sim.start();
    for (int s = 0; s < static_cast<int>(std::lround(t / dt)); ++s) sim.step(dt);
    const Tally n = tally(sim);
    EXPECT_EQ(n.glued, 4);
    EXPECT_EQ(n.locked, 4);
    EXPECT_EQ(sim.glued_contacts(), 4);
    double top = -1e300;  // the cube's highest corner
    for (const Vec3& v : sim.blocks()[1].vertices) top = std::max(top, v.z());
    std::printf("glued: top at %.6e m (hand %.6e), normal forces", top, -w / (4 * kPn));
    for (const Contact3& c : sim.contacts()) {
      std::printf(" %.3f", c.normal_force);
      EXPECT_NEAR(c.normal_force, -w / 4, 1e-6 * w) << "contact at " << c.geo.point_i.transpose();
      EXPECT_EQ(c.joint, sim.model().glue_joint());
    }
    std::printf(" N (hand %.3f)\n", -w / 4);
    EXPECT_NEAR(top, -w / (4 * kPn), 1e-3 * w / (4 * kPn));
  }
  Simulation3 joint(hanging_cube(0, 0, true));
  joint.start();
  const double z0 = joint.blocks()[1].centroid.z();
  for (int s = 0; s < static_cast<int>(std::lround(t / dt)); ++s) joint.step(dt);
  const double fall = -0.5 * kG * t * t, dz = joint.blocks()[1].centroid.z() - z0;
  std::printf("joint: dz = %.6f m (hand %.6f)\n", dz, fall);
  EXPECT_NEAR(dz, fall, 1e-3 * std::abs(fall));
  EXPECT_EQ(tally(joint).glued, 0);
  EXPECT_EQ(tally(joint).closed, 0);
}

// The hanging cube shifted by half a side along x and y under the fixed
// one: the faces overlap on a 0.5 m square whose corners are a corner of
// each cube inside the other's face (vertex-face) and two crossings of their
// edges (edge-edge). All four are on the cut and glued; the cube, its weight
// off the square's centre, hangs on them tilted, from equilibrium at
// t = 0 without moving (< 1e-9 m in 0.1 s), the normal forces summing to
// -W = -25506 N (vertical balance; the moment makes them unequal) within
// 2e-6 W (measured 1e-6 W: the start-up stops when a static solve moves
// less than 1e-9 of the model's size).
TEST(Glued3, EdgeCrossingsOnTheCutAreGluedToo) {
  Model3 m = hanging_cube(kArtificialSet, kArtificialSet, true);
  m.blocks[1] = box({0, 0, -1}, {1, 1, 0});
  m.blocks[1].faces[kTop].set = kArtificialSet;
  Simulation3 sim(m);
  sim.start();
  const Vec3 c0 = sim.blocks()[1].centroid;
  for (int s = 0; s < 100; ++s) sim.step(1e-3);
  int edge_pairs = 0;
  double normal = 0;
  for (const Contact3& c : sim.contacts()) {
    edge_pairs += c.glued && c.kind == ContactKind3::EdgeEdge ? 1 : 0;
    normal += c.normal_force;
  }
  const double moved = (sim.blocks()[1].centroid - c0).norm();
  std::printf("offset cube: %d glued (%d edge-edge), normal forces sum %.4f N (hand %.4f), moved %.2e m\n",
              sim.glued_contacts(), edge_pairs, normal, -kRho * kG, moved);
  EXPECT_EQ(sim.glued_contacts(), 4);
  EXPECT_EQ(tally(sim).locked, 4);
  EXPECT_EQ(edge_pairs, 2);
  EXPECT_NEAR(normal, -kRho * kG, 2e-6 * kRho * kG);
  EXPECT_LT(moved, 1e-9);
}

// Two parts of different bodies meeting on artificial faces are not one
// piece of rock (the rule asks for the same Polyhedron::body): not glued.
TEST(Glued3, PartsOfDifferentBodiesAreNotGlued) {
  Model3 m = hanging_cube(kArtificialSet, kArtificialSet, true);
  m.blocks[1].body = 1;
  Simulation3 sim(m);
  sim.start();
  sim.step(1e-3);
  EXPECT_EQ(sim.glued_contacts(), 0);
  EXPECT_EQ(tally(sim).closed, 0);  // the default joint holds no tension: the cube lets go
}

// ---- A slab on a cut steeper than the joint's friction angle.

// A 1 x 1 x 0.1 m slab (W = rho g 0.1 m^3 = 2551 N) on a fixed base, the
// plane dipping 30 degrees, friction 10 degrees on the faces' set 0 and on
// the default joint (the one an unglued artificial face would get). On
// artificial faces it is glued: it does not move after the start-up
// (< 1e-9 m in 0.5 s), and its four springs carry the weight, normal
// forces summing to W cos 30 = 2208.9 N, shear forces to W sin 30 =
// 1275.3 N up the dip. On set 0 it slides as V1, s = g (sin a - cos a
// tan phi) t^2 / 2 = 0.425872 m at 0.5 s, within 0.1 %.
struct Slide {
  double down_dip = 0, normal = 0, shear = 0;  // m; N summed over the contacts (shear along the dip)
  Tally n;
};

Slide slab_on_plane(int set, double t_end) {
  const Matrix3d r = testing::plane_rotation(30, 90);
  Model3 m;
  m.blocks = {box({-5, -5, -1}, {5, 5, 0}, r), box({-0.5, -0.5, 0}, {0.5, 0.5, 0.1}, r)};
  m.blocks[0].faces[kTop].set = set;
  m.blocks[1].faces[kBottom].set = set;
  m.fixed = {true, false};
  m.materials = {{kRho, 1e10, 0.25}};
  df::JointProperties joint;
  joint.friction_deg = 10;
  m.joint_sets = {joint};
  m.default_joint = joint;
  m.normal_penalty = m.shear_penalty = kPn;
  m.contact_reach = 0.01;
  m.control.initial_equilibrium = true;
  Simulation3 sim(m);
  sim.start();
  const Vec3 c0 = sim.blocks()[1].centroid;
  const double dt = 1e-3;
  for (int s = 0; s < static_cast<int>(std::lround(t_end / dt)); ++s) sim.step(dt);
  Slide out;
  const Vec3 dip = r * Vec3(1, 0, 0);
  out.down_dip = (sim.blocks()[1].centroid - c0).dot(dip);
  for (const Contact3& c : sim.contacts()) {
    out.normal += c.normal_force;
    // The shear force on the slab (block i or j) along the dip, in world axes.
    const Vec3 on_i = c.geo.t1 * c.shear_force.x() + c.geo.t2 * c.shear_force.y();
    out.shear += (c.i == 1 ? 1.0 : -1.0) * on_i.dot(-dip);
  }
  out.n = tally(sim);
  return out;
}

TEST(Glued3, SlabOnAGluedCutHoldsAndOnAJointSlides) {
  const double a = 30 * kDeg, phi = 10 * kDeg, t = 0.5;
  const double w = kRho * kG * 0.1;
  EXPECT_NEAR(w * std::cos(a), 2208.9, 0.05);  // the numbers in the comment
  EXPECT_NEAR(w * std::sin(a), 1275.3, 0.05);
  const Slide glued = slab_on_plane(kArtificialSet, t);
  std::printf("glued: moved %.3e m, N %.4f (hand %.4f), S %.4f (hand %.4f), glued %d, locked %d\n", glued.down_dip,
              glued.normal, w * std::cos(a), glued.shear, w * std::sin(a), glued.n.glued, glued.n.locked);
  EXPECT_LT(std::abs(glued.down_dip), 1e-9);
  EXPECT_EQ(glued.n.glued, 4);
  EXPECT_EQ(glued.n.locked, 4);
  EXPECT_NEAR(glued.normal, w * std::cos(a), 1e-6 * w);
  EXPECT_NEAR(glued.shear, w * std::sin(a), 1e-6 * w);
  const Slide joint = slab_on_plane(0, t);
  const double v1 = 0.5 * kG * (std::sin(a) - std::cos(a) * std::tan(phi)) * t * t;
  EXPECT_NEAR(v1, 0.425872, 1e-6);
  std::printf("joint: moved %.6f m (V1 %.6f), sliding contacts %d\n", joint.down_dip, v1,
              static_cast<int>(joint.n.closed - joint.n.locked));
  EXPECT_NEAR(joint.down_dip, v1, 1e-3 * v1);
  EXPECT_EQ(joint.n.glued, 0);
}

// ---- The energy ledger with glued springs.

// The 1 m cube hanging under a wider fixed block (2 x 2 m: each of the
// cube's top corners lies inside the block's face, one contact each),
// started at rest and pulled down by a load growing at 0.4 W/s for 0.25 s.
// Glued, its springs store what gravity and the load do: the ledger's
// residual stays below 1e-3 of the energy moved (the bonds' pulled cube
// measured 2e-4; here 2.3e-4), and the contact springs end with
// (W + F)^2 / 8 pn = 0.09840 J in the normal springs at F = 0.1 W
// (W + F = 28057 N shared by four corners), plus what the shear springs
// take from the cube's contraction under the pull (measured +0.07 %). The same cube
// held by a bond that cannot break (cohesion and tensile strength 1e12
// Pa) has the same springs in the same states: its ledger is the glued
// one's, record for record, to the bit.
Model3 pulled_cube(bool glued) {
  const double w = kRho * kG;
  Model3 m;
  m.blocks = {box({-1, -1, 0}, {1, 1, 1}), box({-0.5, -0.5, -1}, {0.5, 0.5, 0})};
  const int set = glued ? kArtificialSet : 0;
  m.blocks[0].faces[kBottom].set = set;
  m.blocks[1].faces[kTop].set = set;
  m.fixed = {true, false};
  m.materials = {{kRho, 1e10, 0.25}};
  df::JointProperties bond;
  bond.cohesion = bond.tensile_strength = 1e12;
  m.joint_sets = {bond};
  m.default_joint.friction_deg = 30;
  m.normal_penalty = m.shear_penalty = kPn;
  m.contact_reach = 0.01;
  m.loads = {{1, Vec3(0, 0, -0.5), TimeHistory3{{0.0, 1.0}, {Vec3::Zero(), Vec3(0, 0, -0.4 * w)}}}};
  m.control.dt = 1e-3;
  m.control.steps = 250;
  return m;
}

TEST(Glued3, LedgerBalancesWithGluedSprings) {
  const double w = kRho * kG, pull = w + 0.1 * w;
  const double hand = pull * pull / (8 * kPn);
  EXPECT_NEAR(hand, 0.09840, 5e-6);  // the number in the comment
  Simulation3 glued(pulled_cube(true)), bonded(pulled_cube(false));
  for (Simulation3* s : {&glued, &bonded})
    while (!s->finished()) s->advance();
  EXPECT_EQ(glued.glued_contacts(), 4);
  EXPECT_EQ(tally(bonded).glued, 0);
  const std::vector<df::EnergyRecord>& log = glued.energy_log();
  double worst = 0;
  for (std::size_t k = 1; k < log.size(); ++k)
    worst = std::max(worst, std::abs(log[k].residual) / df::energy_moved(log.front(), log[k]));
  std::printf("glued ledger: |residual| / energy moved <= %.2e; contact springs %.6f J at the end (hand %.6f, %+.2e)\n",
              worst, log.back().contact, hand, log.back().contact / hand - 1);
  EXPECT_LT(worst, 1e-3);
  EXPECT_GE(log.back().contact, hand);
  EXPECT_NEAR(log.back().contact, hand, 2e-3 * hand);
  ASSERT_EQ(log.size(), bonded.energy_log().size());
  for (std::size_t k = 0; k < log.size(); ++k) {
    const df::EnergyRecord& b = bonded.energy_log()[k];
    EXPECT_EQ(log[k].contact, b.contact) << "record " << k;
    EXPECT_EQ(log[k].elastic, b.elastic) << "record " << k;
    EXPECT_EQ(log[k].residual, b.residual) << "record " << k;
  }
}

// ---- Checkpoint.

// The hanging cube pulled down by a load growing to 2 W over 1 s, stopped
// at step 50 of 100, written, read and resumed: the glue is in the
// checkpoint (`glued`), and the resumed run ends bit for bit where the
// uninterrupted one does, still glued.
TEST(Glued3, ResumedRunStaysGluedBitForBit) {
  Model3 model = hanging_cube(kArtificialSet, kExcavationSet, true);
  model.loads = {{1, Vec3(0, 0, -0.5), TimeHistory3{{0.0, 1.0}, {Vec3::Zero(), Vec3(0, 0, -2 * kRho * kG)}}}};
  model.control.dt = 1e-3;
  model.control.steps = 100;
  PolyhedronModel blocks;
  blocks.blocks = model.blocks;
  for (Polyhedron& b : blocks.blocks) refresh_geometry(b), b.body = -1;
  const testing::WholeAndResumed3 runs = testing::run_whole_and_resumed3(model, blocks, 50, "glued3d");
  int glued = 0;
  for (const Contact3& c : runs.saved.checkpoint->contacts) glued += c.glued ? 1 : 0;
  EXPECT_EQ(glued, 4);
  const Simulation3 &a = *runs.whole, &b = *runs.resumed;
  EXPECT_EQ(a.glued_contacts(), 4);
  for (std::size_t i = 0; i < a.blocks().size(); ++i) EXPECT_EQ(a.blocks()[i].vertices, b.blocks()[i].vertices);
  ASSERT_EQ(a.contacts().size(), b.contacts().size());
  for (std::size_t k = 0; k < a.contacts().size(); ++k) {
    EXPECT_EQ(a.contacts()[k].glued, b.contacts()[k].glued);
    EXPECT_EQ(a.contacts()[k].normal_force, b.contacts()[k].normal_force);
  }
  EXPECT_EQ(a.energy_log().back().residual, b.energy_log().back().residual);
}

}  // namespace
}  // namespace dda::df3
