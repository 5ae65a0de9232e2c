// Contact geometry: the sign convention (penetration negative, docs/formulation.md
// "Contacts"), the linearisation of dn, the entrance-edge rule for
// vertex-vertex contacts, and the broad phase. Expected values are worked by
// hand in the comments.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>

#include "df_test_models.hpp"
#include "forced_threads.hpp"
#include "dda/df/2d/block_kinematics.hpp"
#include "dda/df/core/block_system.hpp"
#include "dda/df/core/broad_phase.hpp"
#include "dda/df/2d/contact.hpp"
#include "dda/df/2d/contact_detection.hpp"
#include "dda/df/core/friction.hpp"

namespace dda::df {
namespace {

using test::rectangle;

TEST(ContactSign, PenetrationIsNegative) {
  // Unit square [0,1]^2; its top edge runs (1,1) -> (0,1) (edge 2, CCW).
  const Polygon2 sq = rectangle(0, 0, 1, 1);
  EXPECT_NEAR(signed_distance({0.5, 1.2}, sq[2], sq[3]), 0.2, 1e-15);    // above: outside
  EXPECT_NEAR(signed_distance({0.5, 0.9}, sq[2], sq[3]), -0.1, 1e-15);   // below: inside
  EXPECT_NEAR(signed_distance({0.5, -0.3}, sq[0], sq[1]), 0.3, 1e-15);   // under the bottom edge
}

TEST(ContactSign, DetectedRestingContactHasNegativeDn) {
  // A 1x1 block sunk 1 mm into a 3x1 base: its two bottom vertices touch the
  // base's top edge (edge 2) with dn = -0.001.
  const std::vector<Polygon2> blocks{rectangle(-1, -1, 3, 1), rectangle(0, -0.001, 1, 1)};
  const auto found = find_contacts(blocks, {{0, 1}}, 0.01);
  ASSERT_EQ(found.size(), 2u);
  for (const ContactCandidate& c : found) {
    EXPECT_EQ(c.vblock, 1);
    EXPECT_EQ(c.eblock, 0);
    EXPECT_EQ(c.edge, 2);
    EXPECT_NEAR(c.dn, -0.001, 1e-12);
    EXPECT_FALSE(c.vertex_vertex);
  }
}

TEST(ContactGeometry, LinearisedDistanceMatchesMovedGeometry) {
  // dn0 + en.di + gn.dj against the exact distance after moving both blocks
  // by small increments. The linearisation holds the edge length l at its
  // start value (classic DDA), so the error is |d|^2 plus dn0 * dl / l:
  // second order for a contact that is nearly closed (dn0 = 0.5 mm here).
  const Polygon2 base = rectangle(-1, -1, 3, 1);
  const Polygon2 top = rectangle(0.2, 0.0005, 1, 0.5);
  const Vec2 cb = block_geometry(base).centroid, ct = block_geometry(top).centroid;
  Vector6d di, dj;
  di << 1e-4, -2e-4, 3e-4, 1e-4, -2e-4, 5e-5;
  dj << -1e-4, 1e-4, -2e-4, 2e-4, 1e-4, -1e-4;
  for (int v = 0; v < 2; ++v) {
    const ContactGeometry g = contact_geometry(top, ct, base, cb, v, 2, 0.5);
    const Vec2 p = top[v] + t_matrix(ct, top[v]) * di;
    const Vec2 a = base[2] + t_matrix(cb, base[2]) * dj, b = base[3] + t_matrix(cb, base[3]) * dj;
    const double exact = signed_distance(p, a, b);
    const double linear = g.dn0 + g.en.dot(di) + g.gn.dot(dj);
    EXPECT_NEAR(linear, exact, 1e-6) << "vertex " << v;  // |d|^2 ~ 1e-7
    EXPECT_GT(std::abs(linear - g.dn0), 1e-5);  // the increments do change dn
    EXPECT_NEAR(g.dn0, 0.0005, 1e-15);
  }
}

TEST(ContactGeometry, GradientsAreTTransposeAtTheirPoints) {
  // The geometry keeps three of its gradients as arms from a centroid. Each
  // must be T^T t of the right block at the right point, by the definitions
  // in contact.hpp, here formed from t_matrix (not from the arms): es at the
  // vertex P of block i; gc at P's projection Pc on the edge of block j; gs
  // at the shear reference P0 = A + ref_ratio (B - A) on block j, and at Pc
  // once the reference is moved there. And en = T_i(P)^T n.
  const Polygon2 base = rectangle(-1, -1, 3, 1);
  const Polygon2 top = rectangle(0.2, 0.0005, 1, 0.5);
  const Vec2 cb = block_geometry(base).centroid, ct = block_geometry(top).centroid;
  const Vec2 a = base[2], b = base[3];  // the top edge runs from (2, 0) to (-1, 0)
  const Vec2 t = (b - a).normalized(), n(t.y(), -t.x());
  for (int v = 0; v < 2; ++v) {
    ContactGeometry g = contact_geometry(top, ct, base, cb, v, 2, 0.3);
    const Vec2 p = top[v];
    const Vec2 pc = a + (p - a).dot(t) * t, p0 = a + 0.3 * (b - a);
    auto tt = [](const Vec2& c, const Vec2& at, const Vec2& f) -> Vector6d {
      return t_matrix(c, at).transpose() * f;
    };
    EXPECT_LT((g.es() - tt(ct, p, t)).norm(), 1e-14) << v;
    EXPECT_LT((g.gc() + tt(cb, pc, t)).norm(), 1e-14) << v;
    EXPECT_LT((g.gs() + tt(cb, p0, t)).norm(), 1e-14) << v;
    EXPECT_LT((g.en - tt(ct, p, n)).norm(), 1e-14) << v;
    EXPECT_GT((g.gs() - g.gc()).norm(), 0.05) << v;  // P0 and Pc lie 0.1 m or more apart here
    g.reference_at_projection();
    EXPECT_EQ(g.gs(), g.gc()) << v;
  }
}

// The terms tests' contact: the lower-left corner of a block (1) pressed
// 0.5 mm into the top face of a larger one (0), its shear reference at 0.4
// of that face.
Contact corner_on_face() {
  const Polygon2 base = rectangle(-1, -1, 3, 1), top = rectangle(0.2, -0.0005, 1, 0.5);
  Contact c;
  c.vblock = 1;
  c.vertex = 0;
  c.eblock = 0;
  c.edge = 2;
  c.geo = contact_geometry(top, block_geometry(top).centroid, base, block_geometry(base).centroid, 0, 2, 0.4);
  return c;
}

// An empty system of the two blocks, their coupling declared.
BlockSystem two_block_system() {
  BlockSystem sys;
  sys.reset(2, {{1, 0}});
  return sys;
}

TEST(ContactTerms, SpringsAndForcesAddUpAndSpringsComeOutAgain) {
  // The open-close iteration assembles a contact's springs and forces in
  // two parts, and swaps the springs of a contact that changed state by
  // taking out the old ones (weight -1): the system must come out as if
  // assembled afresh, to rounding.
  Contact c = corner_on_face();
  c.state = ContactState::Locked;
  const auto friction = make_friction_law(JointProperties{});
  const ContactLaw law{1e9, 4e8, 0, friction.get(), 1e-9};
  auto system = [] {
    BlockSystem sys = two_block_system();
    for (int i = 0; i < 2; ++i) sys.diagonal(i) = 1e6 * Matrix6d::Identity();
    return sys;
  };
  BlockSystem whole = system(), parts = system(), swapped = system();
  add_contact_terms(c, law, 1e-3, whole);
  add_contact_springs(c, law, 1.0, parts);
  add_contact_forces(c, law, 1e-3, parts);
  EXPECT_EQ(Eigen::MatrixXd(whole.full()), Eigen::MatrixXd(parts.full()));
  EXPECT_EQ(whole.rhs(), parts.rhs());
  // Locked, then sliding: out with the locked springs, in with the sliding one.
  add_contact_springs(c, law, 1.0, swapped);
  add_contact_springs(c, law, -1.0, swapped);
  c.state = ContactState::Sliding;
  add_contact_springs(c, law, 1.0, swapped);
  BlockSystem fresh = system();
  add_contact_springs(c, law, 1.0, fresh);
  const Eigen::MatrixXd k = Eigen::MatrixXd(fresh.full());
  EXPECT_LE((Eigen::MatrixXd(swapped.full()) - k).norm(), 1e-14 * k.norm());
  EXPECT_GT((Eigen::MatrixXd(whole.full()) - k).norm(), 1e-3 * k.norm());  // the shear spring did count
}

TEST(ContactTerms, ForcesUpdatedInPlaceMatchForcesFormedAfresh) {
  // Between open-close iterates F is updated, not formed again
  // (Simulation::reassemble): a sliding contact whose normal force changed
  // adds the change of its friction, and a contact that changed state takes
  // its old forces out and puts its new ones in. F must come out as if
  // formed afresh, to rounding.
  Contact c = corner_on_face();
  c.geo.ds0 = 2e-5;  // the locked spring is stretched: its force differs from the sliding friction
  c.state = ContactState::Sliding;
  c.slip_sign = -1;
  c.normal_force = 3e5;
  JointProperties joint;
  joint.friction_deg = 30;
  const auto friction = make_friction_law(joint);
  const ContactLaw law{1e9, 4e8, 0, friction.get(), 1e-9};
  const double dt = 1e-3;
  const auto system = two_block_system;
  auto relative = [](const BlockSystem& a, const BlockSystem& b) {
    return (a.rhs() - b.rhs()).norm() / b.rhs().norm();
  };

  // The friction as it goes into F: against the slip, tan(phi) N.
  const double f1 = friction_force(c, law, dt);
  EXPECT_NEAR(f1, -std::tan(deg2rad(30)) * 3e5, 1e-9 * 3e5);

  // The normal force changes: only the friction changes.
  BlockSystem updated = system();
  add_contact_forces(c, law, f1, 1.0, updated);
  c.normal_force = 2.5e5;
  const double f2 = friction_force(c, law, dt);
  add_friction_change(c, f2 - f1, updated);
  BlockSystem fresh = system();
  add_contact_forces(c, law, dt, fresh);
  EXPECT_LE(relative(updated, fresh), 1e-14);
  EXPECT_GT(relative(system(), fresh), 0.5);  // F is not empty: the comparison can fail

  // Sliding -> locked: out with the sliding forces, in with the locked ones.
  Contact locked = c;
  locked.state = ContactState::Locked;
  add_contact_forces(c, law, f2, -1.0, updated);
  add_contact_forces(locked, law, friction_force(locked, law, dt), 1.0, updated);
  BlockSystem fresh_locked = system();
  add_contact_forces(locked, law, dt, fresh_locked);
  EXPECT_EQ(friction_force(locked, law, dt), 0.0);
  EXPECT_LE(relative(updated, fresh_locked), 1e-14);
  EXPECT_GT(relative(fresh, fresh_locked), 1e-3);  // the two states' forces differ
}

// The narrow phase found exactly one contact: vertex `vertex` of block
// `vblock` against edge `edge` of block `eblock`, at signed distance dn.
void expect_one_contact(const std::vector<ContactCandidate>& found, int vblock, int vertex, int eblock, int edge,
                        double dn) {
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].vblock, vblock);
  EXPECT_EQ(found[0].vertex, vertex);
  EXPECT_EQ(found[0].eblock, eblock);
  EXPECT_EQ(found[0].edge, edge);
  EXPECT_NEAR(found[0].dn, dn, 1e-12);
}

