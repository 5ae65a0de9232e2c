// The energy ledger of the 3D solver (df/energy.hpp; J), term for term the
// 2D one (simulation_physics.cpp):
//
// stored   kinetic 1/2 v^T M v of the free blocks (the twelve rates); elastic
//          V/2 sigma^T D^-1 sigma; contact E_n(N) + |S|^2/2ps of every
//          closed contact, E_n the normal law's energy at N (N^2/2pn for
//          the linear penalty) (a sliding one keeps its shear spring stretched by
//          the friction force); fixed p/2 |gap|^2 of the fixed-point springs;
//          bolts T^2/2k of every intact bolt.
// input    gravity rho V g . u_c; loads: the rest of the body acceleration
//          (an earthquake in loading mode), point loads and the joint water's
//          loads as assembled, moving
//          fixed points (the change of their spring's energy plus the work
//          it does on the block) and the ground of an earthquake in
//          displacement mode, which moves the fixed blocks: the work it does
//          on the contact springs, -N dn_g - S . ds_g, dn_g and ds_g the
//          changes of the contact's gap and slip that the ground's own
//          increment makes.
// losses   friction |S . slip| of every sliding contact; damping, the work
//          of the viscous stress beta/dt V de^T D de (control.damping);
//          breakage, the energy a joint's bond held in its springs when it
//          broke (simulation3d_bonds.cpp), and T^2/2k of a bolt when it
//          breaks (simulation3d_bolts.cpp, which also books the ground's
//          work on a bolt to a moving fixed block).
//
// residual = input - (stored - stored at the start) - friction - damping - breakage:
// what the implicit step and the penalty springs dissipate, >= 0 but for
// rounding, and exactly 0 for a block without contacts, whose kinetic
// energy changes by the work done (constant acceleration in the step).
#include <vector>

#include "dda/df/block_system.hpp"
#include "dda/df/simulation3d.hpp"

