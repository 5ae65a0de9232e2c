#pragma once
// The smallest complete 3D DDA time step (docs/formulation.md, "3D"; issue 6):
// convex polyhedral blocks with twelve unknowns each (block3d.hpp), contacts
// from find_contacts3 (contact3d_geometry.hpp) kept across steps with their
// open / sliding / locked state, one global sparse system per open-close
// iterate, solved by CHOLMOD (its analysis kept while the pattern holds).
// Candidate pairs come from a uniform grid (broad_phase3d.hpp); block terms
// and contact search run on all OpenMP threads, with the same result on any
// number of them.
//
// Friction: every law of the 2D solver (friction.hpp, friction_laws.hpp),
// per joint set of the faces in contact, through the same FrictionLaw
// interface: the law gives the strength from the normal force and the slip
// speed of the current iterate, and advances its state once per step.
//
// Bonds: a joint set's cohesion and tensile strength act on the contacts of
// faces in touch at the start, each over its share of the face-to-face
// patch (simulation3d_bonds.cpp); a bond broken stays broken.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dda/common/polyhedron_model.hpp"
#include "dda/df/3d/block3d.hpp"
#include "dda/df/3d/bolts3d.hpp"
#include "dda/df/3d/contact3d_geometry.hpp"
#include "dda/df/core/damping.hpp"
#include "dda/df/core/energy.hpp"
#include "dda/df/core/friction.hpp"
#include "dda/df/core/normal_law.hpp"
#include "dda/df/core/water.hpp"
#include "dda/df/3d/ground_motion3d.hpp"
#include "dda/df/3d/points3d.hpp"
#include "dda/df/core/linear_solver.hpp"
#include "dda/df/core/start_up.hpp"
#include "dda/df/core/step_timings.hpp"
#include "dda/df/3d/viscous_boundary3d.hpp"

namespace dda::df {
class WorkBook;  // df/src/core/energy_ledger.hpp
}  // namespace dda::df