// A step's attempt updates the contacts in place; one thrown away puts back
// what the iteration changed (ContactIterationState). Through updates that
// close, lock, slide, stick and break a bond, restoring must give the
// contact back exactly, every field of it: a field update_contact writes
// and the saved state leaves out would make a redone step start from the
// thrown-away attempt. (A new field of Contact belongs in `same` below.)
TEST(ContactIterationState, RestoringUndoesEveryUpdate) {
  auto same = [](const Contact& a, const Contact& b) {
    const ContactGeometry &g = a.geo, &h = b.geo;
    return a.vblock == b.vblock && a.vertex == b.vertex && a.eblock == b.eblock && a.edge == b.edge &&
           a.joint == b.joint && a.state == b.state && a.ref_ratio == b.ref_ratio && a.slip_sign == b.slip_sign &&
           a.normal_force == b.normal_force && a.shear_force == b.shear_force &&
           a.slip_velocity == b.slip_velocity && a.friction_settled == b.friction_settled && a.length == b.length &&
           a.bonded == b.bonded && a.broke == b.broke && a.glued == b.glued &&
           a.friction.theta == b.friction.theta && a.friction.slip == b.friction.slip &&
           a.friction.extra == b.friction.extra && g.length == h.length && g.tangent == h.tangent &&
           g.dn0 == h.dn0 && g.en == h.en && g.gn == h.gn && g.ratio0 == h.ratio0 && g.ds0 == h.ds0 &&
           g.es() == h.es() && g.gs() == h.gs() && g.gc() == h.gc();
  };
  JointProperties joint;
  joint.friction_deg = 30;
  joint.cohesion = 1e5;
  joint.tensile_strength = 1e5;
  const auto friction = make_friction_law(joint);
  const ContactLaw law{1e9, 4e8, joint.tensile_strength, friction.get(), 1e-9};
  std::mt19937 rng(5);
  std::normal_distribution<double> u(0, 1);
  int changed = 0, states_seen[3] = {0, 0, 0};
  for (const ContactState start : {ContactState::Open, ContactState::Locked, ContactState::Sliding}) {
    for (const bool bonded : {false, true}) {
      for (int trial = 0; trial < 40; ++trial) {
        Contact c = corner_on_face();
        c.state = start;
        c.bonded = bonded;
        c.length = 0.5;
        c.slip_sign = start == ContactState::Sliding ? 1 : 0;
        c.geo.ds0 = 1e-6 * u(rng);
        c.normal_force = 1e5 * std::abs(u(rng));
        c.friction.slip = 0.01;
        const Contact before = c;
        const ContactIterationState saved = iteration_state(c);
        const double scale = std::pow(10.0, -6 + trial % 4);  // from 1 um to 1 mm
        const Vector6d di = scale * Vector6d::NullaryExpr([&] { return u(rng); });
        const Vector6d dj = scale * Vector6d::NullaryExpr([&] { return u(rng); });
        c.state = update_contact(c, law, 1e-3, di, dj, trial % 5 == 0);
        ++states_seen[static_cast<int>(c.state)];
        changed += !same(c, before);
        restore_iteration_state(c, saved);
        EXPECT_TRUE(same(c, before)) << "from " << to_string(start) << (bonded ? ", bonded" : "") << ", trial "
                                     << trial;
      }
    }
  }
  // The updates did change the contacts, into every state.
  EXPECT_GT(changed, 200);
  for (const int n : states_seen) EXPECT_GT(n, 0);
}

