#pragma once
// Non-reflecting (viscous) boundary of the 3D solver and seismic input
// through it as an incident wave: the 2D formulation (viscous_boundary.hpp)
// on the faces of polyhedral blocks, with the dashpots of
// lysmer_dashpot.hpp.
//
// A boundary face of a block stands for the same material continuing
// outside the model. On it act the tractions
//   t = D (2 v_in - v)  on an input face (the incident wave enters there),
//   t = -D v            on the others,
// D = rho (Vp n n^T + Vs (I - n n^T)), n the face's outward normal, v the
// velocity of the face's point, v_in(t) the incident wave's particle
// velocity (half the outcrop motion: a free surface doubles a wave), and
//   Vp = sqrt(E (1 - nu) / ((1 + nu)(1 - 2 nu) rho)),  Vs = sqrt(E / (2 (1 + nu) rho)).
//
// In the step (as 2D): the velocity is the step's mean, T d / dt, so the
// dashpots are a stiffness D / dt on the face, and v_in is the mean of the
// incident velocity over the step:
//   K_ii += (1/dt) integral over the face of T^T D T dA,
//   F_i  += integral of T^T D (2 v_in) dA  (input faces),
// T = displacement_matrix(x, centroid) (3 x 12, linear in x), the integrals
// over the face at the start of the step, exactly (a fan of triangles from
// the face's first vertex, each with the edge-midpoint rule, exact for
// quadratics). The energy the dashpots take out in a step is
// (1/dt) integral of (T d)^T D (T d) dA >= 0 (the ledger's radiation); the
// incident traction's work, integral of (2 D v_in) . (T d) dA, counts with
// the loads.
//
// The boundary carries no static load (as in 2D): a model under gravity
// resting on a viscous base alone sinks through it.
#include <vector>

#include "dda/common/polyhedron_model.hpp"
#include "dda/df/block3d.hpp"
#include "dda/df/points3d.hpp"

namespace dda::df3 {

struct ViscousFace3 {
  int block = -1;
  int face = -1;       // index into the block's faces
  bool input = false;  // the incident wave enters here
};

struct ViscousBoundary3 {
  std::vector<ViscousFace3> faces;
  // v_in(t), m/s (x east, y north, z up); no rows: no incident wave. After
  // its last row it holds the last value: end the table at rest.
  History3 incident_velocity;
};

// rho (Vp n n^T + Vs (I - n n^T)) of the material, n the outward unit normal.
Matrix3d dashpot_matrix3(const Material3& m, const Vec3& outward_normal);

// The dashpots of face `face` of block p (the block's own material `m`) and,
// on an input face, the incident traction 2 D v_in (v_in the step's mean;
// zero: none), into the block's 12 x 12 stiffness and load.
void add_viscous_face_terms(const Polyhedron& p, int face, const Material3& m, const Vec3& incident_velocity,
                            double dt, Matrix12d& k, Vector12d& f);

// Energy of face `face` in a step with increment d: what its dashpots take
// out, and the work of the incident traction.
struct ViscousFaceEnergy {
  double absorbed = 0;
  double input_work = 0;
};
ViscousFaceEnergy viscous_face_energy(const Polyhedron& p, int face, const Material3& m,
                                      const Vec3& incident_velocity, const Vector12d& d, double dt);

// InputError naming `what` unless every face exists on its block and the
// incident velocity table is usable.
void check_viscous_boundary3(const ViscousBoundary3& v, const std::vector<Polyhedron>& blocks,
                             const std::string& what);

}  // namespace dda::df3
