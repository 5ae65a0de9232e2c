#pragma once
// The smallest complete 3D DDA time step (DDA_FORMULATION.md, "3D"; issue 6):
// convex polyhedral blocks with twelve unknowns each (block3d.hpp), contacts
// from find_contacts3 (contact3d_geometry.hpp) kept across steps with their
// open / sliding / locked state, one global sparse system per open-close
// iterate, solved with Eigen::SimplicialLDLT.
//
// Left out on purpose (first increment): step control (dt is the caller's),
// broad phase (all pairs whose boxes are within reach), cohesion / tensile
// strength, friction laws other than constant Coulomb, dynamic input, fixed
// and load points, outputs.
#include <Eigen/Core>
#include <vector>

#include "dda/common/polyhedron_model.hpp"
#include "dda/df/block3d.hpp"
#include "dda/df/contact3d_geometry.hpp"

namespace dda::df3 {

struct Model3 {
  std::vector<Polyhedron> blocks;  // convex; volume / centroid / second_moment are recomputed
  std::vector<bool> fixed;         // fixed blocks have no unknowns (d = 0); empty = none fixed
  Material3 material;
  double friction_deg = 30;        // Coulomb friction angle of every contact
  double normal_penalty = 1e9;     // N/m, per contact point
  double shear_penalty = 1e9;      // N/m, per contact point
  Vec3 gravity{0, 0, -9.81};       // m/s^2
  double contact_reach = 0.01;     // m: contacts with |dn0| <= reach are tracked
  double tolerance = 1e-8;         // m: open-close band (as law.tolerance in 2D)
  int max_iterations = 10;         // open-close iterations per step
};

enum class ContactState3 { Open, Sliding, Locked };

// One tracked contact: block i's vertex / edge against block j's face / edge.
struct Contact3 {
  int i = -1, j = -1;
  ContactKind3 kind = ContactKind3::VertexFace;
  int ids[4] = {-1, -1, -1, -1};   // VF: vertex of i, face of j; EE: edge_i[0..1], edge_j[0..1]
  ContactState3 state = ContactState3::Open;
  ContactGeometry3 geo;            // at the start of the current step
  Vec3 ref_j{0, 0, 0};             // shear-spring anchor on block j (world, moves with j)
  Eigen::Vector2d slip_dir{1, 0};  // sliding: unit slip of i relative to j on (t1, t2), fixed in a step
  Eigen::Vector2d slip{0, 0};      // closed: slip of i relative to j in the last iterate (m)
  double normal_force = 0;         // N, compression positive (last iterate)
  Eigen::Vector2d shear_force{0, 0};  // N on i, (t1, t2), last iterate
};

struct StepInfo3 {
  int iterations = 0;
  bool converged = false;          // states (and sliding forces) settled within max_iterations
  int open = 0, sliding = 0, locked = 0;
};

// Contact helpers (simulation3d_contacts.cpp), public so tests can use them.

// Candidates of every pair of blocks whose boxes are within `reach`, with the
// state of the matching contact of `previous` (same i, j, kind and ids); new
// contacts start open. The anchor, slip direction and forces carry over.
std::vector<Contact3> detect_contacts3(const std::vector<Polyhedron>& blocks, const std::vector<Contact3>& previous,
                                       double reach);

// Open-close rule for one contact given the iterate's increments of its two
// blocks (zero for a fixed block); returns the new state and updates anchor,
// slip direction and forces. `settled` is cleared when a sliding contact's
// friction force moved more than 0.1 % since the previous iterate. `hold` (the 2D rule): a contact that already changed state twice
// in this step may no longer open or re-lock, so cycles between near-limit
// states end (it can still go locked -> sliding).
ContactState3 update_contact3(Contact3& c, const Model3& m, const Vector12d& di, const Vector12d& dj, bool hold,
                              bool& settled);

// Tangential stretch of the shear spring at the start of the step (t1, t2).
Eigen::Vector2d shear_offset(const Contact3& c);

class Simulation3 {
 public:
  explicit Simulation3(Model3 model);

  // One step of length dt (s); vertices, velocities, stresses and contact
  // anchors are updated at the end.
  StepInfo3 step(double dt);

  const std::vector<Polyhedron>& blocks() const { return model_.blocks; }
  const std::vector<Vector12d>& velocities() const { return velocity_; }
  const std::vector<Vector6d>& stresses() const { return stress_; }
  const std::vector<Contact3>& contacts() const { return contacts_; }
  double time() const { return time_; }

 private:
  // Solves K d = F for the current states; returns all blocks' increments.
  std::vector<Vector12d> solve(double dt) const;
  void finish_step(const std::vector<Vector12d>& d, double dt);

  Model3 model_;
  std::vector<int> dof_;  // first unknown of each block, -1 if fixed
  int n_dofs_ = 0;
  std::vector<Vector12d> velocity_;
  std::vector<Vector6d> stress_;
  std::vector<Contact3> contacts_;
  double time_ = 0;
};

}  // namespace dda::df3