TEST(EntranceEdge, VertexEntersThroughTopEdge) {
  // Block j: unit square; corner Q = (1,1). Block i: a diamond whose lowest
  // vertex P = (0.999, 0.9995) is 0.5 mm below the top face and 1 mm left of
  // the right face. Its edges rise at +-45 degrees, so it can only have come
  // through the top edge (the right-face candidate is inadmissible: the
  // diamond's left edge would cross it). Expected: P against edge 2 (top),
  // dn = -0.0005.
  const Vec2 p(0.999, 0.9995);
  const Polygon2 diamond{p, p + Vec2(0.5, 0.5), p + Vec2(0, 1), p + Vec2(-0.5, 0.5)};
  const std::vector<Polygon2> blocks{rectangle(0, 0, 1, 1), diamond};
  const auto found = find_contacts(blocks, {{0, 1}}, 0.01);
  expect_one_contact(found, 1, 0, 0, 2, -0.0005);
  if (!found.empty()) {
    EXPECT_TRUE(found[0].vertex_vertex);
  }
}

TEST(EntranceEdge, VertexEntersThroughSideEdge) {
  // Same square; block i now has its corner P = (0.9995, 0.999) with edges
  // going right (+x) and up-right, i.e. a block lying to the right. P is
  // 0.5 mm inside the right face and 1 mm below the top face: it came in
  // through the right edge (edge 1, (1,0) -> (1,1)), the smaller
  // penetration, with dn = -0.0005.
  const Vec2 p(0.9995, 0.999);
  const Polygon2 wedge{p, p + Vec2(1, 0), p + Vec2(1, 1)};
  const std::vector<Polygon2> blocks{rectangle(0, 0, 1, 1), wedge};
  const auto found = find_contacts(blocks, {{0, 1}}, 0.01);
  expect_one_contact(found, 1, 0, 0, 1, -0.0005);
}