namespace dda::df3 {

// Time stepping of Simulation3::advance / run (the 2D Control's rules).
struct Control3 {
  double dt = 1e-3;                     // s, the step it starts with and grows back to
  std::string dt_basis;                 // why the model chose dt (time_step.hpp); empty when the scenario gave it
  double total_time = 0;                // s, the run's end (or `steps`)
  int steps = 0;
  double max_displacement_ratio = 0.01; // no vertex moves more than this times w0 in a step (else dt is cut)
  double min_dt_ratio = 1e-3;           // dt is never cut below this times dt
  df::ViscousDamping damping;           // of the blocks' deformation (damping.hpp); none by default
  // Linear solver (linear_solver.hpp): "cholmod", "pcg" (12x12 block-Jacobi
  // conjugate gradients, warm-started) or "auto": CHOLMOD below
  // kAutoPcgBlocks3 (80) free blocks, PCG from there on.
  std::string solver = "auto";
  // Start from equilibrium, as the 2D Control::initial_equilibrium: before
  // the first step the model is relaxed statically under gravity, first
  // with every closed contact stuck, then with the joints' friction
  // (settle3d.cpp); time stays 0, the velocities are the initial ones.
  // Without it the blocks start with no contact force and fall into their
  // springs under suddenly applied gravity, a jolt the closed-form
  // solutions (which start at rest) do not have, and which slides a cube at
  // its friction limit 0.14 mm (tests/df/test_simulation3d.cpp,
  // CubeHoldsAtItsFrictionLimit). On by default, as in 2D.
  bool initial_equilibrium = true;
  // Settle the contact states a solve changed on the blocks around them
  // before the whole model is solved again (contact_clusters.hpp, shared
  // with 2D's Control::contact_clusters); false: every iterate solves the
  // whole model.
  bool contact_clusters = true;
};

// Size from which the 3D "auto" solver uses PCG, in free blocks. Measured on
// the jointed cube of bench/bench_df3d.cpp from rest, one thread: at 82 free
// blocks PCG takes 44 ms a step and CHOLMOD 128 ms.
constexpr int kAutoPcgBlocks3 = 80;

struct Model3 {
  std::vector<Polyhedron> blocks;  // convex; volume / centroid / second_moment are recomputed
  std::vector<bool> fixed;         // fixed blocks have no unknowns (d = 0); empty = none fixed
  // Block b is of materials[block_material[b]]; an empty block_material
  // puts every block in materials[0].
  std::vector<Material3> materials{Material3{}};
  std::vector<int> block_material;
  // The state at t = 0, each empty (all zero) or one entry per block.
  // Stress in Vector6d's order [sx sy sz tyz tzx txy] (Pa, tension
  // positive): it is carried exactly as the stress of earlier steps, so a
  // free block relaxes it into strain. Velocity: rates of the twelve
  // unknowns, [vx vy vz] of the centroid (m/s), [wx wy wz] the angular
  // velocity (rad/s), then strain rates (1/s); zero on fixed blocks, which
  // have no unknowns.
  std::vector<Vector6d> initial_stress;
  std::vector<Vector12d> initial_velocity;
  // Joint properties by the joint set of the faces in contact (PolyFace::set;
  // index = set id); faces of other sets (boundary, excavation, none given)
  // use default_joint. Read: the friction (law, angle, parameters), the
  // bond (cohesion, tensile_strength; Pa, over the contact's bond_area),
  // the normal law and the joint's own penalties (ContactSprings3).
  std::vector<df::JointProperties> joint_sets;
  df::JointProperties default_joint;
  // The run's springs, N/m per contact point: those of every joint that
  // gives no normal_penalty / shear_penalty of its own (ContactSprings3).
  double normal_penalty = 1e9;
  double shear_penalty = 1e9;
  Vec3 gravity{0, 0, -9.81};       // m/s^2
  // Hydrostatic joint water (df/core/water.hpp, docs/formulation.md); none: dry
  // joints, and no cost. Saturation per set: JointProperties::saturation.
  std::optional<df::WaterTable<3>> water;
  GroundInput3 earthquake;         // none while earthquake.motion is null; the fixed blocks are the foundation
  // Non-reflecting boundary faces and the incident wave (viscous_boundary3d.hpp); none: no cost.
  std::optional<ViscousBoundary3> viscous;
  std::vector<FixedPoint3> fixed_points;  // on free blocks
  std::vector<PointLoad3> loads;          // on free blocks
  std::vector<MeasurementPoint3> measurements;
  std::vector<Bolt3> bolts;               // rock bolts (bolts3d.hpp), blocks resolved
  Vec3 origin{0, 0, 0};                   // local origin of every position (PolyhedronModel::origin)
  double contact_reach = 0.01;     // m: contacts with |dn0| <= reach are tracked
  double contact_merge = 1e-3;     // m: one pair's candidates closer than this are one contact (see detect_contacts3)
  // m: open-close band (as ContactLaw::tolerance in 2D). A locked contact
  // slides only when its spring pulls ps * tolerance past the strength, so
  // the band must stay far below the weights' share per contact: at 1e-8 m
  // and ps = 1e11 that was 1 kN, 4 % of a 1 m cube's weight, and V3 in 3D
  // slid 3 % short (0.5 % at 1e-11).
  double tolerance = 1e-11;
  int max_iterations = 10;         // open-close iterations per step (then advance() cuts dt)
  Control3 control;

