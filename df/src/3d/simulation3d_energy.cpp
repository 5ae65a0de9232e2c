// The energy ledger's 3D kernel (df/core/energy.hpp; J), term for term the 2D
// one (simulation_physics.cpp); the bookkeeping, the residual and the order
// of the sums are energy_ledger.hpp's, shared with 2D:
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
//          breaks (advance_bolts, simulation3d_bolts.cpp, where
//          bolt_ground_work gives the ground's work on a bolt to a moving
//          fixed block).
//
// residual = input - (stored - stored at the start) - friction - damping - breakage:
// what the implicit step and the penalty springs dissipate, >= 0 but for
// rounding, and exactly 0 for a block without contacts, whose kinetic
// energy changes by the work done (constant acceleration in the step).
#include <cmath>
#include <cstddef>
#include <vector>

#include "dda/df/3d/simulation3d.hpp"
#include "core/energy_ledger.hpp"

namespace dda::df3 {

namespace {

// Energy held by a closed contact's springs.
double contact_spring_energy(const Contact3& c, const ContactSprings3& springs) {
  if (c.state == ContactState3::Open) return 0;
  return springs.normal_energy(c.normal_force) + c.shear_force.squaredNorm() / (2 * springs.ps);
}

}  // namespace

// The 3D kernel of the energy ledger (energy_ledger.hpp): the blocks'
// twelve unknowns; a fixed block (or one the ground moves) has none, holds
// no kinetic energy and takes no work of its own.
struct Simulation3::EnergyTerms {
  struct Step {
    const std::vector<Vector12d>& d;  // the step's increments, one per block
    double dt;
    double span;  // of the loads' time: 0 while settling (time stands still), else dt
    double beta;  // of the viscous damping: 0 while settling
  };
  const Simulation3& s;

  std::size_t block_count() const { return s.model_.blocks.size(); }

  // 1/2 v^T M v (the twelve rates) and V/2 sigma^T D^-1 sigma.
  df::BlockEnergy block_energy(std::size_t b) const {
    df::BlockEnergy e;
    if (s.dof_[b] >= 0) {  // fixed, or moved by the ground: no unknowns
      const Matrix12d m = mass_matrix(block_geometry(s.model_.blocks[b]), s.model_.material_of(b).density);
      e.kinetic = 0.5 * s.velocity_[b].dot(m * s.velocity_[b]);
    }
    if (const Vector6d& sigma = s.stress_[b]; !sigma.isZero())
      e.strain = 0.5 * s.model_.blocks[b].volume *
                 sigma.dot(elastic_matrix(s.model_.material_of(b)).ldlt().solve(sigma));
    return e;
  }

  // Gravity rho V g . u_c, the rest of the body acceleration (an earthquake
  // in loading mode) with the loads, the viscous damping's work
  // beta/dt V de^T D de.
  df::BlockWork block_work(std::size_t b, const Step& step) const {
    df::BlockWork w;
    if (s.dof_[b] < 0) return w;
    const Polyhedron& p = s.model_.blocks[b];
    const Material3& mat = s.model_.material_of(b);
    const Vec3 u = step.d[b].segment<3>(kTranslation);
    const double mass = mat.density * p.volume;
    w.gravity = mass * s.model_.gravity.dot(u);
    w.loads = mass * (s.body_acceleration_ - s.model_.gravity).dot(u);
    if (step.beta > 0) {
      const Vector6d de = step.d[b].segment<6>(kStrain);
      w.damping = step.beta / step.dt * p.volume * de.dot(elastic_matrix(mat) * de);
    }
    return w;
  }