TEST(EntranceEdge, FarBlocksHaveNoContact) {
  const std::vector<Polygon2> blocks{rectangle(0, 0, 1, 1), rectangle(1.5, 0, 1, 1)};
  EXPECT_TRUE(find_contacts(blocks, {{0, 1}}, 0.1).empty());
}

// A thin wedge (3.5 x 23 m, 8.8 degrees) that a vertical joint cuts off a
// sloping cliff face, resting on the block below it (coordinates of the
// site_response example's mesh, which threw it off at 38 m/s before the
// fix): its bottom-right vertex lies on the lower block's top edge, 0.52 m
// past the end of the lower block's short slanted edge, whose line it is
// 3.46 m "inside". With a search distance of 8.75 m that edge is within
// reach; the contact must be with the top edge, in exact touch, never with
// the slanted one.
TEST(EntranceEdge, VertexBesideAShortEdgeIsNotAPenetrationOfIt) {
  const std::vector<Polygon2> blocks{
      {{954.177, 319.52}, {987.937, 319.52}, {987.937, 364.607}, {954.691, 364.607}, {954.177, 361.179}},
      {{954.691, 364.607}, {958.187, 364.607}, {958.187, 387.916}}};
  const auto found = find_contacts(blocks, {{0, 1}}, 8.75);
  ASSERT_FALSE(found.empty());
  for (const ContactCandidate& c : found)
    EXPECT_GT(c.dn, -1e-6) << c.vblock << "/" << c.vertex << " on " << c.eblock << "/" << c.edge;
}

