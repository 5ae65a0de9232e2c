#pragma once
// One vertex-edge contact: its persistent state, its linearised geometry for
// the current step, its springs and its open / sliding / locked decision.
//
// Normal: dn(d) = dn0 + en.d_i + gn.d_j (see contact_detection.hpp for the
// sign: penetration negative). A closed contact adds the penalty energy
// pn/2 dn^2, i.e. K += pn [en; gn][en; gn]^T, F -= pn dn0 [en; gn].
// Shear (locked only): ds(d) = ds0 + es.d_i + gs.d_j, the tangential offset
// of P1 from a reference point P0 fixed on the edge since the contact locked;
// energy ps/2 ds^2.
// Sliding: no shear spring; the friction force F_f (from the FrictionLaw,
// with the normal force of the previous iterate) acts on P1 against the slip
// direction, and the opposite force on the edge at the projection of P1.
#include "dda/df/2d/block_kinematics.hpp"
#include "dda/df/core/friction.hpp"
#include "dda/df/core/normal_law.hpp"
#include "dda/df/core/types.hpp"

namespace dda::df {

class BlockSystem;

enum class ContactState { Open, Sliding, Locked };
const char* to_string(ContactState s);

// Geometry of a contact in the configuration at the start of the step.
//
// Three of its five gradients are T^T t of a block at a point: they are
// kept as the point's arm from the block's centroid, two numbers instead of
// six, and formed when asked for, by the same arithmetic that formed them
// once (so the same numbers). A contact is then 336 bytes instead of 432:
// the pass that forms every contact's geometry each step writes that much
// less (a quarter of its time on a 50k-block model at rest), and a model's
// contacts take a fifth less memory. en is kept whole: formed from its arm
// it would cost six divisions by l each time it is asked for. (The
// open-close update, which reads every contact each iterate, ran as fast
// with 432-, 336- or 304-byte contacts: it is not limited by their bytes.)
struct ContactGeometry {
  double length = 0;             // edge length l, m
  Vec2 tangent{1, 0};            // unit A -> B
  double dn0 = 0;                // signed normal distance, m
  Vector6d en = Vector6d::Zero();  // d(dn)/d(d_i)
  Vector6d gn = Vector6d::Zero();  // d(dn)/d(d_j)
  double ratio0 = 0;             // projection of P1 on the edge, A = 0, B = 1
  double ds0 = 0;                // tangential offset of P1 from the reference point, m
  Vec2 arm_p{0, 0};              // P1 - centroid of block i
  Vec2 arm_ref{0, 0};            // P0 - centroid of block j (the shear reference)
  Vec2 arm_proj{0, 0};           // Pc - centroid of block j (the projection of P1)