  // The joint of a contact's `joint` index: joint set, or the default
  // (also for glue_joint(), which has no joint of its own).
  const df::JointProperties& joint(int index) const {
    return static_cast<std::size_t>(index) < joint_sets.size() ? joint_sets[static_cast<std::size_t>(index)]
                                                               : default_joint;
  }
  // The `joint` index of glued contacts (Contact3::glued), after the
  // default's: their springs are the default joint's penalties, linear.
  int glue_joint() const { return static_cast<int>(joint_sets.size()) + 1; }
  const Material3& material_of(std::size_t b) const {
    return materials[block_material.empty() ? 0 : static_cast<std::size_t>(block_material[b])];
  }
};

enum class ContactState3 { Open, Sliding, Locked };

// The springs of the contacts of one joint (a joint set, or the default),
// as 2D resolves them per joint: the joint's normal_penalty, else the
// run's; its shear_penalty, else the run's ratio ps / pn times its normal
// penalty (the run's ps itself for a joint without a normal penalty of its
// own); and its normal law (normal_law.hpp: N against the penetration,
// per contact point), made once and shared by copies.
struct ContactSprings3 {
  double pn = 0, ps = 0;
  std::shared_ptr<const df::NormalLaw> normal;
  // The normal spring over a step that starts at gap dn0 (m, penetration
  // negative): N = -k (s0 + the step's change of the gap).
  df::NormalSpring normal_spring(double dn0) const { return df::normal_spring_over_step(normal.get(), pn, dn0); }
  // J held by the normal spring at force n (the law's integral of N dg).
  double normal_energy(double n) const { return normal->energy_at_force(n); }
};
// One per joint index (Model3::joint: the sets, then the default).
// InputError for a penalty that is not a positive number, or a bad law.
std::vector<ContactSprings3> contact_springs3(const Model3& m);
// The springs of glued contacts (Model3::glue_joint): the default joint's
// pn and ps, with the linear penalty whatever normal law it has (the 2D
// glue's springs too).
ContactSprings3 glue_springs3(const ContactSprings3& default_joint);

// One tracked contact: block i's vertex / edge against block j's face / edge.
struct Contact3 {
  int i = -1, j = -1;
  ContactKind3 kind = ContactKind3::VertexFace;
  int ids[4] = {-1, -1, -1, -1};   // VF: vertex of i, face of j; EE: edge_i[0..1], edge_j[0..1]
  ContactState3 state = ContactState3::Open;
  ContactGeometry3 geo;            // at the start of the current step
  Vec3 ref_j{0, 0, 0};             // shear-spring anchor on block j (world, moves with j)
  Vec3 point_now{0, 0, 0};         // P carried with block i to the end of the last step (identity, see detect_contacts3)
  Eigen::Vector2d slip_dir{1, 0};  // sliding: unit direction on (t1, t2) that friction opposes, fixed in a step
  Eigen::Vector2d slip{0, 0};      // closed: slip of i relative to j in the last iterate (m)
  double normal_force = 0;         // N, compression positive (last iterate)
  Eigen::Vector2d shear_force{0, 0};  // N on i, (t1, t2), last iterate
  int joint = 0;                   // index into the laws: joint set, joint_sets.size() for the default,
                                   // Model3::glue_joint() while glued
  double strength = 0;             // N, the law's shear strength at the last iterate's N and slip speed
  double slip_velocity = 0;        // m/s, |slip| / dt in the last iterate (closed contacts)
  Vec3 slip_axis{0, 0, 0};         // world direction of the first slip: the sign of later slip along it
                                   // is the 2D slip_sign the laws count reversals with (degradation)
  df::FrictionState friction;      // the law's memory, carried with the contact
  // The joint's bond (simulation3d_bonds.cpp): cohesion c bond_area in shear
  // and tension T bond_area while intact; it breaks once, for ever.
  bool bonded = false;
  double bond_area = 0;            // m^2, this contact's share of its face-to-face patch
  double bond_released = 0;        // J, spring energy the bond let go in this step (the ledger's breakage)
  // Across one of DC's artificial cuts (on_artificial_cut3), in touch when
  // the run starts: one piece of rock, not a joint. Locked for ever, both
  // springs on whatever their forces; no friction, normal law or water.
  bool glued = false;
};

// One accepted step.
struct StepRecord3 {
  int step = 0;                    // 1 = first
  double time = 0, dt = 0;         // s, at the end of the step; its length
  int iterations = 0;              // open-close iterations (of the accepted attempt)
  bool converged = false;          // states (and sliding forces) settled within max_iterations
  int dt_cuts = 0;                 // attempts redone with a shorter step
  double max_displacement = 0;     // m, largest vertex displacement
  int open = 0, sliding = 0, locked = 0;
};

// Contact helpers (simulation3d_contacts.cpp), public so tests can use them.

// The contacts of every pair of blocks whose boxes are within `reach`.
//
// Identity. A contact is the material point P where two blocks touch, not
// the features that describe it: where a corner of one block sits on a
// corner or edge of the other (every corner of a wedge cut from the same
// planes as its supports), the candidate search finds the same point as a
// vertex of i on a face of j, a vertex of j on a face of i, or an edge pair,
// and which one it reports changes from step to step with round-off and
// tiny motions. So (1) the candidates of one pair closer than `merge` to
// each other are one contact (the one continuing a previous contact if any,
// else vertex-face before edge-edge, in search order), and (2) a contact
// inherits state, shear anchor, slip direction and forces from the previous
// contact of the same pair whose point (carried with its block) is nearest,
// within `merge`, whichever kind or orientation either has; each previous
// contact passes on at most once. Without this a switch restarted the
// contact open without its shear spring, and the V4 wedge crept at phi = 30.
std::vector<Contact3> detect_contacts3(const std::vector<Polyhedron>& blocks, const std::vector<Contact3>& previous,
                                       double reach, double merge);
// The same into `out` (not `previous`), whose storage is reused: at 10,000
// blocks the list is 250 MB, and a fresh one costs as much in page faults
// as the copy into it.
void detect_contacts3(const std::vector<Polyhedron>& blocks, const std::vector<Contact3>& previous, double reach,
                      double merge, std::vector<Contact3>& out);

// Open-close rule for one contact given the iterate's increments of its two
// blocks (zero for a fixed block); returns the new state and updates anchor,
// slip direction and forces. `settled` is cleared when a sliding contact's
// friction force moved more than 0.1 % since the previous iterate. `hold` (the 2D rule): a contact that already changed state twice
// in this step may no longer open or re-lock, so cycles between near-limit
// states end (it can still go locked -> sliding).
// `springs`: the contact's joint's (ContactSprings3).
ContactState3 update_contact3(Contact3& c, const Model3& m, const ContactSprings3& springs,
                              const df::FrictionLaw& law, double dt, const Vector12d& di, const Vector12d& dj,
                              bool hold, bool& settled);

// What a friction law sees at the contact (normal force and slip speed of
// the last iterate); slip_sign3 is +1 / -1 for slip along / against the
// contact's slip_axis while sliding, else 0.
df::FrictionInput friction_input3(const Contact3& c, double dt);
int slip_sign3(const Contact3& c);

// The joint set (PolyFace::set) of the faces in contact; negative if none.
int contact_joint_set(const std::vector<Polyhedron>& blocks, const Contact3& c);

// The contact lies on one of DC's artificial cuts (kArtificialSet): its two
// blocks are parts of one rock body (the same Polyhedron::body), and a face
// of either block at the contact's feature (the face under a vertex, or a
// face of the vertex's block through it; a face at either edge of an edge
// pair) is artificial and lies in the contact plane, facing the other block
// within 10 degrees. DC's excavations tag only one side of such a cut: the
// piece kept first has an excavation face there (it partly faces the
// opening), the next piece an artificial face; so one side suffices.
bool on_artificial_cut3(const std::vector<Polyhedron>& blocks, const Contact3& c);

// Tangential stretch of the shear spring at the start of the step (t1, t2).
Eigen::Vector2d shear_offset(const Contact3& c);

// Everything that changes in a run (a checkpoint): with the same Model3,
// restore() continues exactly where state() was taken. Of each contact's
// geometry only the normal, tangents and the two points are needed (the
// next step's detection recomputes the rest).
struct SimulationState3 {
  double time = 0;
  double dt = 0;                                  // advance()'s current step
  std::vector<std::vector<Vec3>> vertices;        // per block
  std::vector<Vector12d> velocity;
  std::vector<Vector6d> stress;
  std::vector<Contact3> contacts;
  std::vector<StepRecord3> log;
  std::vector<Vec3> fixed_at, load_at, measure_at;
  std::vector<std::vector<MeasurementSample3>> histories;
  std::vector<df::EnergyRecord> energy_log;       // the ledger; empty in files written before it
  df::LinearSolver::WarmStart solver_warm_start;  // PCG's start vector (empty for CHOLMOD)
  bool started = false;                           // initial equilibrium done (or not asked for)
  std::vector<BoltState3> bolts;                  // per bolt of the model
  std::vector<std::vector<df::BoltSample>> bolt_histories;
  bool bonds_placed = false;                      // the joints' bonds and the glue are placed (simulation3d_bonds.cpp)
};

class ContactCoupling3;  // df/src/3d/contact_coupling3d.hpp
struct Assembly3;        // df/src/3d/simulation3d_assembly.hpp

class Simulation3 {
 public:
  explicit Simulation3(Model3 model);
  ~Simulation3();
  Simulation3(Simulation3&&) noexcept;
  Simulation3& operator=(Simulation3&&) noexcept;