// A block with a 9 mm arm (an L: a bed boundary 9 mm above a tunnel roof
// left a sliver of the bed below fused to the block at the wall; a
// 192k-block tunnel model's mesh, coordinates in m) and the block above
// resting on the arm: the arm's top edge and the upper block's bottom edge
// overlap by 6 mm, from the arm's top-left corner A = (294.69801, 129.00913)
// to the upper block's bottom-right corner P = (294.70397, 129.00913). With
// the model's search distance of 25 mm, P is within reach of both ends of
// the arm's 9 mm end edge (edge 3, x = 294.69801) and 6 mm "inside" its
// line; a contact with it put 33 MN on the arm in the first step and the
// roof blocks flew at 2 m/s. P is nearer to the arm's top edge (0 mm) than
// to its end (6 mm), so it is in exact touch only. Expected: one contact,
// the pair P, A (6 mm apart) resolved to A on the upper block's bottom
// edge (edge 0) at dn = 0, the first of the tied exact touches.
TEST(EntranceEdge, CornerOnAThinArmIsNotAPenetrationOfTheArmsEnd) {
  const std::vector<Polygon2> blocks{{{295.0, 128.29518},
                                      {295.27006, 128.29518},
                                      {295.27006, 129.00913},
                                      {294.69801, 129.00913},
                                      {294.69801, 129.0},
                                      {295.0, 129.0}},
                                     {{293.44099, 129.00913},
                                      {294.70397, 129.00913},
                                      {294.70397, 130.64742},
                                      {293.44099, 130.64742}}};
  const auto found = find_contacts(blocks, {{0, 1}}, 0.025);
  expect_one_contact(found, 0, 3, 1, 0, 0.0);
}

// The other side of that rule: stacked unit squares pressed 0.1 mm into
// each other, corners over corners (a joint meeting a bed). The upper
// square's bottom corners lie on the lines of the lower one's side faces,
// at distance zero from them, yet could not touch them (the upper square
// would cross them): the top face keeps the contacts. Expected: one
// contact per corner pair, each between the two faces at dn = -1e-4.
TEST(EntranceEdge, CornersPressedIntoAFaceAtItsCornersKeepTheFace) {
  const std::vector<Polygon2> blocks{rectangle(0, 0, 1, 1), rectangle(0, 0.9999, 1, 1)};
  const auto found = find_contacts(blocks, {{0, 1}}, 0.01);
  ASSERT_EQ(found.size(), 2u);
  for (const ContactCandidate& c : found) {
    const bool faces = (c.eblock == 0 && c.edge == 2) || (c.eblock == 1 && c.edge == 0);
    EXPECT_TRUE(faces) << c.vblock << "/" << c.vertex << " on " << c.eblock << "/" << c.edge;
    EXPECT_NEAR(c.dn, -1e-4, 1e-12);
  }
}