namespace dda::df3 {

namespace {

// Energy held by a closed contact's springs.
double contact_spring_energy(const Contact3& c, const ContactSprings3& springs) {
  if (c.state == ContactState3::Open) return 0;
  return springs.normal_energy(c.normal_force) + c.shear_force.squaredNorm() / (2 * springs.ps);
}

// Sum of term(b) over the blocks: the terms in parallel, the sum serially
// in block order (the same on any number of threads).
template <class Term>
double sum_over_blocks(std::size_t n, Term term) {
  std::vector<double> terms(n);
  const int nb = static_cast<int>(n);
#pragma omp parallel for schedule(static) if (nb > df::parallel_grain())
  for (int b = 0; b < nb; ++b) terms[static_cast<std::size_t>(b)] = term(static_cast<std::size_t>(b));
  double sum = 0;
  for (const double t : terms) sum += t;
  return sum;
}

}  // namespace

double Simulation3::kinetic_energy() const {
  return sum_over_blocks(model_.blocks.size(), [this](std::size_t b) {
    if (dof_[b] < 0) return 0.0;  // fixed, or moved by the ground: no unknowns
    const Matrix12d m = mass_matrix(block_geometry(model_.blocks[b]), model_.material_of(b).density);
    return 0.5 * velocity_[b].dot(m * velocity_[b]);
  });
}

void Simulation3::start_energy() {
  df::EnergyRecord e;
  e.time = time_;
  store_energy(e);
  energy_start_ = e;
  energy_log_.assign(1, e);
}

void Simulation3::store_energy(df::EnergyRecord& e) const {
  e.kinetic = kinetic_energy();
  e.elastic = sum_over_blocks(model_.blocks.size(), [this](std::size_t b) {
    const Vector6d& sigma = stress_[b];
    if (sigma.isZero()) return 0.0;
    return 0.5 * model_.blocks[b].volume * sigma.dot(elastic_matrix(model_.material_of(b)).ldlt().solve(sigma));
  });
  e.contact = e.fixed = e.bolts = 0;
  // In contact order, a zero term leaving the sum as it was: the same on
  // any number of threads.
  for (const Contact3& c : contacts_) e.contact += contact_spring_energy(c, springs_of(c));
  e.bolts = stored_bolt_energy();
  for (std::size_t k = 0; k < model_.fixed_points.size(); ++k) {
    const FixedPoint3& f = model_.fixed_points[k];
    Vec3 target = f.position;
    if (f.motion) target += f.motion->at(time_);
    const double p = f.penalty > 0 ? f.penalty : 10 * model_.normal_penalty;
    e.fixed += 0.5 * p * (target - fixed_at_[k]).squaredNorm();
  }
}

void Simulation3::add_step_work(const std::vector<Vector12d>& d, double dt) {
  df::EnergyRecord e = energy_log_.back();
  const double span = settling_ ? 0.0 : dt;
  const double beta = settling_ ? 0.0 : model_.control.damping.beta();
  for (std::size_t b = 0; b < model_.blocks.size(); ++b) {
    if (dof_[b] < 0) continue;
    const Polyhedron& p = model_.blocks[b];
    const Material3& mat = model_.material_of(b);
    const Vec3 u = d[b].segment<3>(kTranslation);
    const double mass = mat.density * p.volume;
    e.gravity_work += mass * model_.gravity.dot(u);
    e.load_work += mass * (body_acceleration_ - model_.gravity).dot(u);
    if (beta > 0) {
      const Vector6d de = d[b].segment<6>(kStrain);
      e.damping += beta / dt * p.volume * de.dot(elastic_matrix(mat) * de);
    }
  }
  for (std::size_t k = 0; k < model_.loads.size(); ++k) {
    const PointLoad3& l = model_.loads[k];
    const auto b = static_cast<std::size_t>(l.block);
    const Vec3 u = displacement_matrix(load_at_[k], model_.blocks[b].centroid) * d[b];
    e.load_work += l.force.average(time_, time_ + span).dot(u);
  }
  for (const df::WaterLoad<3>& l : water_loads_) {  // the joint water, counted with the loads
    const auto b = static_cast<std::size_t>(l.block);
    if (dof_[b] >= 0) e.load_work += l.force.dot(displacement_matrix(l.at, model_.blocks[b].centroid) * d[b]);
  }
  for (std::size_t k = 0; k < model_.fixed_points.size(); ++k) {
    // A moving fixed point does work on its spring: the change of the
    // spring's energy plus the work the spring does on the block (as 2D).
    const FixedPoint3& f = model_.fixed_points[k];
    const auto b = static_cast<std::size_t>(f.block);
    const Vec3 u = displacement_matrix(fixed_at_[k], model_.blocks[b].centroid) * d[b];
    Vec3 target0 = f.position, target1 = f.position;
    if (f.motion) target0 += f.motion->at(time_), target1 += f.motion->at(time_ + span);
    const Vec3 gap0 = target0 - fixed_at_[k], gap1 = target1 - fixed_at_[k] - u;
    const double p = f.penalty > 0 ? f.penalty : 10 * model_.normal_penalty;
    e.load_work += 0.5 * p * (gap1.squaredNorm() - gap0.squaredNorm()) + p * gap1.dot(u);
  }
  for (const Contact3& c : contacts_) {
    e.breakage += c.bond_released;  // a bond's springs at its break (simulation3d_bonds.cpp)
    if (c.state == ContactState3::Open) continue;
    if (c.state == ContactState3::Sliding) e.friction += std::abs(c.shear_force.dot(c.slip));
    // The ground moving a fixed block loads the contact's springs.
    const bool i_moved = dof_[c.i] < 0 && !d[c.i].isZero(), j_moved = dof_[c.j] < 0 && !d[c.j].isZero();
    if (i_moved)
      e.load_work -= c.normal_force * c.geo.en.dot(d[c.i]) + c.shear_force.dot(c.geo.es * d[c.i]);
    if (j_moved)
      e.load_work -= c.normal_force * c.geo.gn.dot(d[c.j]) + c.shear_force.dot(c.geo.gs * d[c.j]);
  }
  if (!bolts_.empty()) e.load_work += bolt_ground_work(d);
  if (model_.viscous) add_viscous_work(d, dt, e);  // radiation, and the incident wave's work with the loads
  energy_log_.push_back(e);
}

void Simulation3::close_energy_record() {
  df::EnergyRecord& e = energy_log_.back();
  e.time = time_;
  store_energy(e);
  e.residual = e.input() - (e.stored() - energy_start_.stored()) - e.friction - e.damping - e.breakage - e.radiation;
}

}  // namespace dda::df3
