// Materials and the state at t = 0 of a 3D run (Model3: materials,
// block_material, initial_stress, initial_velocity).
//
// A model that does not hold together (no material, lists whose sizes do
// not match the blocks, a material that does not exist) and values a user
// could have typed (a material, a stress or velocity that is not finite, a
// moving fixed block) are an InputError of one sentence, as build_model()
// makes them in 2D (model.cpp): `dda` reports them as a problem of the input,
// not as an internal error.
#include <cmath>
#include <stdexcept>
#include <string>

#include "dda/common/error.hpp"
#include "dda/df/3d/simulation3d.hpp"

namespace dda::df3 {

namespace {

void check_material(const Material3& m, std::size_t index) {
  const std::string which = "3D material " + std::to_string(index);
  if (!(std::isfinite(m.density) && m.density > 0)) throw InputError(which + " needs a density > 0.");
  if (!(std::isfinite(m.young) && m.young > 0)) throw InputError(which + " needs a Young's modulus > 0.");
  // nu = 0.5 is incompressible (lambda infinite); nu <= -1 makes D indefinite.
  if (!(m.poisson > -1 && m.poisson < 0.5)) throw InputError(which + " needs a Poisson's ratio in (-1, 0.5).");
}

}  // namespace

void Simulation3::set_initial_state() {
  const std::size_t n = model_.blocks.size();
  if (model_.materials.empty()) throw InputError("The 3D model has no material.");
  for (std::size_t k = 0; k < model_.materials.size(); ++k) check_material(model_.materials[k], k);
  if (model_.block_material.empty()) model_.block_material.assign(n, 0);
  if (model_.block_material.size() != n)
    throw InputError("The 3D block material list has " + std::to_string(model_.block_material.size()) +
                     " entries for " + std::to_string(n) + " blocks.");
  for (std::size_t b = 0; b < n; ++b)
    if (const int k = model_.block_material[b]; k < 0 || static_cast<std::size_t>(k) >= model_.materials.size())
      throw InputError("3D block " + std::to_string(b) + " refers to material " + std::to_string(k) +
                       ", which does not exist.");

  if (model_.initial_stress.empty()) model_.initial_stress.assign(n, Vector6d::Zero());
  if (model_.initial_velocity.empty()) model_.initial_velocity.assign(n, Vector12d::Zero());
  if (model_.initial_stress.size() != n || model_.initial_velocity.size() != n)
    throw InputError("The 3D initial stress and velocity lists must be empty or have one entry per block.");
  for (std::size_t b = 0; b < n; ++b) {
    if (!model_.initial_stress[b].allFinite() || !model_.initial_velocity[b].allFinite())
      throw InputError("3D block " + std::to_string(b) + ": its initial stress or velocity is not a finite number.");
    // A fixed block has no unknowns: a velocity would be dropped without a word.
    if (model_.fixed[b] && !model_.initial_velocity[b].isZero())
      throw InputError("3D block " + std::to_string(b) + " is fixed, so it cannot have an initial velocity.");
  }
  velocity_ = model_.initial_velocity;
  stress_ = model_.initial_stress;
}

}  // namespace dda::df3