TEST(EntranceEdge, VertexNearBothEndsOfAShortEdgeMakesOneContact) {
  // Block 0: unit square with its top-right corner chamfered by a 7 mm edge
  // (edge 2, from (1, 0.995) to (0.995, 1)). Block 1: a diamond whose lowest
  // vertex P = (0.999, 0.999) sits 2.1 mm outside the chamfer, 4.1 mm from
  // both of its ends. With a 10 mm search distance both ends pair with P as
  // vertex-vertex contacts, and both resolve to P against the chamfer (the
  // square's faces x = 1 and y = 1 are implausible: P is beside them, not in
  // the square). Expected: that contact once, dn = 0.003 / sqrt(2). Twice
  // would put its springs into K twice.
  const Vec2 p(0.999, 0.999);
  const std::vector<Polygon2> blocks{
      {{0, 0}, {1, 0}, {1, 0.995}, {0.995, 1}, {0, 1}},
      {p, p + Vec2(0.5, 0.1), p + Vec2(0.6, 0.6), p + Vec2(0.1, 0.5)}};
  const auto found = find_contacts(blocks, {{0, 1}}, 0.01);
  expect_one_contact(found, 1, 0, 0, 2, 0.003 / std::sqrt(2.0));
}

TEST(EntranceEdge, ShortEdgeRepeatsAreDroppedOnTheParallelPathToo) {
  // The chamfer case above 40 times over (pairs 3 m apart in x), on two
  // threads with every loop parallel: each block drops the repeat of its own
  // candidates, and the blocks' lists are closed up in parallel. Expected:
  // the single-thread list, one contact per pair (diamond 2q + 1, vertex 0,
  // against chamfer edge 2 of square 2q), sorted and without gaps.
  const Vec2 p(0.999, 0.999);
  std::vector<Polygon2> blocks;
  std::vector<std::pair<int, int>> pairs;
  for (int q = 0; q < 40; ++q) {
    const Vec2 at(3.0 * q, 0);
    blocks.push_back({at + Vec2(0, 0), at + Vec2(1, 0), at + Vec2(1, 0.995), at + Vec2(0.995, 1), at + Vec2(0, 1)});
    blocks.push_back({at + p, at + p + Vec2(0.5, 0.1), at + p + Vec2(0.6, 0.6), at + p + Vec2(0.1, 0.5)});
    pairs.emplace_back(2 * q, 2 * q + 1);
  }
  const auto serial = find_contacts(blocks, pairs, 0.01);
  std::vector<ContactCandidate> parallel;
  {
    const testing::ForcedThreads threads(2);
    parallel = find_contacts(blocks, pairs, 0.01);
  }
  ASSERT_EQ(serial.size(), 40u);
  ASSERT_EQ(parallel.size(), serial.size());
  for (int q = 0; q < 40; ++q) {
    const ContactCandidate& c = parallel[static_cast<std::size_t>(q)];
    EXPECT_EQ(std::tie(c.vblock, c.vertex, c.eblock, c.edge), std::make_tuple(2 * q + 1, 0, 2 * q, 2)) << q;
    EXPECT_EQ(c.dn, serial[static_cast<std::size_t>(q)].dn) << q;
  }
}

// The index of the last step's contacts: lookups by the full key and by
// (vertex block, vertex, edge block) within the vertex block's own keys, on
// contacts in any order, and the in-order key comparison that tells a model
// whose contacts are those of the last step.
struct Key {
  int vblock, vertex, eblock, edge;
};