  // One step of length dt (s), accepted whatever happens; vertices,
  // velocities, stresses and contact anchors are updated at the end. The
  // first step (of step or advance) first runs the start-up relaxation of
  // Control3::initial_equilibrium, unless start() has.
  StepRecord3 step(double dt);
  // One step with step control (Model3::control): dt cut by 3 when the
  // contacts do not settle, or to what the displacement limit allows, and
  // grown back by 10 % a step; never longer than max_dt. RunawayError for a
  // solution that is not finite or moves more than the model at dt_min.
  StepRecord3 advance(double max_dt = 1e300);
  bool finished() const;  // total_time reached, or `steps` steps taken
  void run();             // advance() until finished()
  SimulationState3 state() const;
  // InputError if the state does not fit the model (block, vertex or point counts).
  void restore(const SimulationState3& s);
  const std::vector<StepRecord3>& log() const { return log_; }

  const std::vector<Polyhedron>& blocks() const { return model_.blocks; }
  const std::vector<Vector12d>& velocities() const { return velocity_; }
  const std::vector<Vector6d>& stresses() const { return stress_; }
  // J: 1/2 v^T M v of every free block at its velocity and place now (the
  // twelve rates, rigid and strain; block3d.hpp's mass matrix).
  double kinetic_energy() const;
  // The energy ledger (df/core/energy.hpp; J): record 0 is the state the run
  // starts from (after the start-up relaxation), then one per accepted step.
  const std::vector<df::EnergyRecord>& energy_log() const { return energy_log_; }
  const std::vector<Contact3>& contacts() const { return contacts_; }
  // Contacts glued across artificial cuts now (Contact3::glued).
  int glued_contacts() const;
  const Model3& model() const { return model_; }
  // Per measurement point (model order): sample 0 at the start, then one per step.
  const std::vector<std::vector<MeasurementSample3>>& histories() const { return histories_; }
  double time() const { return time_; }
  // Rock bolts (bolts3d.hpp), model order: state now, and one history each
  // (sample 0 at the start, then one per step).
  const std::vector<BoltState3>& bolts() const { return bolts_; }
  const std::vector<std::vector<df::BoltSample>>& bolt_histories() const { return bolt_histories_; }
  // Wall time of assembly and solves, summed over all steps (contact_search
  // and total are not filled: bench/bench_df3d.cpp times those itself).
  const df::StepTimings& timings() const { return timings_; }
  const df::LinearSolver& solver() const { return *solver_; }
  // The start-up relaxation of Control3::initial_equilibrium (settle3d.cpp),
  // as the 2D Simulation reports it: the static solves spent with the
  // contacts stuck, then with friction, and whether the model came to rest
  // in frictional equilibrium (start_up.hpp).
  using StartUp = df::StartUp;
  const StartUp& start_up() const { return start_up_; }
  // Hears of every accepted solve of the start-up relaxation (start_up.hpp).
  void observe_start_up(df::StartUpObserver observer) { start_up_observer_ = std::move(observer); }
  // Static solves the start-up relaxation accepted, both phases.
  int settle_iterations() const { return start_up_.stuck_iterations + start_up_.friction_iterations; }
  // Runs the start-up relaxation now if it has not run (the first step
  // otherwise does), so that a caller can report it before the first frame.
  // A run restored from a checkpoint has started and does not relax again.
  void start() {
    if (!started_) settle();
  }

