// The viscous boundary and the incident wave in the 3D step
// (viscous_boundary3d.hpp): the faces' dashpots in K, the incident traction
// in F, and both in the energy ledger.
#include <algorithm>

#include "dda/common/error.hpp"
#include "dda/df/3d/simulation3d.hpp"
#include "core/energy_ledger.hpp"
#include "3d/simulation3d_assembly.hpp"

namespace dda::df3 {

void Simulation3::check_viscous() const {
  const bool incident = model_.earthquake.mode && model_.earthquake.mode->route == df::GroundMotionRoute::incident_wave;
  if (!model_.viscous) {
    if (incident)
      throw InputError("The incident earthquake mode sends the wave in through a viscous boundary, and the model has "
                       "none (add the bottom to boundaries.viscous).");
    return;
  }
  const ViscousBoundary3& v = *model_.viscous;
  check_viscous_boundary3(v, model_.blocks, "Model3 viscous boundary");
  const bool has_input = std::any_of(v.faces.begin(), v.faces.end(), [](const ViscousFace3& f) { return f.input; });
  if (incident && !has_input)
    throw InputError("The incident earthquake mode sends the wave in through the viscous boundary's bottom faces, "
                     "and the model has none (add the bottom to boundaries.viscous).");
}

FaceTraction Simulation3::face_traction(const ViscousFace3& face, double dt) const {
  // Settling into equilibrium (time stands still): the dashpots alone.
  if (settling_) return {};
  const auto b = static_cast<std::size_t>(face.block);
  return face_traction3(*model_.viscous, face, model_.blocks[b], model_.material_of(b), time_, time_ + dt);
}

void Simulation3::add_viscous_terms(double dt, Assembly3& sys) const {
  // Settling into equilibrium the boundary carries nothing: a dashpot has
  // no static force, and the start-up relaxation's pseudo steps are not
  // motion.
  if (settling_) return;
  // In face order, serially: the sums do not depend on the threads.
  for (const ViscousFace3& face : model_.viscous->faces) {
    const auto b = static_cast<std::size_t>(face.block);
    if (dof_[b] < 0) continue;  // a fixed block has no unknowns
    Matrix12d k = Matrix12d::Zero();
    Vector12d f = Vector12d::Zero();
    add_viscous_face_terms(model_.blocks[b], face.face, model_.material_of(b), face_traction(face, dt), dt, k, f);
    sys.add_k(face.block, face.block, k);
    sys.add_f(face.block, f);
  }
}

// As 2D: the dashpots' absorption is radiation, the work of the traction
// from outside (the incident wave's on the base, the free field's on the
// sides) counts with the loads.
void Simulation3::add_viscous_work(const std::vector<Vector12d>& d, double dt, df::WorkBook& book) const {
  for (const ViscousFace3& face : model_.viscous->faces) {
    const auto b = static_cast<std::size_t>(face.block);
    if (dof_[b] < 0) continue;
    const ViscousFaceEnergy w =
        viscous_face_energy(model_.blocks[b], face.face, model_.material_of(b), face_traction(face, dt), d[b], dt);
    book.radiation(w.absorbed);
    book.loads(w.input_work);
  }
}

}  // namespace dda::df3
