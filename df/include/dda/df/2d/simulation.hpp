#pragma once
// The 2D DDA time stepper.
//
// One step: find contacts (broad + narrow phase, states carried over from the
// last step), then the open-close iteration: assemble K d = F with the assumed
// contact states, solve, re-decide every contact's state from the solution,
// until no state changes. A step that does not settle within
// Control::max_open_close iterations, or moves a vertex further than
// g2 * w0, is redone with a smaller dt; dt grows back by 10 % per easy step.
// An accepted step moves the vertices (exact rotation), turns the block
// stresses with the step's rotation and adds E * strain to them, and carries
// k * v1 as the next start velocity, with v1 = 2 d / dt - v0 (constant
// acceleration within the step). A step whose solution is not finite, or
// moves a block beyond the model even at the smallest dt, throws
// RunawayError (runaway.hpp).
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "dda/df/2d/block_kinematics.hpp"
#include "dda/df/core/block_system.hpp"
#include "dda/df/2d/bolts.hpp"
#include "dda/df/2d/contact.hpp"
#include "dda/df/core/energy.hpp"
#include "dda/df/core/friction.hpp"
#include "dda/df/core/normal_law.hpp"
#include "dda/df/core/linear_solver.hpp"
#include "dda/df/2d/model.hpp"
#include "dda/df/2d/moved_blocks.hpp"
#include "dda/df/2d/near_list.hpp"
#include "dda/df/core/start_up.hpp"
#include "dda/df/core/step_timings.hpp"
#include "dda/df/2d/viscous_boundary.hpp"

namespace dda::df {

struct BlockState {
  Polygon2 vertices;             // current, CCW
  BlockGeometry geometry;        // of the current vertices
  Vector6d velocity = Vector6d::Zero();      // start velocity of the next step (k * v1)
  Vector6d velocity_end = Vector6d::Zero();  // v1, end velocity of the last step (before k)
  // Acceleration of the last step, 2 (d - dt v0) / dt^2: constant within a
  // DDA step. For the receivers, and for the motion the next step's first
  // solve starts from (Simulation::predicted_step).
  Vector6d acceleration = Vector6d::Zero();
  Vector3d stress = Vector3d::Zero();    // [sx, sy, txy], Pa, tension positive
};

// What happened in one accepted step.
struct StepRecord {
  int step = 0;
  double time = 0;               // s, at the end of the step
  double dt = 0;                 // s, the step actually taken
  int open_close_iterations = 0; // in the accepted attempt
  int dt_cuts = 0;               // attempts thrown away before it
  bool converged = true;         // false: accepted at the smallest dt without settling
  int open = 0, sliding = 0, locked = 0;
  double max_displacement = 0;   // m, largest vertex displacement
  double kinetic_energy = 0;     // J per unit thickness, end of step (before k is applied)
  double elastic_energy = 0;     // J per unit thickness, block strain energy
};

struct MeasurementSample {
  double time = 0;
  Vec2 position{0, 0};
  Vec2 displacement{0, 0};       // from the initial position
  Vec2 velocity{0, 0};           // end-of-step velocity of the material point
  Vec2 acceleration{0, 0};       // of the material point during the step that ended here (0 at the start)
  Vector3d stress = Vector3d::Zero();  // stress of the block it lies in
};

// Everything of a Simulation that changes as it runs: what a checkpoint
// saves and restore() puts back. state() and restore() are defined in
// df/src/2d/simulation_state.cpp, the HDF5 form in df/src/io/checkpoint_h5.cpp.
// Whoever adds a member to Simulation that evolves over the steps (a friction
// or bolt state, an energy sum, a runaway counter, a solver warm start that
// changes the result) must add it here, to state() and restore(), and to the
// checkpoint reader and writer, or a resumed run will differ from an
// uninterrupted one (tests/df/test_io_checkpoint.cpp checks that they agree).
struct SimulationState {
  double time = 0;
  double dt = 0;                                  // the step the next attempt starts with
  int step_count = 0;
  std::vector<BlockState> blocks;
  std::vector<Contact> contacts;                  // of the last accepted step
  std::vector<Vec2> fixed_anchor, fixed_pos;      // one per fixed point
  std::vector<Vec2> load_pos, measurement_pos;
  std::vector<StepRecord> log;
  std::vector<std::vector<MeasurementSample>> histories;
  LinearSolver::WarmStart solver_warm_start;      // PCG's start vector (empty for direct solvers)
  // Physics state (bolts.hpp, energy.hpp); not yet in the checkpoint files.
  std::vector<BoltState> bolts;
  std::vector<std::vector<BoltSample>> bolt_histories;
  std::vector<EnergyRecord> energy_log;
  bool started = false;                           // initial equilibrium done (or not asked for)
};

class Simulation {
 public:
  // No solver given: make_solver(model.control.solver).
  explicit Simulation(Model model, std::unique_ptr<LinearSolver> solver = nullptr);

