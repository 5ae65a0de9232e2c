// Lysmer-Kuhlemeyer dashpots and the incident wave on the faces of 3D
// blocks (viscous_boundary3d.hpp).
#include "dda/df/3d/viscous_boundary3d.hpp"

#include <string>

#include "dda/common/error.hpp"
#include "dda/common/short_number.hpp"
#include "dda/df/core/free_field.hpp"
#include "dda/df/core/lysmer_dashpot.hpp"
#include "dda/df/core/time_step.hpp"

namespace dda::df3 {
namespace {

// Calls point(x, weight) at quadrature points of the face whose weights
// integrate any quadratic in x exactly over it: the face (convex, planar) is
// a fan of triangles from its first vertex, each with the three midpoints
// of its sides at a third of its area.
template <class Point>
void for_each_face_point(const Polyhedron& p, int face, Point&& point) {
  const std::vector<int>& v = p.faces[static_cast<std::size_t>(face)].vertices;
  const Vec3& a = p.vertices[static_cast<std::size_t>(v[0])];
  for (std::size_t k = 1; k + 1 < v.size(); ++k) {
    const Vec3& b = p.vertices[static_cast<std::size_t>(v[k])];
    const Vec3& c = p.vertices[static_cast<std::size_t>(v[k + 1])];
    const double third = (b - a).cross(c - a).norm() / 6;  // area / 3
    point(0.5 * (a + b), third);
    point(0.5 * (b + c), third);
    point(0.5 * (c + a), third);
  }
}

}  // namespace

Matrix3d dashpot_matrix3(const Material3& m, const Vec3& n) {
  return df::lysmer_dashpot<3>(m.density, df::p_wave_speed(m.young, m.poisson, m.density, false),
                               df::shear_wave_speed(m.young, m.poisson, m.density), n);
}

Vec3 free_field_traction3(const ViscousBoundary3& v, const Material3& m, const Vec3& n, double z, double t0,
                          double t1) {
  const double vp = df::p_wave_speed(m.young, m.poisson, m.density, false);
  const double vs = df::shear_wave_speed(m.young, m.poisson, m.density);
  const df::FreeFieldMotion<3> ff =
      df::free_field_motion<3>(v.incident_velocity, vs, vp, z, v.base_z, v.surface_z, t0, t1);
  // A plane wave strains no horizontal line: sigma_xx = sigma_yy = nu / (1 - nu) sigma_zz.
  const double lateral = m.poisson / (1 - m.poisson);
  return dashpot_matrix3(m, n) * ff.velocity + df::free_field_stress(ff, m.density, vs, vp, lateral) * n;
}

FaceTraction face_traction3(const ViscousBoundary3& v, const ViscousFace3& f, const Polyhedron& p,
                            const Material3& m, double t0, double t1) {
  if (v.incident_velocity.t.empty() || !(f.input || f.free_field)) return {};
  const Vec3 n = p.faces[static_cast<std::size_t>(f.face)].normal;
  if (f.input) {
    const Vec3 traction = 2.0 * dashpot_matrix3(m, n) * v.incident_velocity.average(t0, t1);
    return [traction](const Vec3&) { return traction; };
  }
  return [&v, m, n, t0, t1](const Vec3& x) { return free_field_traction3(v, m, n, x.z(), t0, t1); };
}

void add_viscous_face_terms(const Polyhedron& p, int face, const Material3& m, const FaceTraction& traction,
                            double dt, Matrix12d& k, Vector12d& f) {
  const Matrix3d dashpot = dashpot_matrix3(m, p.faces[static_cast<std::size_t>(face)].normal);
  for_each_face_point(p, face, [&](const Vec3& x, double w) {
    const Matrix3x12d t = displacement_matrix(x, p.centroid);
    k += (w / dt) * t.transpose() * dashpot * t;
    if (traction) f += w * t.transpose() * traction(x);
  });
}

ViscousFaceEnergy viscous_face_energy(const Polyhedron& p, int face, const Material3& m,
                                      const FaceTraction& traction, const Vector12d& d, double dt) {
  const Matrix3d dashpot = dashpot_matrix3(m, p.faces[static_cast<std::size_t>(face)].normal);
  ViscousFaceEnergy e;
  for_each_face_point(p, face, [&](const Vec3& x, double w) {
    const Vec3 u = displacement_matrix(x, p.centroid) * d;
    e.absorbed += w * u.dot(dashpot * u) / dt;
    if (traction) e.input_work += w * traction(x).dot(u);
  });
  return e;
}

void check_viscous_boundary3(const ViscousBoundary3& v, const std::vector<Polyhedron>& blocks,
                             const std::string& what) {
  for (const ViscousFace3& f : v.faces) {
    const bool block_ok = f.block >= 0 && static_cast<std::size_t>(f.block) < blocks.size();
    if (!block_ok || f.face < 0 ||
        static_cast<std::size_t>(f.face) >= blocks[static_cast<std::size_t>(f.block)].faces.size())
      throw InputError(what + ": face " + std::to_string(f.face) + " of block " + std::to_string(f.block) +
                       " does not exist.");
  }
  if (!v.incident_velocity.t.empty()) v.incident_velocity.check(what + ", incident velocity");
  bool free_field = false;
  for (const ViscousFace3& f : v.faces) {
    if (f.input && f.free_field)
      throw InputError(what + ": face " + std::to_string(f.face) + " of block " + std::to_string(f.block) +
                       " is both an input face and a free-field face; the wave enters at the base, the free field "
                       "stands on the sides.");
    free_field = free_field || f.free_field;
  }
  // The free field is a wave going up from the base and back down from the
  // surface: a surface at or below the base has none.
  if (free_field && !(v.surface_z > v.base_z))
    throw InputError(what + ": the free field's surface (z = " + short_number(v.surface_z) +
                     " m) must lie above its base (z = " + short_number(v.base_z) + " m).");
}

}  // namespace dda::df3