 private:
  void detect();                     // contacts at the start of the step, with their joints
  void prepare_input(double dt);     // body acceleration, foundation motion, sliding strengths
  // Open-close iteration of one attempt; true if the states settled.
  bool iterate(double dt, std::vector<Vector12d>& d, int& iterations);
  // Contact clusters (simulation3d_clusters.cpp, the driver in
  // contact_clusters.hpp): after a global update that changed some
  // contacts, their states settled on the blocks around them, the rest held.
  // True when they settled (the caller verifies with a full global solve).
  // d is corrected on the cluster; `changed` holds the changes the next
  // solve must swap in, `changes` counts each contact's state changes.
  // `unsettled`: per contact, the global update changed its state or left
  // its friction lagging (the clusters' seeds).
  bool settle_clusters(double dt, std::vector<Vector12d>& d, std::vector<int>& changes,
                       std::vector<std::pair<int, ContactState3>>& changed,
                       const std::vector<std::uint8_t>& unsettled);
  double max_vertex_displacement(const std::vector<Vector12d>& d) const;
  // Accepts the step: `moved` is max_vertex_displacement(d), already known.
  StepRecord3 record(double dt, const std::vector<Vector12d>& d, double moved, int iterations, bool converged,
                   int cuts);
  // Solves K d = F for the current states; returns all blocks' increments.
  // `changed` (null on an attempt's first iterate): the contacts whose state
  // changed since the last assembly, with the state they were assembled in.
  std::vector<Vector12d> solve(double dt, const std::vector<std::pair<int, ContactState3>>* changed);
  // K afresh and the blocks' loads (block_loads_), for the current states.
  void assemble(double dt);
  // K of the last assembly with the springs of `changed` swapped.
  void swap_springs(const std::vector<std::pair<int, ContactState3>>& changed);
  // add(range, contacts) for kRanges fixed ranges of K's columns, in
  // parallel (Assembly3); `contacts` are the indices of the contacts with a
  // block in the range (range_contacts_, in contact order).
  template <class AddTerms>
  void for_each_range(Eigen::VectorXd& f, AddTerms&& add);
  // The range of K's columns block b's unknowns fall in; -1 for a fixed block.
  int range_of(int b) const;
  // Fills range_contacts_ for contacts_ (once per attempt: the iterates
  // keep the list).
  void index_ranges();
  void finish_step(const std::vector<Vector12d>& d, double dt);
  // One law per joint set, then the default joint's (friction_).
  void make_friction_laws();
  // Checks the materials and the initial state of the model and starts
  // velocity_ and stress_ from it (simulation3d_materials.cpp).
  void set_initial_state();
  // Points: checked and indexed by block in the constructor; their springs
  // and loads enter block b's terms; they move with their blocks.
  void index_points();
  void add_point_terms(int b, double dt, const BlockGeometry3& g, Matrix12d& k, Vector12d& f) const;
  void sample_measurements();
  // Rock bolts (simulation3d_bolts.cpp): checked and started in the
  // constructor; their pairs in K's pattern, their springs in K and F, K's
  // solve with their coupling; moved with their blocks (and broken) at the
  // end of a step (bolt_released_); the ground's work on them.
  void start_bolts();
  void restart_bolt_histories();
  void add_bolt_pairs(std::vector<std::pair<int, int>>& pairs) const;
  void add_bolt_terms(Assembly3& sys) const;
  Eigen::VectorXd solve_system(const Eigen::VectorXd& f, double dt);
  void advance_bolts(const std::vector<Vector12d>& d, const std::vector<Vec3>& old_centroid);
  double bolt_ground_work(const std::vector<Vector12d>& d) const;
  // The viscous boundary (simulation3d_waves.cpp): checked in the
  // constructor; its dashpots and incident traction in K and F; their
  // energy in the step's ledger record.
  void check_viscous() const;
  // The traction from outside on a face over the step (empty while settling).
  FaceTraction face_traction(const ViscousFace3& face, double dt) const;
  void add_viscous_terms(double dt, Assembly3& sys) const;
  void add_viscous_work(const std::vector<Vector12d>& d, double dt, df::WorkBook& book) const;
  // Bonds (simulation3d_bonds.cpp): until the first accepted solve, every
  // detection bonds the contacts of bonded joints in touch, each with its
  // share of the patch, and closes them.
  void place_bonds();
  // Glue (simulation3d_bonds.cpp): until the first accepted solve, every
  // detection glues the contacts on artificial cuts in touch, closed.
  void place_glue();
  // The energy ledger (its 3D kernel in simulation3d_energy.cpp, the
  // bookkeeping energy_ledger.hpp's, shared with 2D): started afresh from
  // the current state; a step's work and losses, taken from the
  // configuration at its start with the forces as assembled (before
  // finish_step moves the blocks); then the stored energy at its end and
  // the residual.
  struct EnergyTerms;
  void start_energy();
  void add_step_work(const std::vector<Vector12d>& d, double dt);
  void close_energy_record();
  // The law the open-close iteration uses: the joint's, or while the model
  // settles with its contacts stuck, one that never lets go (as for a glued
  // contact, which has no joint and never asks it).
  const df::FrictionLaw& law_of(const Contact3& c) const {
    return settling_stuck_ || c.glued ? *df::stuck_friction() : *friction_[static_cast<size_t>(c.joint)];
  }
  // The contact's springs: its joint's penalties and normal law.
  const ContactSprings3& springs_of(const Contact3& c) const { return springs_[static_cast<size_t>(c.joint)]; }
  // Control3::initial_equilibrium (settle3d.cpp): both phases, and one of
  // them (solves spent, negative when it did not come to rest).
  void settle();
  df::Relaxation relax(bool contacts_stick);