  // One accepted step (internally possibly several attempts).
  const StepRecord& step();
  // Steps until Control::total_time (or Control::steps when total_time is 0).
  void run();
  // Steps until `time` exactly (the last step is shortened to land on it).
  void run_until(double time);

  double time() const { return time_; }
  double current_dt() const { return dt_; }
  const Model& model() const { return model_; }
  const std::vector<BlockState>& blocks() const { return blocks_; }
  const std::vector<Contact>& contacts() const { return contacts_; }
  const std::vector<StepRecord>& log() const { return log_; }
  // One history per measurement point; sample 0 is the initial state.
  const std::vector<std::vector<MeasurementSample>>& histories() const { return histories_; }
  // Current position of a measurement point.
  Vec2 measurement_position(int i) const { return measurement_pos_[i]; }
  const LinearSolver& solver() const { return *solver_; }
  const StepTimings& timings() const { return timings_; }

  // A copy of the evolving state, and its restoration into a Simulation made
  // from the same Model (restore() checks the sizes; InputError if they do
  // not match the model).
  SimulationState state() const;
  void restore(const SimulationState& s);

  // Bolts (bolts.hpp): current state, and one history per bolt (sample 0 is
  // the initial state, then one sample per accepted step).
  const std::vector<BoltState>& bolts() const { return bolts_; }
  const std::vector<std::vector<BoltSample>>& bolt_histories() const { return bolt_histories_; }
  // Energy (energy.hpp): record 0 is the initial state, then one per step.
  const std::vector<EnergyRecord>& energy_log() const { return energy_log_; }
  // Static solves the start-up relaxation accepted, both phases (settle.cpp).
  int settle_iterations() const { return start_up_.stuck_iterations + start_up_.friction_iterations; }
  // The start-up relaxation of Control::initial_equilibrium, phase by phase
  // (settle.cpp): static solves with every closed contact stuck, then with
  // the friction laws, and whether that second phase found a frictional
  // equilibrium (start_up.hpp; the 3D solver reports the same).
  using StartUp = ::dda::df::StartUp;
  const StartUp& start_up() const { return start_up_; }
  // Hears of every accepted solve of the start-up relaxation (start_up.hpp).
  void observe_start_up(df::StartUpObserver observer) { start_up_observer_ = std::move(observer); }
  // Runs the start-up relaxation now if it has not run (the first step
  // otherwise does), so that a caller can count or report it apart.
  void start() {
    if (!started_) settle();
  }

