#pragma once
// Non-reflecting (viscous) boundary of Lysmer and Kuhlemeyer (1969), and
// seismic input through it as an incident wave (a "compliant base").
//
// A boundary edge of a block stands for the contact with the same material
// continuing outside the model. Along it act the tractions of dashpots,
//   t = -D v,   D = rho Vp n n^T + rho Vs s s^T,
// n the outward normal and s the tangent of the edge, v the velocity of the
// boundary point: a plane wave reaching the edge at normal incidence leaves
// through it without reflection (the dashpot force is exactly the traction
// the outgoing wave would have carried on). With an incident wave of
// particle velocity v_in(t) coming in from outside, the traction on the edge
// is t = D (2 v_in - v): the incoming wave's traction D v_in plus the
// dashpot's, which takes back out whatever the model sends down again
// (Joyner & Chen 1975). v_in is half the motion a free surface of the base
// rock would have (the outcrop motion), since a free surface doubles it.
//
// The dashpot law is lysmer_dashpot.hpp's, shared with the 3D boundary
// (viscous_boundary3d.hpp). Wave speeds of the block's material in the
// plane of the model:
//   plane strain: Vp = sqrt(E (1 - nu) / ((1 + nu)(1 - 2 nu) rho)),
//   plane stress: Vp = sqrt(E / ((1 - nu^2) rho)),
//   both:         Vs = sqrt(E / (2 (1 + nu) rho)).
//
// Free-field edges (on the lateral sides of a model shaken by an incident
// wave): the dashpots act on the motion relative to the free field, the
// motion the incident wave gives a uniform half-space with the model's free
// surface, and the free field's own stresses are applied:
//   t = D (v_ff - v) + sigma_ff n.
// Without them a lateral dashpot drags on the plane wave itself (a layer
// shaken from below loses half its amplitude next to viscous sides) and a
// free side lacks the plane wave's stresses. v_ff and sigma_ff are
// free_field.hpp's (shared with 3D): from a base at y_b and a free surface
// at y_s, the x component of v_in an S wave at Vs, the y component a P wave
// at Vp; sigma_xx = sigma_yy nu / (1 - nu) in plane strain, nu sigma_yy in
// plane stress. The free field is that of one uniform material, the edge's
// own: the sides must stand in uniform rock.
//
// In the step: DDA integrates with constant acceleration, so the mean
// velocity over the step is v = T d / dt. The dashpot force is taken at
// that mean (the trapezoidal rule for a viscous force), which makes it an
// extra stiffness D / dt on the edge:
//   K_ii += (1/dt) integral of T^T D T ds,
//   F_i  += integral of T^T D (2 v_in) ds      (input edges only, v_in the
//            mean of the incident velocity over the step),
// the integrals along the edge in the configuration at the start of the step
// (T is linear along the edge, so two-point Gauss quadrature is exact). The
// energy the dashpots take out of the model in a step is
// (1/dt) integral of (T d)^T D (T d) ds >= 0.
#include <functional>

#include "dda/df/2d/block_kinematics.hpp"
#include "dda/df/core/free_field.hpp"
#include "dda/df/2d/model.hpp"

namespace dda::df {

class BlockSystem;
using Matrix2d = Eigen::Matrix2d;

double p_wave_speed(const Material& m);  // m/s, in the plane of the model
double s_wave_speed(const Material& m);  // m/s

// rho Vp n n^T + rho Vs s s^T for an edge with outward unit normal n.
Matrix2d dashpot_matrix(const Material& m, const Vec2& outward_normal);

// The traction an edge receives from outside besides its dashpots' -D v, as
// a function of the point on the edge (mean over the step): 2 D v_in on an
// input edge, D v_ff + sigma_ff n on a free-field edge, zero otherwise.
using EdgeTraction = std::function<Vec2(const Vec2& point)>;

// The incident wave's free field at height y, mean over [t0, t1]
// (free_field_traction() evaluates D v_ff + sigma_ff n from it).
using FreeField = FreeFieldMotion<2>;
FreeField free_field(const TimeHistory& incident, const Material& m, double y, double y_base, double y_surface,
                     double t0, double t1);
Vec2 free_field_traction(const FreeField& ff, const Material& m, const Matrix2d& dashpot, const Vec2& outward_normal);

// The dashpots of edge `edge` (vertex edge -> edge + 1, counter-clockwise)
// of block i with vertices `v` and centroid `c`, and the traction from
// outside (empty: none).
void add_viscous_edge_terms(int i, const Polygon2& v, const Vec2& c, int edge, const Matrix2d& dashpot,
                            const EdgeTraction& traction, double dt, BlockSystem& sys);

// Energy the edge's dashpots take out of the model in a step with
// increment di (J per unit thickness), and the work of the outside
// traction on the edge.
struct ViscousEdgeEnergy {
  double absorbed = 0;
  double input_work = 0;
};
ViscousEdgeEnergy viscous_edge_energy(const Polygon2& v, const Vec2& c, int edge, const Matrix2d& dashpot,
                                      const EdgeTraction& traction, const Vector6d& di, double dt);

}  // namespace dda::df