  Model3 model_;
  // The step's input: gravity plus the earthquake's body acceleration on
  // free blocks, and the known increments of fixed blocks (zero, or the
  // foundation's translation in displacement mode).
  Vec3 body_acceleration_{0, 0, 0};
  std::vector<Vector12d> known_;
  std::vector<int> dof_;  // first unknown of each block, -1 if fixed
  int n_dofs_ = 0;
  std::vector<Vector12d> velocity_;
  std::vector<Vector6d> stress_;
  std::vector<Contact3> contacts_;
  // Storage kept from step to step (see detect_contacts3): the list of two
  // searches ago, and the contacts at the start of advance()'s step.
  std::vector<Contact3> spare_contacts_, start_contacts_;
  std::vector<StepRecord3> log_;
  std::vector<df::EnergyRecord> energy_log_;  // record 0: the stored energy the ledger counts changes from
  std::vector<df::WaterLoad<3>> water_loads_;  // the joint water's loads of the step (assemble), for the ledger
  double dt_ = 0;   // current step of advance()
  double w0_ = 1;   // m, the reference length of the displacement limit
  std::vector<std::unique_ptr<df::FrictionLaw>> friction_;
  std::vector<ContactSprings3> springs_;  // per joint index, as friction_, then the glue's (Model3::glue_joint)
  std::vector<std::vector<int>> fixed_of_block_, loads_of_block_;  // point indices per block
  std::vector<Vec3> fixed_at_, load_at_, measure_at_;              // where the material points are now
  std::vector<std::vector<MeasurementSample3>> histories_;
  std::vector<BoltState3> bolts_;
  std::vector<double> bolt_released_;  // J a bolt let go when it broke in this step (advance_bolts; the ledger's breakage)
  std::vector<std::vector<df::BoltSample>> bolt_histories_;
  double time_ = 0;
  // K's lower triangle, its pattern kept while the contacts join the same
  // pairs of blocks (k_pairs_, in contact order), so that the solver keeps
  // its symbolic analysis (simulation3d_assembly.hpp).
  std::unique_ptr<df::LinearSolver> solver_;
  Eigen::SparseMatrix<double> k_lower_;
  Eigen::VectorXd block_loads_;  // F's block and point terms of the attempt's first iterate
  std::vector<std::pair<int, int>> k_pairs_;
  // K's coupling blocks as the contacts' springs, for PCG (set once per
  // attempt, states once per iterate).
  std::unique_ptr<ContactCoupling3> coupling_;
  static constexpr int kRanges = 8;  // fixed: it sets the summation order of K and F
  std::vector<std::vector<int>> range_contacts_ = std::vector<std::vector<int>>(kRanges);
  df::StepTimings timings_;
  bool started_ = false;         // settle() has run (or was not asked for)
  bool bonds_used_ = false;      // some joint has cohesion or tensile strength
  bool bonds_placed_ = false;    // a solve was accepted: no new bonds or glue from here on
  bool settling_ = false;        // before t = 0, relaxing statically: time stands still
  bool settling_stuck_ = false;  // and every closed contact sticks (its first phase)
  StartUp start_up_;
  df::StartUpObserver start_up_observer_;
};

}  // namespace dda::df3