 private:
  const StepRecord& advance(double max_dt);
  // The step's contacts with their geometry from the current positions;
  // saves what an attempt changes of each (restore_iteration_states()).
  void detect_contacts();
  // detect_contacts() when the contacts differ from the last step's: a new
  // list, states carried over from the last step's contacts by key.
  void carry_over(const std::vector<ContactCandidate>& candidates, const ContactIndex& last);
  int joint_of(int vblock, int vertex, int eblock, int edge) const;
  // The step's system afresh; friction[k] gets the friction force of
  // contact k as assembled (friction_force).
  void assemble(double dt, const std::vector<Contact>& contacts, std::vector<double>& friction);
  // What the last update of the open-close iteration changed, for the
  // next iterate's assembly. Kept between steps only to keep its memory.
  struct StateChanges {
    long changed = 0;                         // contacts whose state changed
    std::vector<std::uint8_t> is_changed;     // per contact: its state changed
    std::vector<AssembledSprings> assembled;  // per contact whose state changed: its springs as assembled
    std::vector<std::uint8_t> revisit;        // per contact: changed, or sliding (its forces can differ)
    // For the next update (open_close): per contact, changed or its friction
    // lagging (it is updated whether or not its blocks moved), and its blocks.
    std::vector<std::uint8_t> unsettled;
    std::vector<std::pair<int, int>> blocks;
  };
  // The system of the next open-close iterate from the last one: only the
  // contacts `changes` flags to revisit are read; `friction` is as
  // assemble() leaves it, and is kept up to date.
  void reassemble(double dt, const std::vector<Contact>& contacts, const StateChanges& changes,
                  std::vector<double>& friction);
  // The state update of contact k from the increments d (open_close and
  // the clusters): writes k's flags in state_changes_ and counts its state
  // changes in `changes` (from the second on the contact is held).
  struct ContactUpdate {
    bool flipped = false;  // state or slip direction changed
    bool moved = false;    // state changed (its springs must be swapped)
    bool lags = false;     // sliding, and its friction does not yet agree with its normal force
  };
  ContactUpdate update_one(std::size_t k, std::vector<Contact>& contacts, const Eigen::VectorXd& d, double dt,
                           std::vector<std::uint8_t>& changes);
  // Contact clusters (contact_clusters.hpp, this kernel in simulation_clusters.cpp): after a global solve whose
  // update changed a few contacts, their states are settled by solves on
  // the blocks around them alone, the rest of the model held where the
  // global solve put it; true when they settled (the caller then verifies
  // with a full global solve), false when the cluster grew past a quarter
  // of the model or did not settle (the caller goes on globally). d is
  // corrected on the cluster in both cases.
  bool settle_clusters(double dt, std::vector<Contact>& contacts, Eigen::VectorXd& d,
                       std::vector<std::uint8_t>& changes, std::vector<double>& friction);
  // The open-close iteration of one attempt; true when the states settled.
  // With trial_first false the first solve is a full one (see quiet_step).
  bool open_close(double dt, std::vector<Contact>& contacts, Eigen::VectorXd& d, int& iterations,
                  bool trial_first = true);
  // Whether the last accepted step was quiet: its first solve changed no
  // contact state (it settled in the fewest solves possible, without a cut).
  // The next step then most likely settles on its first solve too, so that
  // solve is made at full accuracy rather than as a trial that would have
  // to be repeated. Read from the log, so a resumed run decides the same.
  bool quiet_step() const;
  // Moves the blocks by d and fills rec; rec.max_displacement comes set by
  // the caller (max_vertex_displacement(d), measured to accept the step).
  void accept(double dt, const Eigen::VectorXd& d, std::vector<Contact>& contacts, StepRecord& rec);
  void record_measurements();
  ContactLaw law_of(const Contact& c) const;
  double max_vertex_displacement(const Eigen::VectorXd& d) const;
  // contacts_' iteration states back from saved_states_, where
  // detect_contacts() put them.
  void restore_iteration_states();
  // Where an iterative solve of a step of length dt starts: every block
  // keeps its velocity and acceleration, d = v dt + a dt^2 / 2.
  Eigen::VectorXd predicted_step(double dt) const;
  // Each block's radius: the distance from its centroid to its farthest vertex (m).
  std::vector<double> block_radii() const;
  // Physics extensions, defined in simulation_physics.cpp, settle.cpp and
  // runaway.cpp (owned with the physics files).
  void init_physics();
  void assemble_physics(double dt);
  // What the energy ledger needs of one contact at the end of a step with
  // increments di, dj of its blocks: the friction loss of the step (sliding)
  // and the energy of its springs (normal, and shear when locked).
  struct ContactEnergy {
    double friction_loss = 0, normal = 0, shear = 0;
  };
  ContactEnergy contact_energy(const Contact& c, const Vector6d& di, const Vector6d& dj) const;
  // The energy ledger's 2D kernel (simulation_physics.cpp; the bookkeeping
  // is energy_ledger.hpp's, shared with 3D).
  struct EnergyTerms;
  // Record 0 of the ledger, from the current state (init_physics).
  void start_energy();
  // The bolts moved with their blocks (and broken), then the step's record
  // opened with its work and losses; contact_energy_ holds the step's
  // contacts' terms (accept() fills it in its one pass over the contacts).
  void before_accept(double dt, const Eigen::VectorXd& d);
  // The bolts' histories, and the step's record closed.
  void after_accept(double dt);
  void settle();
  // One phase of settle(): static pseudo-steps until no vertex moves more
  // than the tolerance (start_up_relax.hpp's rules).
  Relaxation relax(bool contacts_stick);
  void check_runaway(const Eigen::VectorXd& d, double moved, double dt, bool at_min_dt) const;
  // s, beta of the blocks' viscous damping in this step: none while
  // relaxing before t = 0, whose pseudo steps are not time.
  double damping_beta() const { return settling_ ? 0.0 : model_.control.damping.beta(); }
  // Dashpot matrix of a viscous boundary edge in the current configuration,
  // and the traction from outside on it during the step [time_, time_ + dt].
  Eigen::Matrix2d edge_dashpot(const ViscousEdge& e) const;
  EdgeTraction edge_traction(const ViscousEdge& e, const Eigen::Matrix2d& dashpot, double dt) const;

