#pragma once
// Non-reflecting (viscous) boundary of the 3D solver and seismic input
// through it as an incident wave: the 2D formulation (viscous_boundary.hpp)
// on the faces of polyhedral blocks, with the dashpots of
// lysmer_dashpot.hpp.
//
// A boundary face of a block stands for the same material continuing
// outside the model. On it act the tractions
//   t = D (2 v_in - v)            on an input face (the incident wave enters there),
//   t = D (v_ff - v) + sigma_ff n on a free-field face (a side of a model
//                                 shaken by the incident wave),
//   t = -D v                      on the others,
// D = rho (Vp n n^T + Vs (I - n n^T)), n the face's outward normal, v the
// velocity of the face's point, v_in(t) the incident wave's particle
// velocity (half the outcrop motion: a free surface doubles a wave), and
//   Vp = sqrt(E (1 - nu) / ((1 + nu)(1 - 2 nu) rho)),  Vs = sqrt(E / (2 (1 + nu) rho)).
//
// The free field (free_field.hpp, shared with 2D) is the motion the
// incident wave gives a uniform half-space of the face's material, whose
// free surface is the top of the free-field faces, and sigma_ff its
// stresses: v_in's x and y components are S waves (at Vs), its z component
// a P wave (at Vp), each up-going from the base plus its reflection from
// the surface; sigma_xz and sigma_yz are rho Vs times the down- less the
// up-going x and y velocity, sigma_zz rho Vp times that of z, and sigma_xx
// = sigma_yy = sigma_zz nu / (1 - nu) (a plane wave strains no horizontal
// line), sigma_xy = 0. So a west or east face (n = -+x) receives the shear
// sigma_xz n_x along z and the normal sigma_xx n_x, a south or north face
// sigma_yz n_y along z and sigma_yy n_y. Without the free field, dashpots
// on the sides drag on the vertically travelling wave itself.
//
// In the step (as 2D): the velocity is the step's mean, T d / dt, so the
// dashpots are a stiffness D / dt on the face, and v_in is the mean of the
// incident velocity over the step:
//   K_ii += (1/dt) integral over the face of T^T D T dA,
//   F_i  += integral of T^T D (2 v_in) dA  (input faces),
// T = displacement_matrix(x, centroid) (3 x 12, linear in x), the integrals
// over the face at the start of the step, exactly (a fan of triangles from
// the face's first vertex, each with the edge-midpoint rule, exact for
// quadratics; the free field varies along z, so on the sides it is
// approximate). The energy the dashpots take out in a step is
// (1/dt) integral of (T d)^T D (T d) dA >= 0 (the ledger's radiation); the
// work of the traction from outside, integral of t_out . (T d) dA with
// t_out = 2 D v_in or D v_ff + sigma_ff n, counts with the loads (as 2D).
//
// The boundary carries no static load (as in 2D): a model under gravity
// resting on a viscous base alone sinks through it.
#include <functional>
#include <string>
#include <vector>

#include "dda/common/polyhedron_model.hpp"
#include "dda/df/3d/block3d.hpp"
#include "dda/df/3d/points3d.hpp"

namespace dda::df3 {

struct ViscousFace3 {
  int block = -1;
  int face = -1;            // index into the block's faces
  bool input = false;       // the incident wave enters here
  bool free_field = false;  // a side face: dashpots relative to the incident wave's free field
};

struct ViscousBoundary3 {
  std::vector<ViscousFace3> faces;
  // v_in(t), m/s (x east, y north, z up); no rows: no incident wave. After
  // its last row it holds the last value: end the table at rest.
  TimeHistory3 incident_velocity;
  // Heights of the base the wave enters through and of the free surface
  // above the free-field faces, m (z).
  double base_z = 0, surface_z = 0;
};

// rho (Vp n n^T + Vs (I - n n^T)) of the material, n the outward unit normal.
Matrix3d dashpot_matrix3(const Material3& m, const Vec3& outward_normal);

// The traction a face receives from outside besides its dashpots' -D v, as
// a function of the point of the face (mean over the step): 2 D v_in on an
// input face, D v_ff + sigma_ff n on a free-field face; empty: none.
using FaceTraction = std::function<Vec3(const Vec3& point)>;

// That traction on face `f` of the boundary `v` over the step [t0, t1], for
// the face's block p of material m (empty without an incident wave).
FaceTraction face_traction3(const ViscousBoundary3& v, const ViscousFace3& f, const Polyhedron& p,
                            const Material3& m, double t0, double t1);

// D v_ff + sigma_ff n at height z over [t0, t1] (free_field.hpp) for a face
// of outward normal n.
Vec3 free_field_traction3(const ViscousBoundary3& v, const Material3& m, const Vec3& n, double z, double t0,
                          double t1);

// The dashpots of face `face` of block p (the block's own material `m`) and
// the traction from outside, into the block's 12 x 12 stiffness and load.
void add_viscous_face_terms(const Polyhedron& p, int face, const Material3& m, const FaceTraction& traction,
                            double dt, Matrix12d& k, Vector12d& f);

// Energy of face `face` in a step with increment d: what its dashpots take
// out, and the work of the traction from outside.
struct ViscousFaceEnergy {
  double absorbed = 0;
  double input_work = 0;
};
ViscousFaceEnergy viscous_face_energy(const Polyhedron& p, int face, const Material3& m,
                                      const FaceTraction& traction, const Vector12d& d, double dt);

// InputError naming `what` unless every face exists on its block and the
// incident velocity table is usable.
void check_viscous_boundary3(const ViscousBoundary3& v, const std::vector<Polyhedron>& blocks,
                             const std::string& what);

}  // namespace dda::df3
