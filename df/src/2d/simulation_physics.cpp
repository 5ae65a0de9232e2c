// Physics extensions of the time stepper: bolts and the energy ledger's 2D
// kernel (members of Simulation kept out of simulation.cpp, which is
// shared). The ledger's bookkeeping is energy_ledger.hpp's, shared with 3D.
#include <cmath>
#include <cstddef>
#include <vector>

#include "dda/df/2d/simulation.hpp"
#include "dda/df/2d/viscous_boundary.hpp"
#include "2d/block_terms.hpp"
#include "core/energy_ledger.hpp"
#include "2d/water_faces.hpp"

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
  start_energy();
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

// The 2D kernel of the energy ledger (energy_ledger.hpp): per unit
// thickness, the blocks' six unknowns, the contacts' terms as accept()
// evaluated them in its pass over the contacts.
struct Simulation::EnergyTerms {
  struct Step {
    const Eigen::VectorXd& d;  // the step's increments, kDofs per block
    double dt;
    double beta;  // of the viscous damping (damping_beta())
    Vector6d of(int block) const { return d.segment<kDofs>(kDofs * block); }
  };
  const Simulation& s;
  const std::vector<ContactEnergy>& contacts;  // one per contact of s.contacts_

  std::size_t block_count() const { return static_cast<std::size_t>(s.model_.block_count()); }

  BlockEnergy block_energy(std::size_t i) const {
    const BlockState& b = s.blocks_[i];
    const int mat = s.model_.block_material[i];
    const double twice_kinetic = b.velocity.dot(mass_matrix(b.geometry, s.model_.materials[mat].density) * b.velocity);
    return {0.5 * twice_kinetic, strain_energy(b, s.compliance_[mat])};
  }

  BlockWork block_work(std::size_t i, const Step& step) const {
    const BlockState& b = s.blocks_[i];
    const int m = s.model_.block_material[i];
    const Vector6d di = step.of(static_cast<int>(i));
    // The kinetic energy a dynamic parameter k < 1 takes from the end
    // velocity v1, and the work of the damping stress, beta/dt S de' E de.
    const Vector6d v1 = 2.0 / step.dt * di - b.velocity;
    const double twice_kinetic = v1.dot(mass_matrix(b.geometry, s.model_.materials[m].density) * v1);
    double viscous = 0;
    if (step.beta > 0) {
      const Vector3d de = di.tail<3>();
      viscous = step.beta / step.dt * b.geometry.area * de.dot(s.emat_[m] * de);
    }
    const double k = s.model_.control.dynamic;
    BlockWork w;
    w.damping = (1 - k * k) * 0.5 * twice_kinetic + viscous;
    w.gravity = b.geometry.area * s.model_.materials[m].density * s.model_.gravity.dot(di.head<2>());
    return w;  // the body acceleration is in the term list, after the water
  }