  Model model_;
  std::unique_ptr<LinearSolver> solver_;
  std::vector<std::unique_ptr<FrictionLaw>> friction_;  // one per joint
  std::vector<std::unique_ptr<NormalLaw>> normal_;      // one per joint
  std::vector<Matrix3d> emat_;                          // one per material
  std::vector<Matrix3d> compliance_;                    // emat_^-1: strain energy density is s' C s / 2
  std::vector<BlockState> blocks_;
  std::vector<Contact> contacts_;                       // of the last accepted step
  // Scratch, not state (dead between steps): the list detect_contacts()
  // builds before swapping it into contacts_. Kept so that a list of tens of
  // MB is neither allocated nor faulted in again every step.
  std::vector<Contact> work_;
  StateChanges state_changes_;
  MovedBlocks moved_blocks_;  // open_close(): the blocks whose contacts a trial iterate updates
  std::vector<ContactEnergy> contact_energy_;  // of the step being accepted, one per contact
  // What the step's iteration changes in each contact, as it was at the
  // start of the step: an attempt thrown away puts it back.
  std::vector<ContactIterationState> saved_states_;
  // Scratch of detect_contacts(): the current polygons, kept so their
  // vertex lists are not allocated again every step.
  std::vector<Polygon2> polygons_;
  NearList near_list_;  // vertex-edge pairs near enough to be in contact, kept between steps
  // The contacts' keys for detect_contacts(), kept from the last detection
  // while contact_index_current_ (restore() clears it).
  ContactIndex contact_index_;
  bool contact_index_current_ = false;
  // How far a vertex may have moved since the last detection: the largest
  // move of each accepted step, added up (accept()); unknown (infinite)
  // until a first detection and after restore(). Lets the near list skip
  // reading every vertex while the model is at rest.
  double moved_since_detection_ = std::numeric_limits<double>::infinity();
  std::vector<char> keep_reference_;  // per contact of carry_over(): keeps its shear reference point
  std::vector<Vec2> fixed_anchor_, fixed_pos_;          // fixed points: target and current
  std::vector<Vec2> load_pos_, measurement_pos_;
  std::vector<StepRecord> log_;
  std::vector<std::vector<MeasurementSample>> histories_;
  BlockSystem system_;
  StepTimings timings_;
  double time_ = 0;
  double dt_ = 0;
  double max_step_displacement_ = 0;                    // g2 * w0
  int step_count_ = 0;
  std::vector<BoltState> bolts_;
  std::vector<double> bolt_released_;  // J per unit thickness a bolt let go when it broke in this step (the ledger's breakage)
  std::vector<std::vector<BoltSample>> bolt_histories_;
  // The joint water's loads of the step being assembled (empty without water).
  std::vector<WaterLoad<2>> water_loads_;
  std::vector<EnergyRecord> energy_log_;  // record 0: the stored energy the run starts from
  bool started_ = false;               // settle() has run (or was not asked for)
  bool settling_ = false;              // before t = 0, relaxing statically (settle.cpp)
  bool settling_stuck_ = false;        // and every closed contact sticks (its first phase)
  StartUp start_up_;
  df::StartUpObserver start_up_observer_;
};

}  // namespace dda::df
