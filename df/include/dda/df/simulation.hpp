#pragma once
// The 2D DDA time stepper.
//
// One step: find contacts (broad + narrow phase, states carried over from the
// last step), then the open-close iteration: assemble K d = F with the assumed
// contact states, solve, re-decide every contact's state from the solution,
// until no state changes. A step that does not settle within
// Control::max_open_close iterations, or moves a vertex further than
// g2 * w0, is redone with a smaller dt; dt grows back by 10 % per easy step.
// An accepted step moves the vertices (exact rotation), adds E * strain to
// the block stresses and carries k * v1 as the next start velocity, with
// v1 = 2 d / dt - v0 (constant acceleration within the step).
#include <memory>
#include <string>
#include <vector>

#include "dda/df/block_kinematics.hpp"
#include "dda/df/block_system.hpp"
#include "dda/df/contact.hpp"
#include "dda/df/friction.hpp"
#include "dda/df/linear_solver.hpp"
#include "dda/df/model.hpp"

namespace dda::df {

struct BlockState {
  Polygon2 vertices;             // current, CCW
  BlockGeometry geometry;        // of the current vertices
  Vector6d velocity = Vector6d::Zero();      // start velocity of the next step (k * v1)
  Vector6d velocity_end = Vector6d::Zero();  // v1, end velocity of the last step (before k)
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
  Vector3d stress = Vector3d::Zero();  // stress of the block it lies in
};

class Simulation {
 public:
  explicit Simulation(Model model, std::unique_ptr<LinearSolver> solver = make_cholmod_solver());

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

 private:
  const StepRecord& advance(double max_dt);
  void detect_contacts();
  int joint_of(int vblock, int vertex, int eblock, int edge) const;
  void assemble(double dt, const std::vector<Contact>& contacts);
  bool open_close(double dt, std::vector<Contact>& contacts, Eigen::VectorXd& d, int& iterations);
  void accept(double dt, const Eigen::VectorXd& d, std::vector<Contact>& contacts, StepRecord& rec);
  void record_measurements();
  ContactLaw law_of(const Contact& c) const;
  double max_vertex_displacement(const Eigen::VectorXd& d) const;

  Model model_;
  std::unique_ptr<LinearSolver> solver_;
  std::vector<std::unique_ptr<FrictionLaw>> friction_;  // one per joint
  std::vector<Matrix3d> emat_;                          // one per material
  std::vector<BlockState> blocks_;
  std::vector<Contact> contacts_;                       // of the last accepted step
  std::vector<Vec2> fixed_anchor_, fixed_pos_;          // fixed points: target and current
  std::vector<Vec2> load_pos_, measurement_pos_;
  std::vector<StepRecord> log_;
  std::vector<std::vector<MeasurementSample>> histories_;
  BlockSystem system_;
  double time_ = 0;
  double dt_ = 0;
  double max_step_displacement_ = 0;                    // g2 * w0
  int step_count_ = 0;
};

}  // namespace dda::df
