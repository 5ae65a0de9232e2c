// Lysmer-Kuhlemeyer dashpots and the incident wave on the faces of 3D
// blocks (viscous_boundary3.hpp).
#include "dda/df/viscous_boundary3.hpp"

#include <string>

#include "dda/common/error.hpp"
#include "dda/df/lysmer_dashpot.hpp"
#include "dda/df/time_step.hpp"

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

void add_viscous_face_terms(const Polyhedron& p, int face, const Material3& m, const Vec3& incident_velocity,
                            double dt, Matrix12d& k, Vector12d& f) {
  const Matrix3d dashpot = dashpot_matrix3(m, p.faces[static_cast<std::size_t>(face)].normal);
  const Vec3 traction = 2.0 * dashpot * incident_velocity;
  const bool loaded = !incident_velocity.isZero();
  for_each_face_point(p, face, [&](const Vec3& x, double w) {
    const Matrix3x12d t = displacement_matrix(x, p.centroid);
    k += (w / dt) * t.transpose() * dashpot * t;
    if (loaded) f += w * t.transpose() * traction;
  });
}

ViscousFaceEnergy viscous_face_energy(const Polyhedron& p, int face, const Material3& m,
                                      const Vec3& incident_velocity, const Vector12d& d, double dt) {
  const Matrix3d dashpot = dashpot_matrix3(m, p.faces[static_cast<std::size_t>(face)].normal);
  const Vec3 traction = 2.0 * dashpot * incident_velocity;
  ViscousFaceEnergy e;
  for_each_face_point(p, face, [&](const Vec3& x, double w) {
    const Vec3 u = displacement_matrix(x, p.centroid) * d;
    e.absorbed += w * u.dot(dashpot * u) / dt;
    e.input_work += w * traction.dot(u);
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
}

}  // namespace dda::df3