  // Every force term as assembled (F . T d), so that for a block without
  // contacts the change of kinetic energy equals the work done.
  void book_step_terms(const Step& step, WorkBook& book) const {
    const Model& model = s.model_;
    const double t0 = s.time_, t1 = s.time_ + step.dt;
    for (std::size_t k = 0; k < model.loads.size(); ++k) {  // point loads
      const PointLoad& l = model.loads[k];
      const Vec2 u = t_matrix(s.blocks_[l.block].geometry.centroid, s.load_pos_[k]) * step.of(l.block);
      book.loads(load_force(l, t0, t1).dot(u));
    }
    for (const WaterLoad<2>& l : s.water_loads_)  // the joint water
      book.loads(l.force.dot(t_matrix(s.blocks_[l.block].geometry.centroid, l.at) * step.of(l.block)));
    if (const auto& ba = model.body_acceleration) {  // rho S b . u_c of every shaken block
      const Vec2 b = step_body_acceleration(*ba, t0, step.dt, s.settling_);
      for (const int i : ba->blocks)
        book.loads(s.blocks_[i].geometry.area * model.materials[model.block_material[i]].density *
                   b.dot(step.of(i).head<2>()));
    }
    for (std::size_t k = 0; k < model.fixed_points.size(); ++k) {
      // A moving fixed point does work on its spring: the change of the
      // spring's energy plus the work the spring does on the block.
      const FixedPoint& f = model.fixed_points[k];
      const Vec2 u = t_matrix(s.blocks_[f.block].geometry.centroid, s.fixed_pos_[k]) * step.of(f.block);
      const Vec2 gap0 = fixed_point_target(f, s.fixed_anchor_[k], t0) - s.fixed_pos_[k];
      const Vec2 gap1 = fixed_point_target(f, s.fixed_anchor_[k], t1) - s.fixed_pos_[k] - u;
      const double p = *f.penalty;
      book.loads(0.5 * p * (gap1.squaredNorm() - gap0.squaredNorm()) + p * gap1.dot(u));
    }
    if (const auto& vb = model.viscous_boundary) {  // the dashpots' loss; an incident wave's work with the loads
      for (const ViscousEdge& ve : vb->edges) {
        const BlockState& b = s.blocks_[ve.block];
        const Eigen::Matrix2d dashpot = s.edge_dashpot(ve);
        const ViscousEdgeEnergy w = viscous_edge_energy(b.vertices, b.geometry.centroid, ve.edge, dashpot,
                                                        s.edge_traction(ve, dashpot, step.dt), step.of(ve.block),
                                                        step.dt);
        book.radiation(w.absorbed);
        book.loads(w.input_work);
      }
    }
    for (const ContactEnergy& t : contacts) book.friction(t.friction_loss);  // zero unless sliding
  }

  void book_released(WorkBook& book) const {
    for (const double released : s.bolt_released_) book.breakage(released);
  }

  // Normal and shear springs as two terms, one after the other in contact
  // order.
  void book_springs(SpringBook& book) const {
    for (const ContactEnergy& t : contacts) {
      book.contact(t.normal);
      book.contact(t.shear);
    }
    for (std::size_t k = 0; k < s.model_.fixed_points.size(); ++k) {
      const FixedPoint& f = s.model_.fixed_points[k];
      book.fixed(0.5 * *f.penalty *
                 (fixed_point_target(f, s.fixed_anchor_[k], s.time_) - s.fixed_pos_[k]).squaredNorm());
    }
    for (std::size_t k = 0; k < s.bolts_.size(); ++k) book.bolts(bolt_energy(s.model_.bolts[k], s.bolts_[k]));
  }
};

void Simulation::start_energy() {
  // The contacts' springs as they stand (no step: no friction loss).
  std::vector<ContactEnergy> terms(contacts_.size());
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(contacts_.size());
#pragma omp parallel for schedule(static) if (model_.block_count() > parallel_grain())
  for (std::ptrdiff_t k = 0; k < n; ++k) terms[k] = contact_energy(contacts_[k], Vector6d::Zero(), Vector6d::Zero());
  static_assert(EnergyKernel<EnergyTerms>);
  start_energy_log(energy_log_, EnergyTerms{*this, terms}, time_);
}

void Simulation::before_accept(double dt, const Eigen::VectorXd& d) {
  // The bolts' ends ride with their blocks (from the centroids at the
  // step's start); a bolt that breaks lets go of its energy.
  bolt_released_.assign(bolts_.size(), 0.0);
  for (std::size_t k = 0; k < bolts_.size(); ++k) {
    const Bolt& b = model_.bolts[k];
    const Vec2 ca = blocks_[b.anchor_block].geometry.centroid, ch = blocks_[b.head_block].geometry.centroid;
    bolt_released_[k] = advance_bolt(b, bolts_[k], ca, d.segment<kDofs>(kDofs * b.anchor_block), ch,
                                     d.segment<kDofs>(kDofs * b.head_block));
  }
  open_step_record(energy_log_, EnergyTerms{*this, contact_energy_}, EnergyTerms::Step{d, dt, damping_beta()});
}

void Simulation::after_accept(double /*dt*/) {
  for (std::size_t k = 0; k < bolts_.size(); ++k) {
    bolt_histories_[k].push_back(bolt_sample(time_, bolts_[k]));
  }
  close_step_record(energy_log_, EnergyTerms{*this, contact_energy_}, time_);
}

}  // namespace dda::df