  void book_step_terms(const Step& step, df::WorkBook& book) const {
    const Model3& model = s.model_;
    const std::vector<Vector12d>& d = step.d;
    for (std::size_t k = 0; k < model.loads.size(); ++k) {  // point loads
      const PointLoad3& l = model.loads[k];
      const auto b = static_cast<std::size_t>(l.block);
      const Vec3 u = displacement_matrix(s.load_at_[k], model.blocks[b].centroid) * d[b];
      book.loads(l.force.average(s.time_, s.time_ + step.span).dot(u));
    }
    for (const df::WaterLoad<3>& l : s.water_loads_) {  // the joint water
      const auto b = static_cast<std::size_t>(l.block);
      if (s.dof_[b] >= 0) book.loads(l.force.dot(displacement_matrix(l.at, model.blocks[b].centroid) * d[b]));
    }
    for (std::size_t k = 0; k < model.fixed_points.size(); ++k) {
      // A moving fixed point does work on its spring: the change of the
      // spring's energy plus the work the spring does on the block (as 2D).
      const FixedPoint3& f = model.fixed_points[k];
      const auto b = static_cast<std::size_t>(f.block);
      const Vec3 u = displacement_matrix(s.fixed_at_[k], model.blocks[b].centroid) * d[b];
      Vec3 target0 = f.position, target1 = f.position;
      if (f.motion) target0 += f.motion->at(s.time_), target1 += f.motion->at(s.time_ + step.span);
      const Vec3 gap0 = target0 - s.fixed_at_[k], gap1 = target1 - s.fixed_at_[k] - u;
      const double p = f.penalty > 0 ? f.penalty : 10 * model.normal_penalty;
      book.loads(0.5 * p * (gap1.squaredNorm() - gap0.squaredNorm()) + p * gap1.dot(u));
    }
    for (const Contact3& c : s.contacts_) {
      book.breakage(c.bond_released);  // a bond's springs at its break (simulation3d_bonds.cpp)
      if (c.state == ContactState3::Open) continue;
      if (c.state == ContactState3::Sliding) book.friction(std::abs(c.shear_force.dot(c.slip)));
      // The ground moving a fixed block loads the contact's springs:
      // -N dn_g - S . ds_g.
      const bool i_moved = s.dof_[c.i] < 0 && !d[c.i].isZero(), j_moved = s.dof_[c.j] < 0 && !d[c.j].isZero();
      if (i_moved) book.loads(-(c.normal_force * c.geo.en.dot(d[c.i]) + c.shear_force.dot(c.geo.es * d[c.i])));
      if (j_moved) book.loads(-(c.normal_force * c.geo.gn.dot(d[c.j]) + c.shear_force.dot(c.geo.gs * d[c.j])));
    }
    if (!s.bolts_.empty()) book.loads(s.bolt_ground_work(d));  // summed over the bolts, then booked
    if (s.model_.viscous) s.add_viscous_work(d, step.dt, book);  // radiation; the incident wave's work with the loads
  }

  // The bolts that broke in finish_step (advance_bolts), T^2/2k each.
  void book_released(df::WorkBook& book) const {
    for (const double released : s.bolt_released_) book.breakage(released);
  }

  void book_springs(df::SpringBook& book) const {
    // In contact order, a zero term leaving the sum as it was: the same on
    // any number of threads.
    for (const Contact3& c : s.contacts_)
      book.contact(contact_spring_energy(c, s.springs_of(c)));
    for (std::size_t k = 0; k < s.bolts_.size(); ++k) book.bolts(df::bolt_energy(s.model_.bolts[k], s.bolts_[k]));
    for (std::size_t k = 0; k < s.model_.fixed_points.size(); ++k) {
      const FixedPoint3& f = s.model_.fixed_points[k];
      Vec3 target = f.position;
      if (f.motion) target += f.motion->at(s.time_);
      const double p = f.penalty > 0 ? f.penalty : 10 * s.model_.normal_penalty;
      book.fixed(0.5 * p * (target - s.fixed_at_[k]).squaredNorm());
    }
  }
};

double Simulation3::kinetic_energy() const {
  // The ledger's own per-block term, summed in block order.
  const EnergyTerms k{*this};
  double sum = 0;
  for (std::size_t b = 0; b < model_.blocks.size(); ++b) sum += k.block_energy(b).kinetic;
  return sum;
}

void Simulation3::start_energy() {
  static_assert(df::EnergyKernel<EnergyTerms>);
  df::start_energy_log(energy_log_, EnergyTerms{*this}, time_);
}

void Simulation3::add_step_work(const std::vector<Vector12d>& d, double dt) {
  df::open_step_record(energy_log_, EnergyTerms{*this},
                       EnergyTerms::Step{d, dt, settling_ ? 0.0 : dt, settling_ ? 0.0 : model_.control.damping.beta()});
}

void Simulation3::close_energy_record() { df::close_step_record(energy_log_, EnergyTerms{*this}, time_); }

}  // namespace dda::df3
