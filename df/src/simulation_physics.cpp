// Physics extensions of the time stepper: bolts and the energy ledger
// (members of Simulation kept out of simulation.cpp, which is shared).
#include <cmath>
#include <cstddef>
#include <vector>

#include "dda/df/simulation.hpp"
#include "dda/df/viscous_boundary.hpp"
#include "block_terms.hpp"
#include "water_faces.hpp"

namespace dda::df {
namespace {

// compliance: the inverse of the elasticity matrix.
double strain_energy(const BlockState& b, const Matrix3d& compliance) {
  return 0.5 * b.geometry.area * b.stress.dot(compliance * b.stress);
}

// The body acceleration of a step [t, t + dt]: its mean over the step (so a
// piecewise-linear record gives the exact impulse); while settling into
// equilibrium (time frozen at t, pseudo steps) its value at t.
Vec2 step_body_acceleration(const BodyAcceleration& b, double t, double dt, bool settling) {
  return settling ? b.history.at(t) : b.history.average(t, t + dt);
}


}  // namespace

namespace {
Vec2 outward_normal(const Polygon2& v, int edge) {
  const Vec2 t = v[(edge + 1) % v.size()] - v[edge];
  return Vec2(t.y(), -t.x()).normalized();
}
}  // namespace

Eigen::Matrix2d Simulation::edge_dashpot(const ViscousEdge& e) const {
  return dashpot_matrix(model_.materials[model_.block_material[e.block]], outward_normal(blocks_[e.block].vertices, e.edge));
}

EdgeTraction Simulation::edge_traction(const ViscousEdge& e, const Eigen::Matrix2d& dashpot, double dt) const {
  const ViscousBoundary& vb = *model_.viscous_boundary;
  // No incident wave, or settling into equilibrium (time stands still): the
  // dashpots alone.
  if (vb.incident_velocity.t.empty() || settling_ || !(e.input || e.free_field)) return {};
  const double t0 = time_, t1 = time_ + dt;
  if (e.input) {
    const Vec2 traction = 2.0 * dashpot * vb.incident_velocity.average(t0, t1);
    return [traction](const Vec2&) { return traction; };
  }
  const Material& m = model_.materials[model_.block_material[e.block]];
  const Vec2 n = outward_normal(blocks_[e.block].vertices, e.edge);
  return [&vb, m, dashpot, n, t0, t1](const Vec2& p) {
    return free_field_traction(free_field(vb.incident_velocity, m, p.y(), vb.base_y, vb.surface_y, t0, t1), m,
                               dashpot, n);
  };
}

void Simulation::init_physics() {
  // Called by the constructor (bolts in their initial state) and again after
  // settling into equilibrium (bolts as settled): the histories and the
  // energy ledger start afresh from the current state.
  if (bolts_.size() != model_.bolts.size())
    for (const Bolt& b : model_.bolts) bolts_.push_back(initial_bolt_state(b));
  bolt_histories_.assign(model_.bolts.size(), {});
  for (std::size_t k = 0; k < bolts_.size(); ++k) {
    bolt_histories_[k].push_back(bolt_sample(time_, bolts_[k]));
  }
  // Stored energy of the starting state; the work sums start at zero.
  EnergyRecord e;
  e.time = time_;
  std::vector<ContactEnergy> terms(contacts_.size());
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(contacts_.size());
#pragma omp parallel for schedule(static) if (model_.block_count() > parallel_grain())
  for (std::ptrdiff_t k = 0; k < n; ++k) terms[k] = contact_energy(contacts_[k], Vector6d::Zero(), Vector6d::Zero());
  store_energy(e, terms);
  energy_start_ = e;
  energy_log_.assign(1, e);
}

void Simulation::assemble_physics(double dt) {
  if (const auto& ba = model_.body_acceleration) {
    // Like gravity: rho b S on the translations of each shaken block.
    const Vec2 b = step_body_acceleration(*ba, time_, dt, settling_);
    for (const int i : ba->blocks)
      system_.rhs(i).head<2>() += blocks_[i].geometry.area * model_.materials[model_.block_material[i]].density * b;
  }
  if (const auto& vb = model_.viscous_boundary) {
    for (const ViscousEdge& e : vb->edges) {
      const BlockState& b = blocks_[e.block];
      const Eigen::Matrix2d dashpot = edge_dashpot(e);
      add_viscous_edge_terms(e.block, b.vertices, b.geometry.centroid, e.edge, dashpot,
                             edge_traction(e, dashpot, dt), dt, system_);
    }
  }
  if (const auto& w = model_.water) {
    // Constant over the step, from its start: the contacts (open ones too,
    // within the search distance) say which faces face each other.
    std::vector<const Polygon2*> polygons(blocks_.size());
    for (std::size_t i = 0; i < blocks_.size(); ++i) polygons[i] = &blocks_[i].vertices;
    std::vector<double> saturation;
    for (const JointProperties& j : model_.joints) saturation.push_back(j.saturation);
    water_loads_ = water_loads_2d(*w, saturation, polygons, contacts_, model_.search_distance);
    for (const WaterLoad<2>& l : water_loads_) add_point_load(l.block, blocks_[l.block], l.at, l.force, system_);
  }
  for (std::size_t k = 0; k < bolts_.size(); ++k) {
    const Bolt& b = model_.bolts[k];
    add_bolt_terms(b, bolts_[k], blocks_[b.anchor_block].geometry.centroid, blocks_[b.head_block].geometry.centroid,
                   system_);
  }
}

Simulation::ContactEnergy Simulation::contact_energy(const Contact& c, const Vector6d& di, const Vector6d& dj) const {
  ContactEnergy t;
  if (c.state == ContactState::Open) return t;
  t.normal = normal_[c.joint]->energy_at_force(c.normal_force);
  // The shear spring is elastic-perfectly plastic: a sliding contact keeps
  // it stretched by its friction force over ps (a contact that sticks again
  // starts from that stretch, update_contact), so it stores S^2 / 2 ps in
  // either state. Counting it only while locked made every stick look like
  // energy created from nothing: a wall handed over by the start-up
  // relaxation with 170 sliding contacts, most of which stick in the first
  // step, showed a residual of -54 % of the (tiny) energy moved.
  t.shear = c.shear_force * c.shear_force / (2 * model_.joint_ps[c.joint]);
  if (c.state == ContactState::Sliding) {  // the friction force times the slip of the step
    const double slip = c.geo.es().dot(di) + c.geo.gc().dot(dj);
    t.friction_loss = std::abs(c.shear_force * slip);
  }
  return t;
}

void Simulation::before_accept(double dt, const Eigen::VectorXd& d) {
  // Work and losses of the step, from the configuration at its start. Every
  // force term is taken exactly as assembled (F . T d), so that for a block
  // without contacts the change of kinetic energy equals the work done.
  EnergyRecord e = energy_log_.back();
  auto di = [&](int i) { return Vector6d(d.segment<kDofs>(kDofs * i)); };
  // The mass products per block in parallel; the sums serially, in block
  // order (the same on any number of threads).
  const int nb = model_.block_count();
  std::vector<double> twice_kinetic(nb);  // v1' M v1
  std::vector<double> viscous(nb);        // the work of the damping stress, beta/dt S de' E de
  const double beta = damping_beta();
#pragma omp parallel for schedule(static) if (nb > parallel_grain())
  for (int i = 0; i < nb; ++i) {
    const BlockState& b = blocks_[i];
    const int m = model_.block_material[i];
    const Vector6d v1 = 2.0 / dt * di(i) - b.velocity;
    twice_kinetic[i] = v1.dot(mass_matrix(b.geometry, model_.materials[m].density) * v1);
    if (beta > 0) {
      const Vector3d de = di(i).tail<3>();
      viscous[i] = beta / dt * b.geometry.area * de.dot(emat_[m] * de);
    }
  }
  for (int i = 0; i < nb; ++i) {
    const BlockState& b = blocks_[i];
    const Material& mat = model_.materials[model_.block_material[i]];
    const double k = model_.control.dynamic;
    e.damping += (1 - k * k) * 0.5 * twice_kinetic[i] + viscous[i];
    e.gravity_work += b.geometry.area * mat.density * model_.gravity.dot(di(i).head<2>());
  }
  for (std::size_t k = 0; k < model_.loads.size(); ++k) {
    const PointLoad& l = model_.loads[k];
    const Vec2 u = t_matrix(blocks_[l.block].geometry.centroid, load_pos_[k]) * di(l.block);
    e.load_work += load_force(l, time_, time_ + dt).dot(u);
  }
  for (const WaterLoad<2>& l : water_loads_)  // the joint water, counted with the loads
    e.load_work += l.force.dot(t_matrix(blocks_[l.block].geometry.centroid, l.at) * di(l.block));
  if (const auto& ba = model_.body_acceleration) {  // counted with the loads
    const Vec2 b = step_body_acceleration(*ba, time_, dt, settling_);
    for (const int i : ba->blocks)
      e.load_work += blocks_[i].geometry.area * model_.materials[model_.block_material[i]].density *
                     b.dot(di(i).head<2>());
  }
  for (std::size_t k = 0; k < model_.fixed_points.size(); ++k) {
    // A moving fixed point does work on its spring: the change of the
    // spring's energy plus the work the spring does on the block.
    const FixedPoint& f = model_.fixed_points[k];
    const Vec2 u = t_matrix(blocks_[f.block].geometry.centroid, fixed_pos_[k]) * di(f.block);
    const Vec2 gap0 = fixed_point_target(f, fixed_anchor_[k], time_) - fixed_pos_[k];
    const Vec2 gap1 = fixed_point_target(f, fixed_anchor_[k], time_ + dt) - fixed_pos_[k] - u;
    const double p = *f.penalty;
    e.load_work += 0.5 * p * (gap1.squaredNorm() - gap0.squaredNorm()) + p * gap1.dot(u);
  }
  if (const auto& vb = model_.viscous_boundary) {
    for (const ViscousEdge& ve : vb->edges) {
      const BlockState& b = blocks_[ve.block];
      const Eigen::Matrix2d dashpot = edge_dashpot(ve);
      const ViscousEdgeEnergy w = viscous_edge_energy(b.vertices, b.geometry.centroid, ve.edge, dashpot,
                                                      edge_traction(ve, dashpot, dt), di(ve.block), dt);
      e.radiation += w.absorbed;
      e.load_work += w.input_work;
    }
  }
  // Summed serially in contact order (the same on any number of threads);
  // adding the zero of a contact not sliding leaves the sum as it was.
  for (const ContactEnergy& t : contact_energy_) e.friction += t.friction_loss;
  for (std::size_t k = 0; k < bolts_.size(); ++k) {
    const Bolt& b = model_.bolts[k];
    BoltState& s = bolts_[k];
    const Vec2 ca = blocks_[b.anchor_block].geometry.centroid, ch = blocks_[b.head_block].geometry.centroid;
    if (const double released = advance_bolt(b, s, ca, di(b.anchor_block), ch, di(b.head_block)); released > 0)
      e.breakage += released;
  }
  energy_log_.push_back(e);
}

void Simulation::after_accept(double /*dt*/) {
  for (std::size_t k = 0; k < bolts_.size(); ++k) {
    bolt_histories_[k].push_back(bolt_sample(time_, bolts_[k]));
  }
  // Stored energy at the end of the step.
  EnergyRecord& e = energy_log_.back();
  e.time = time_;
  store_energy(e, contact_energy_);
  e.residual =
      e.input() - (e.stored() - energy_start_.stored()) - e.friction - e.damping - e.breakage - e.radiation;
}

void Simulation::store_energy(EnergyRecord& e, const std::vector<ContactEnergy>& contacts) const {
  e.kinetic = e.elastic = e.contact = e.fixed = e.bolts = 0;
  // The per-block terms in parallel; the sums serially, in block order (the
  // same on any number of threads).
  const int nb = model_.block_count();
  std::vector<double> twice_kinetic(nb), strain(nb);  // v' M v, strain energy
#pragma omp parallel for schedule(static) if (nb > parallel_grain())
  for (int i = 0; i < nb; ++i) {
    const BlockState& b = blocks_[i];
    const int mat = model_.block_material[i];
    twice_kinetic[i] = b.velocity.dot(mass_matrix(b.geometry, model_.materials[mat].density) * b.velocity);
    strain[i] = strain_energy(b, compliance_[mat]);
  }
  for (int i = 0; i < nb; ++i) {
    e.kinetic += 0.5 * twice_kinetic[i];
    e.elastic += strain[i];
  }
  // Normal and shear springs as two terms, added one after the other in
  // contact order (a zero term leaves the sum as it was).
  for (const ContactEnergy& t : contacts) {
    e.contact += t.normal;
    e.contact += t.shear;
  }
  for (std::size_t k = 0; k < model_.fixed_points.size(); ++k) {
    const FixedPoint& f = model_.fixed_points[k];
    e.fixed += 0.5 * *f.penalty * (fixed_point_target(f, fixed_anchor_[k], time_) - fixed_pos_[k]).squaredNorm();
  }
  for (std::size_t k = 0; k < bolts_.size(); ++k) e.bolts += bolt_energy(model_.bolts[k], bolts_[k]);
}

}  // namespace dda::df