TEST(ContactIndex, FindsEveryKeyWithinItsVertexBlock) {
  // Unsorted, with a repeated key (index 1 and 4: the later one is found)
  // and a vertex against two edges of one block (by_vertex: the later one).
  const std::vector<Key> contacts{{3, 1, 0, 2}, {0, 2, 1, 0}, {3, 1, 0, 1}, {0, 0, 5, 3}, {0, 2, 1, 0}, {7, 4, 3, 0}};
  const ContactIndex index(contacts);
  ASSERT_EQ(index.size(), 6u);
  EXPECT_EQ(index.exact(3, 1, 0, 2), 0);
  EXPECT_EQ(index.exact(3, 1, 0, 1), 2);
  EXPECT_EQ(index.exact(0, 2, 1, 0), 4);
  EXPECT_EQ(index.exact(0, 0, 5, 3), 3);
  EXPECT_EQ(index.exact(7, 4, 3, 0), 5);
  EXPECT_EQ(index.by_vertex(3, 1, 0), 2);
  EXPECT_EQ(index.by_vertex(0, 2, 1), 4);
  EXPECT_EQ(index.by_vertex(7, 4, 3), 5);
  // Absent: another edge, vertex or block; blocks with no contact, below the
  // first and beyond the last.
  EXPECT_EQ(index.exact(3, 1, 0, 3), -1);
  EXPECT_EQ(index.by_vertex(3, 2, 0), -1);
  EXPECT_EQ(index.by_vertex(0, 2, 2), -1);
  EXPECT_EQ(index.by_vertex(5, 0, 0), -1);
  EXPECT_EQ(index.by_vertex(-1, 0, 0), -1);
  EXPECT_EQ(index.exact(8, 0, 0, 0), -1);
  const ContactIndex empty{std::vector<Key>{}};
  EXPECT_EQ(empty.exact(0, 0, 0, 0), -1);
  EXPECT_EQ(empty.by_vertex(0, 0, 0), -1);
}

TEST(ContactIndex, SameKeysInOrderOnlyForTheContactsAsTheyStand) {
  auto candidate = [](int vb, int v, int eb, int e) {
    ContactCandidate c;
    c.vblock = vb;
    c.vertex = v;
    c.eblock = eb;
    c.edge = e;
    return c;
  };
  const std::vector<ContactCandidate> sorted{candidate(0, 1, 2, 0), candidate(1, 0, 0, 3), candidate(2, 2, 1, 1)};
  EXPECT_TRUE(ContactIndex(sorted).same_keys_in_order(sorted));
  auto fewer = sorted;
  fewer.pop_back();
  EXPECT_FALSE(ContactIndex(sorted).same_keys_in_order(fewer));
  auto other_edge = sorted;
  other_edge[1].edge = 2;
  EXPECT_FALSE(ContactIndex(sorted).same_keys_in_order(other_edge));
  // The same keys, but the contacts stand in another order: the candidates
  // (sorted) are not the contacts in place.
  const std::vector<ContactCandidate> shuffled{sorted[2], sorted[0], sorted[1]};
  EXPECT_FALSE(ContactIndex(shuffled).same_keys_in_order(sorted));
  {
    const testing::ForcedThreads threads(2);  // the parallel comparison
    EXPECT_TRUE(ContactIndex(sorted).same_keys_in_order(sorted));
    EXPECT_FALSE(ContactIndex(sorted).same_keys_in_order(other_edge));
  }
}

TEST(BroadPhase, SameAsBruteForce) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(0, 50), size(0.2, 3);
  std::vector<Box2> boxes;
  for (int i = 0; i < 400; ++i) {
    Box2 b;
    b.lo = {pos(rng), pos(rng)};
    b.hi = b.lo + Vec2(size(rng), size(rng));
    boxes.push_back(b);
  }
  boxes.push_back({{-5, -5}, {60, 0}});  // one huge block (a base)
  const double margin = 0.1;
  std::vector<std::pair<int, int>> brute;
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
    for (int j = i + 1; j < static_cast<int>(boxes.size()); ++j)
      if (boxes[i].lo.x() - margin <= boxes[j].hi.x() + margin && boxes[j].lo.x() - margin <= boxes[i].hi.x() + margin &&
          boxes[i].lo.y() - margin <= boxes[j].hi.y() + margin && boxes[j].lo.y() - margin <= boxes[i].hi.y() + margin)
        brute.emplace_back(i, j);
  EXPECT_EQ(broad_phase(boxes, margin), brute);
}

TEST(TributaryLength, FaceShareAndCorner) {
  // Bottom-left vertex of a 2 x 1 block on a horizontal edge: half the
  // bottom face counts, the vertical side does not.
  const Polygon2 r = rectangle(0, 0, 2, 1);
  EXPECT_NEAR(tributary_length(r, 0, Vec2(1, 0)), 1.0, 1e-15);
  EXPECT_NEAR(tributary_length(test::rotated(r, 0.7), 0, Vec2(1, 0)), 0.0, 1e-15);
}

}  // namespace
}  // namespace dda::df