  Vector6d es() const { return t_transpose_times_arm(arm_p, tangent); }     // d(ds)/d(d_i)
  Vector6d gs() const { return -t_transpose_times_arm(arm_ref, tangent); }  // d(ds)/d(d_j)
  // -T_j(Pc)^T t: the edge's motion at the projection Pc, along t.
  Vector6d gc() const { return -t_transpose_times_arm(arm_proj, tangent); }
  // The shear reference moved to the projection of P1 (gs becomes gc).
  void reference_at_projection() { arm_ref = arm_proj; }
};

struct Contact {
  int vblock = -1, vertex = -1, eblock = -1, edge = -1;
  int joint = 0;                 // index into Model::joints
  ContactState state = ContactState::Open;
  double ref_ratio = 0;          // reference point P0 on the edge (used while locked)
  int slip_sign = 0;             // +1/-1: P1 slides along +t/-t relative to the edge
  double normal_force = 0;       // N, compression positive, last solve
  double shear_force = 0;        // N on P1 along t, last solve (locked) or friction (sliding)
  double slip_velocity = 0;      // m/s, |relative tangential motion| / dt, last solve
  bool friction_settled = true;  // sliding: the friction assembled matches the new normal force
  double length = 0;             // m, joint length this contact stands for (cohesion, tension)
  bool bonded = false;           // intact cohesive/tensile bond; breaks once, for ever
  bool broke = false;            // set when the bond broke in the current iterate
  bool glued = false;            // across one of DC's artificial cuts: locked for ever
  FrictionState friction;
  ContactGeometry geo;
};

// Linearised geometry of `c` from the current vertices of both blocks; uses
// c.ref_ratio for the shear reference.
ContactGeometry contact_geometry(const Polygon2& vi, const Vec2& ci, const Polygon2& vj,
                                 const Vec2& cj, int vertex, int edge, double ref_ratio);

// Length of joint a vertex contact stands for: half of each edge at the vertex
// that lies within 10 degrees of the contact edge (two vertices of a face lying
// on an edge share the face between them); 0 for a corner against an edge.
double tributary_length(const Polygon2& vi, int vertex, const Vec2& edge_tangent);

// Glue of DC's artificial cuts (edge set kArtificialSet): a cut DC adds to
// make a block simply connected splits one piece of rock in two blocks that
// must behave as one. A contact is glued when its edge and one of the two
// edges at its vertex are artificial (and, checked by the caller, it is
// closed at the start). A glued contact is a bonded joint of unlimited
// cohesion and tensile strength: it stays locked whatever its forces, so
// the two blocks are tied by their normal and shear penalty springs.
bool on_artificial_cut(const Block& vblock, int vertex, const Block& eblock, int edge);

// Per-contact penalties and friction strength, as assembled.
struct ContactLaw {
  double pn = 0, ps = 0;
  double tensile_strength = 0;   // Pa
  const FrictionLaw* friction = nullptr;
  // Distance below which the open-close decision keeps the current state
  // (m): a closed contact opens only when it gaps by more than this, an open
  // one closes only when it penetrates by more, a sliding one locks only when
  // it moves back by more, and a locked one slides only when its spring is
  // stretched this far past the strength. Faces that DC makes in exact touch
  // start at dn = 0, and the solve leaves them at +-1e-20 m of rounding:
  // without the band thousands of such contacts flip every iteration and the
  // step never settles. See Model::contact_tolerance.
  double tolerance = 0;
  // The normal force against the penetration (normal_law.hpp); nullptr or
  // a linear law: the spring pn.
  const NormalLaw* normal = nullptr;
};

// Springs and friction forces of the contact in its current state.
// They are the sum of two parts: `weight` times the springs (K only; weight
// -1 takes out springs added before), and the forces (F only).
void add_contact_terms(const Contact& c, const ContactLaw& law, double dt, BlockSystem& sys);
void add_contact_springs(const Contact& c, const ContactLaw& law, double weight, BlockSystem& sys);
void add_contact_forces(const Contact& c, const ContactLaw& law, double dt, BlockSystem& sys);
// The forces in parts, for an iteration that updates F rather than forming
// it again: the friction force of a sliding contact as it goes into F
// (slip_sign times the strength at its normal force; 0 unless sliding),
// `weight` times the forces with a given friction (weight -1 takes out
// forces added before), and the change of F when only the friction of a
// sliding contact changes by `change`.
double friction_force(const Contact& c, const ContactLaw& law, double dt);
void add_contact_forces(const Contact& c, const ContactLaw& law, double friction, double weight, BlockSystem& sys);
void add_friction_change(const Contact& c, double change, BlockSystem& sys);

// State after a solve with increments di, dj (the state the next iterate
// assumes). Updates the forces of the contact and the bond; returns the new
// state. For a contact that stays sliding, friction_settled says whether the
// friction force assembled (from the previous normal force) agrees with the
// one the new normal force gives, within 0.1 %: the open-close iteration goes
// on until it does, so friction is in effect implicit in the normal force.
// (A looser test, that a lag is harmless when it could move the lighter
// block by only a thousandth of the step's slip, saved 7 % of the solves on
// a layered model but took a third off V1's sliding distance on soft rock:
// the lag is systematic, so its force acts over every step.)
//
// `hold` guards the iteration against chatter: a contact that has already
// changed state twice in this step's iteration is held, i.e. it may still
// close or start sliding but no longer open or stick again. The cycles it
// breaks are between states of (nearly) zero force: the closed iterate pulls
// with a force that the open one shows is not needed, and the other way
// round; holding the contact closed keeps that small pull (bounded by the
// pull seen in the cycle) and lets the step settle at its size instead of
// being cut to the smallest dt.
ContactState update_contact(Contact& c, const ContactLaw& law, double dt, const Vector6d& di,
                            const Vector6d& dj, bool hold = false);

// What a contact's springs and forces depend on besides its geometry and its
// friction: its state and the reference of its shear spring. The open-close
// iteration keeps them as assembled for a contact whose state changes, so
// that the next iterate can take the old springs and forces out of K and F.
struct AssembledSprings {
  ContactState state = ContactState::Open;
  double ds0 = 0;
  Vec2 arm_ref{0, 0};  // ContactGeometry::arm_ref, which gives gs
};
AssembledSprings assembled_springs(const Contact& c);
// c as it was assembled with `s`.
Contact as_assembled(Contact c, const AssembledSprings& s);

// What the open-close iteration changes in a contact: its state and what
// update_contact writes. A step's attempt works on the contacts in place;
// an attempt thrown away (its step cut) puts these back, which is a quarter
// of the bytes of copying whole contacts for every attempt (a copy of the
// 58k contacts of the 10k layered model cost 3-4 % of a step).
struct ContactIterationState {
  ContactState state = ContactState::Open;
  int slip_sign = 0;
  bool friction_settled = true, bonded = false, broke = false;
  double ref_ratio = 0, normal_force = 0, shear_force = 0, slip_velocity = 0;
  double ds0 = 0;
  Vec2 arm_ref{0, 0};  // ContactGeometry::arm_ref, which gives gs
};
ContactIterationState iteration_state(const Contact& c);
void restore_iteration_state(Contact& c, const ContactIterationState& s);

}  // namespace dda::df
