// The 3D time step: assembly of K d = F with 12x12 blocks, open-close
// iteration, and the end-of-step update (simulation3d.hpp).
#include "dda/df/3d/simulation3d.hpp"

#include "dda/df/core/bond.hpp"

#include "3d/contact_coupling3d.hpp"
#include "core/open_close.hpp"
#include "3d/simulation3d_assembly.hpp"
#include "core/start_up_relax.hpp"
#include "core/step_control.hpp"
#include "3d/water_faces3d.hpp"
#include "dda/common/error.hpp"
#include "dda/df/core/runaway.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dda/df/core/block_system.hpp"  // parallel_grain

namespace dda::df3 {

namespace {

// The free-block pairs of the contacts, in contact order (K's pattern
// follows from them; open contacts count too, so it holds while their
// states change).
std::vector<std::pair<int, int>> contact_pairs(const std::vector<Contact3>& contacts, const std::vector<int>& dof) {
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(contacts.size());
  for (const Contact3& c : contacts)
    if (dof[c.i] >= 0 && dof[c.j] >= 0) pairs.emplace_back(c.i, c.j);
  return pairs;
}

}  // namespace

Eigen::SparseMatrix<double> block_lower_pattern(const std::vector<int>& dof, int n_dofs,
                                                const std::vector<std::pair<int, int>>& pairs) {
  // Neighbours after each block column, as first unknowns, sorted and unique.
  const int columns = n_dofs / kDofs;
  std::vector<std::vector<int>> below(static_cast<std::size_t>(columns));
  for (const auto& [i, j] : pairs) {
    const int lo = std::min(dof[i], dof[j]), hi = std::max(dof[i], dof[j]);
    if (lo >= 0 && lo != hi) below[lo / kDofs].push_back(hi);
  }
  std::size_t nnz = 0;
  for (auto& rows : below) {
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    nnz += kDofs * (kDofs + 1) / 2 + kDofs * kDofs * rows.size();
  }
  Eigen::SparseMatrix<double> k(n_dofs, n_dofs);
  k.resizeNonZeros(static_cast<Eigen::Index>(nnz));
  int* outer = k.outerIndexPtr();
  int* inner = k.innerIndexPtr();
  int at = 0;
  for (int b = 0; b < columns; ++b)
    for (int c = 0; c < kDofs; ++c) {
      outer[kDofs * b + c] = at;
      for (int r = c; r < kDofs; ++r) inner[at++] = kDofs * b + r;
      for (const int first : below[b])
        for (int r = 0; r < kDofs; ++r) inner[at++] = first + r;
    }
  outer[n_dofs] = at;
  std::fill(k.valuePtr(), k.valuePtr() + nnz, 0.0);
  return k;
}

namespace {
df::PcgOptions pcg_options3() {
  df::PcgOptions o;
  o.block_size = kDofs;
  // Trial solves to 1e-4, not 2D's 1e-6: on the 1k jointed cube (two
  // threads, bench/df3d.sh) PCG then takes 22 iterations a solve instead of
  // 37 with the same open-close iterations, and the 10k step falls from 4.2
  // to 3.0 s; the sliding raft of test_solver_pcg3d.cpp stays 1.7e-6 from
  // CHOLMOD. (1e-2 moved it 2.4e-4. In 2D, 1e-4 costs more open-close
  // iterations than it saves: 144 -> 168 ms on the 10k layered model.)
  o.trial_tolerance = 1e-4;
  return o;
}
}  // namespace

Simulation3::Simulation3(Model3 model)
    : model_(std::move(model)),
      solver_(df::make_solver(model_.control.solver, kAutoPcgBlocks3, pcg_options3())),
      coupling_(std::make_unique<ContactCoupling3>()) {
  const size_t n = model_.blocks.size();
  if (model_.fixed.empty()) model_.fixed.assign(n, false);
  if (model_.fixed.size() != n)
    throw InputError("The 3D fixed-block list has " + std::to_string(model_.fixed.size()) + " entries for " +
                     std::to_string(n) + " blocks.");
  for (size_t b = 0; b < n; ++b) {
    refresh_geometry(model_.blocks[b]);
    dof_.push_back(model_.fixed[b] ? -1 : n_dofs_);
    if (!model_.fixed[b]) n_dofs_ += kDofs;
  }
  set_initial_state();
  known_.assign(n, Vector12d::Zero());
  if (model_.earthquake.motion && !model_.earthquake.mode)
    throw InputError("The 3D earthquake has no mode: give loading, displacement or incident.");
  make_friction_laws();
  springs_ = contact_springs3(model_);
  springs_.push_back(glue_springs3(springs_.back()));  // at Model3::glue_joint
  index_points();
  start_bolts();
  check_viscous();
  start_energy();
  // w0: half the largest side of the model's bounding box (the 2D solver
  // takes half the height); it scales the displacement limit of a step.
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const auto& p : model_.blocks)
    for (const auto& v : p.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  w0_ = n > 0 ? 0.5 * (hi - lo).maxCoeff() : 1.0;
  const Control3& c = model_.control;
  if (!(c.dt > 0) || !(c.max_displacement_ratio > 0) || !(c.min_dt_ratio > 0 && c.min_dt_ratio <= 1) ||
      c.total_time < 0 || c.steps < 0)
    throw InputError("3D control: dt, max_displacement_ratio and min_dt_ratio must be positive (min_dt_ratio at "
                     "most 1), total_time and steps not negative.");
}

Simulation3::~Simulation3() = default;
Simulation3::Simulation3(Simulation3&&) noexcept = default;
Simulation3& Simulation3::operator=(Simulation3&&) noexcept = default;

void Simulation3::make_friction_laws() {
  auto add = [&](const df::JointProperties& joint) {
    bonds_used_ = bonds_used_ || df::forms_bonds(joint);
    friction_.push_back(df::make_friction_law(joint));
  };
  for (const df::JointProperties& joint : model_.joint_sets) add(joint);
  add(model_.default_joint);
}

// Contacts share blocks. add(range) runs for each of kParts fixed ranges of
// block columns in parallel; it goes over the contacts in order and adds
// the terms of those that touch the range, which keeps what lands in its
// columns of K and rows of F (Assembly3): every entry is summed in contact
// order on any number of threads. A contact across two ranges is formed by
// both (few are, blocks being numbered by position).
template <class AddTerms>
void Simulation3::for_each_range(Eigen::VectorXd& f, AddTerms&& add) {
  const int free_blocks = n_dofs_ / kDofs;
  const int nb = static_cast<int>(model_.blocks.size());
#pragma omp parallel for schedule(dynamic, 1) if (nb > df::parallel_grain())
  for (int part = 0; part < kRanges; ++part) {
    Assembly3 range{dof_, k_lower_, f, kDofs * (free_blocks * part / kRanges),
                    kDofs * (free_blocks * (part + 1) / kRanges)};
    add(range, range_contacts_[static_cast<std::size_t>(part)]);
  }
}

int Simulation3::range_of(int b) const {
  const int dof = dof_[static_cast<std::size_t>(b)];
  if (dof < 0) return -1;
  // The ranges of for_each_range: free block number dof / kDofs falls in
  // the last part whose first block is at or before it.
  const int free_blocks = n_dofs_ / kDofs, block = dof / kDofs;
  int part = kRanges - 1;
  while (part > 0 && block < free_blocks * part / kRanges) --part;
  return part;
}

void Simulation3::index_ranges() {
  // One pass over the contacts, instead of every range going over all of
  // them in every assembly (254,000 contacts of 960 bytes at 10,000 blocks).
  for (auto& list : range_contacts_) list.clear();
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    const int ri = range_of(contacts_[k].i), rj = range_of(contacts_[k].j);
    if (ri >= 0) range_contacts_[static_cast<std::size_t>(ri)].push_back(static_cast<int>(k));
    if (rj >= 0 && rj != ri) range_contacts_[static_cast<std::size_t>(rj)].push_back(static_cast<int>(k));
  }
}

void Simulation3::assemble(double dt) {
  std::vector<std::pair<int, int>> pairs = contact_pairs(contacts_, dof_);
  add_bolt_pairs(pairs);
  if (pairs != k_pairs_ || k_lower_.rows() != n_dofs_) {
    k_lower_ = block_lower_pattern(dof_, n_dofs_, pairs);
    k_pairs_ = std::move(pairs);
  } else {
    std::fill(k_lower_.valuePtr(), k_lower_.valuePtr() + k_lower_.nonZeros(), 0.0);
  }
  block_loads_ = Eigen::VectorXd::Zero(n_dofs_);
  Assembly3 sys{dof_, k_lower_, block_loads_};
  // Each block writes only its own diagonal block and F segment: the
  // result does not depend on the number of threads.
  const int nb = static_cast<int>(model_.blocks.size());
#pragma omp parallel for schedule(static) if (nb > df::parallel_grain())
  for (int b = 0; b < nb; ++b) {
    if (dof_[b] < 0) continue;
    const BlockGeometry3 g = block_geometry(model_.blocks[b]);
    Matrix12d k = Matrix12d::Zero();
    Vector12d f = Vector12d::Zero();
    const Material3& material = model_.material_of(static_cast<std::size_t>(b));
    add_inertia(g, material.density, velocity_[b], dt, k, f);
    add_elasticity(g, material, stress_[b], settling_ ? 0.0 : model_.control.damping.beta() / dt, k, f);
    add_body_force(g, material.density, body_acceleration_, f);
    add_point_terms(b, dt, g, k, f);
    sys.add_k(b, b, k);
    sys.add_f(b, f);
  }
  if (model_.water) {
    // The joint water's loads on facing faces (water_faces3d.cpp), from the
    // geometry at the step's start; a fixed block takes none.
    std::vector<double> saturation;
    for (const df::JointProperties& j : model_.joint_sets) saturation.push_back(j.saturation);
    saturation.push_back(model_.default_joint.saturation);
    saturation.push_back(0.0);  // glue_joint: inside one piece of rock, no joint to fill
    water_loads_ = df::water_loads_3d(*model_.water, saturation, model_.blocks, contacts_, model_.contact_reach);
    for (const df::WaterLoad<3>& l : water_loads_) {
      if (dof_[static_cast<std::size_t>(l.block)] < 0) continue;
      Vector12d f = Vector12d::Zero();
      add_point_load(block_geometry(model_.blocks[static_cast<std::size_t>(l.block)]), l.at, l.force, f);
      sys.add_f(l.block, f);
    }
  }
  add_bolt_terms(sys);
  if (model_.viscous) add_viscous_terms(dt, sys);
  for_each_range(block_loads_, [this](Assembly3& range, const std::vector<int>& mine) {
    for (const int k : mine) {
      const Contact3& c = contacts_[static_cast<std::size_t>(k)];
      add_contact_springs(c, c.state, 1.0, springs_of(c), range);
    }
  });
}

void Simulation3::swap_springs(const std::vector<std::pair<int, ContactState3>>& changed) {
  for_each_range(block_loads_, [&](Assembly3& range, const std::vector<int>&) {
    for (const auto& [k, before] : changed) {
      const Contact3& c = contacts_[static_cast<std::size_t>(k)];
      if (!range.owns(c.i) && !range.owns(c.j)) continue;
      add_contact_springs(c, before, -1.0, springs_of(c), range);
      add_contact_springs(c, c.state, 1.0, springs_of(c), range);
    }
  });
}

std::vector<Vector12d> Simulation3::solve(double dt, const std::vector<std::pair<int, ContactState3>>* changed) {
  std::vector<Vector12d> d(model_.blocks.size(), Vector12d::Zero());
  Eigen::VectorXd x;
  {
    df::ScopedTimer timer(timings_.assembly);
    // Swapping a spring costs twice adding it: after changes to more than a
    // third of the contacts K is assembled afresh.
    if (!changed || 3 * changed->size() > contacts_.size())
      assemble(dt);
    else
      swap_springs(*changed);
    // F: the blocks' loads, then every contact's in its current state (the
    // anchors and friction change from one iterate to the next).
    x = block_loads_;
    for_each_range(x, [this](Assembly3& range, const std::vector<int>& mine) {
      for (const int k : mine) {
        const Contact3& c = contacts_[static_cast<std::size_t>(k)];
        add_contact_loads(c, springs_of(c), known_, range);
      }
    });
  }
  {
    df::ScopedTimer timer(timings_.solve);
    coupling_->set_states(contacts_);
    x = solve_system(x, dt);  // InternalError if K is not positive definite
    ++timings_.solves;
  }
  for (size_t b = 0; b < d.size(); ++b)
    if (dof_[b] >= 0) d[b] = x.segment<kDofs>(dof_[b]);
  return d;
}

void Simulation3::prepare_input(double dt) {
  body_acceleration_ = model_.gravity;
  Vec3 foundation(0, 0, 0);
  if (const auto& eq = model_.earthquake; eq.motion) {
    // Settling, time stands at 0 (as in 2D): the ground's acceleration at
    // t = 0 (none, for a record that starts at rest), a foundation that
    // does not move.
    const double span = settling_ ? 0.0 : dt;
    body_acceleration_ += eq.mode->body_acceleration(*eq.motion, time_, span);
    foundation = eq.mode->foundation_displacement(*eq.motion, time_ + span) -
                 eq.mode->foundation_displacement(*eq.motion, time_);
  }
  for (size_t b = 0; b < known_.size(); ++b)
    if (dof_[b] < 0) known_[b].segment<3>(kTranslation) = foundation;
  // A contact that slides on starts the step with the strength its law
  // gives now (state advanced, this step's dt).
  for (Contact3& c : contacts_)
    if (c.state == ContactState3::Sliding) c.strength = law_of(c).strength(friction_input3(c, dt), c.friction);
}

void Simulation3::detect() {
  detect_contacts3(model_.blocks, contacts_, model_.contact_reach, model_.contact_merge, spare_contacts_);
  contacts_.swap(spare_contacts_);
  const int sets = static_cast<int>(model_.joint_sets.size());
  const int nc = static_cast<int>(contacts_.size());
#pragma omp parallel for schedule(static) if (nc > 20 * df::parallel_grain())
  for (int k = 0; k < nc; ++k) {  // each contact only itself
    Contact3& c = contacts_[static_cast<std::size_t>(k)];
    if (c.glued) {
      c.joint = model_.glue_joint();
      continue;
    }
    const int set = contact_joint_set(model_.blocks, c);
    c.joint = set >= 0 && set < sets ? set : sets;
  }
  place_glue();
  place_bonds();
}

int Simulation3::glued_contacts() const {
  return static_cast<int>(std::count_if(contacts_.begin(), contacts_.end(), [](const Contact3& c) { return c.glued; }));
}

bool Simulation3::iterate(double dt, std::vector<Vector12d>& d, int& iterations) {
  prepare_input(dt);
  index_ranges();
  coupling_->set_springs(contacts_, dof_, springs_);
  std::vector<int> changes(contacts_.size(), 0);  // state changes of each contact in this step
  const df::TrialScope trial_scope(*solver_);
  // The contacts whose state the last update changed, with the state they
  // were assembled in: the next iterate swaps only their springs.
  std::vector<std::pair<int, ContactState3>> changed;
  std::vector<ContactState3> before(contacts_.size());
  std::vector<std::uint8_t> unsettled(contacts_.size(), 0);  // per contact, by the last global update (the clusters' seeds)
  // The start-up relaxation has no shorter step to fall back on, so it may
  // iterate longer than a step (start_up.hpp).
  const int limit = settling_ ? std::max(df::kSettleOpenClose, model_.max_iterations) : model_.max_iterations;
  df::FrictionRunaway runaway;  // while settling (start_up_relax.hpp)

  // The 3D kernel of the open-close driver (open_close.hpp, where the rules
  // of the iteration are); a local class has the member function's access.
  struct Kernel3 {
    Simulation3& sim;
    double dt;
    std::vector<Vector12d>& d;
    std::vector<int>& changes;
    std::vector<std::pair<int, ContactState3>>& changed;
    std::vector<ContactState3>& before;
    std::vector<std::uint8_t>& unsettled;
    df::FrictionRunaway& runaway;
    double friction_change = 0;  // the largest of a contact sliding before and after (a maximum: in any order)

    bool solve(int iteration, bool trial) {
      sim.solver_->set_trial(trial);
      d = sim.solve(dt, iteration == 1 ? nullptr : &changed);
      changed.clear();
      for (size_t b = 0; b < d.size(); ++b)
        if (sim.dof_[b] < 0) d[b] = sim.known_[b];
      return sim.solver_->last_was_trial();
    }

    // Every contact is updated after every solve (`every` is not needed).
    bool update_contacts(int, bool) {
      std::vector<Contact3>& contacts = sim.contacts_;
      // Each contact updates only itself, in parallel; `before` keeps the
      // state it was assembled in, for the list of changes (contact order).
      bool settled = true;
      double most = 0;
      const int nc = static_cast<int>(contacts.size());
#pragma omp parallel for schedule(static) reduction(&& : settled) reduction(max : most) if (nc > 20 * df::parallel_grain())
      for (int k = 0; k < nc; ++k) {
        Contact3& c = contacts[static_cast<std::size_t>(k)];
        before[static_cast<std::size_t>(k)] = c.state;
        const double friction_used = c.strength;
        bool friction_settled = true;
        const ContactState3 s =
            update_contact3(c, sim.model_, sim.springs_of(c), sim.law_of(c), dt, d[c.i], d[c.j], changes[k] >= 2,
                            friction_settled);
        settled = settled && friction_settled && s == c.state;
        unsettled[static_cast<std::size_t>(k)] = !friction_settled || s != c.state;
        if (s == ContactState3::Sliding && c.state == ContactState3::Sliding)
          most = std::max(most, std::abs(c.strength - friction_used));
        if (s != c.state) ++changes[k];
        c.state = s;
      }
      friction_change = most;
      for (int k = 0; k < nc; ++k)
        if (contacts[static_cast<std::size_t>(k)].state != before[static_cast<std::size_t>(k)])
          changed.emplace_back(k, before[static_cast<std::size_t>(k)]);
      return settled;
    }

    bool gives_up() { return sim.settling_ && runaway.diverging(!changed.empty(), friction_change); }

    bool settle_clusters() { return sim.settle_clusters(dt, d, changes, changed, unsettled); }
  };
  static_assert(df::OpenCloseKernel<Kernel3>);
  Kernel3 kernel{*this, dt, d, changes, changed, before, unsettled, runaway};
  const df::OpenCloseRules rules{limit, true, model_.control.contact_clusters};
  return df::iterate_open_close(kernel, rules, iterations);  // if not settled, d is from states one update behind the stored ones
}

double Simulation3::max_vertex_displacement(const std::vector<Vector12d>& d) const {
  double most = 0;
  for (size_t b = 0; b < d.size(); ++b) {
    if (dof_[b] < 0) continue;
    const Polyhedron& p = model_.blocks[b];
    for (const Vec3& v : p.vertices) {
      const double u = (move_point(p.centroid, d[b], v) - v).norm();
      if (!std::isfinite(u))
        throw df::RunawayError("Step " + std::to_string(log_.size() + 1) + " at t = " + std::to_string(time_) +
                                   " s: the solution for block " + std::to_string(b) +
                                   " is not a finite number; check the penalties, the time step and the materials.",
                               static_cast<int>(log_.size()) + 1, time_, static_cast<int>(b));
      most = std::max(most, u);
    }
  }
  return most;
}

StepRecord3 Simulation3::record(double dt, const std::vector<Vector12d>& d, double moved, int iterations,
                              bool converged, int cuts) {
  StepRecord3 info;
  info.step = static_cast<int>(log_.size()) + 1;
  info.dt = dt;
  info.iterations = iterations;
  info.converged = converged;
  info.dt_cuts = cuts;
  info.max_displacement = moved;
  add_step_work(d, dt);
  finish_step(d, dt);
  close_energy_record();
  info.time = time_;
  for (const Contact3& c : contacts_) {
    if (c.state == ContactState3::Open) ++info.open;
    if (c.state == ContactState3::Sliding) ++info.sliding;
    if (c.state == ContactState3::Locked) ++info.locked;
  }
  log_.push_back(info);
  return info;
}

StepRecord3 Simulation3::step(double dt) {
  start();
  detect();
  std::vector<Vector12d> d;
  int iterations = 0;
  const bool converged = iterate(dt, d, iterations);
  return record(dt, d, max_vertex_displacement(d), iterations, converged, 0);
}

StepRecord3 Simulation3::advance(double max_dt) {
  const Control3& ctl = model_.control;
  start();
  if (dt_ <= 0) dt_ = ctl.dt;
  detect();
  start_contacts_ = contacts_;  // into the storage of the last step's copy
  const std::vector<Contact3>& start = start_contacts_;
  const df::StepControl rule(ctl.dt, ctl.min_dt_ratio * ctl.dt, ctl.max_displacement_ratio * w0_);
  int cuts = 0;
  for (;;) {
    const df::StepControl::Try attempt = df::StepControl::next_try(dt_, max_dt);
    const double dt = attempt.dt;
    contacts_ = start;
    std::vector<Vector12d> d;
    int iterations = 0;
    const bool settled = iterate(dt, d, iterations);
    double moved = 0;
    try {
      moved = max_vertex_displacement(d);  // RunawayError for a solution that is not finite
    } catch (...) {
      contacts_ = start;
      throw;
    }
    if (const std::optional<double> shorter = rule.redo_dt(settled, moved, dt)) {
      dt_ = *shorter;
      ++cuts;
      continue;
    }
    if (rule.too_far(moved) && moved > 2 * w0_) {
      contacts_ = start;  // the state before the step, for the checkpoint written after this
      throw df::RunawayError("Step " + std::to_string(log_.size() + 1) + " at t = " + std::to_string(time_) +
                                 " s: a block moves " + std::to_string(moved) +
                                 " m in one step at the smallest time step, more than the model's size; check the "
                                 "penalties, the time step and the loads.",
                             static_cast<int>(log_.size()) + 1, time_, -1);
    }
    const StepRecord3 info = record(dt, d, moved, iterations, settled, cuts);
    dt_ = rule.after_step(dt_, attempt.shortened, cuts);
    return info;
  }
}

bool Simulation3::finished() const {
  const Control3& c = model_.control;
  if (c.total_time > 0) return time_ >= c.total_time * (1 - 1e-12);
  return static_cast<int>(log_.size()) >= c.steps;
}

void Simulation3::run() {
  while (!finished()) advance(model_.control.total_time > 0 ? model_.control.total_time - time_ : 1e300);
}

void Simulation3::finish_step(const std::vector<Vector12d>& d, double dt) {
  std::vector<Vec3> old_centroid;
  for (const auto& b : model_.blocks) old_centroid.push_back(b.centroid);
  // Each contact and each block updates only itself: in parallel.
  const int nc = static_cast<int>(contacts_.size()), nb = static_cast<int>(model_.blocks.size());
#pragma omp parallel for schedule(static) if (nc > 20 * df::parallel_grain())
  for (int k = 0; k < nc; ++k) {
    Contact3& c = contacts_[static_cast<std::size_t>(k)];
    // Shear anchors ride on block j (before its centroid moves).
    c.ref_j = move_point(old_centroid[c.j], d[c.j], c.ref_j);
    c.point_now = move_point(old_centroid[c.i], d[c.i], c.geo.point_i);
    // A sliding contact's friction turns as its shear spring would: the
    // spring, stretched by strength / ps along the old direction, is pulled
    // further by the step's slip and returned onto the friction limit
    // (docs/solver3d.md, "Friction at its limit"). A slip much longer than
    // that stretch turns the friction fully along the slip; a creep of a
    // few nanometres, the elastic spreading of a block resting at its limit
    // or round-off, barely turns it.
    if (c.state == ContactState3::Sliding) {
      const Eigen::Vector2d stretched = c.slip_dir * (c.strength / springs_of(c).ps) + c.slip;
      if (stretched.squaredNorm() > 0) c.slip_dir = stretched.normalized();
    }
    // The law's memory over the accepted step (as the 2D solver); the
    // joint's own law, also while settling with the contacts stuck. A glued
    // contact has none.
    df::FrictionInput in = friction_input3(c, dt);
    in.slip_sign = slip_sign3(c);
    if (!c.glued) friction_[static_cast<size_t>(c.joint)]->advance(in, c.friction);
    if (c.state == ContactState3::Sliding) c.friction.slip += c.slip_velocity * dt;
    c.bond_released = 0;  // booked by add_step_work
  }
  bonds_placed_ = true;
#pragma omp parallel for schedule(static) if (nb > df::parallel_grain())
  for (int b = 0; b < nb; ++b) {
    if (dof_[b] < 0) {  // a fixed block moves only with a moving foundation, rigidly
      if (d[b].isZero()) continue;
      velocity_[b].setZero();
      velocity_[b].segment<3>(kTranslation) = model_.earthquake.motion->velocity(time_ + dt);
      Polyhedron& p = model_.blocks[b];
      for (auto& v : p.vertices) v += d[b].segment<3>(kTranslation);
      refresh_geometry(p);  // from the vertices, as restore() does: a resumed run stays bit for bit
      continue;
    }
    velocity_[b] = 2.0 / dt * d[b] - velocity_[b];  // constant acceleration in the step
    stress_[b] += elastic_matrix(model_.material_of(b)) * d[b].segment<6>(kStrain);  // the block's own material
    Polyhedron& p = model_.blocks[b];
    for (auto& v : p.vertices) v = move_point(old_centroid[b], d[b], v);  // exact rotation
    refresh_geometry(p);
  }
  auto carry = [&](std::vector<Vec3>& at, auto block_of) {
    for (size_t p = 0; p < at.size(); ++p) {
      const int b = block_of(p);
      at[p] = move_point(old_centroid[static_cast<size_t>(b)], d[static_cast<size_t>(b)], at[p]);
    }
  };
  carry(fixed_at_, [&](size_t p) { return model_.fixed_points[p].block; });
  carry(load_at_, [&](size_t p) { return model_.loads[p].block; });
  carry(measure_at_, [&](size_t p) { return model_.measurements[p].block; });
  time_ += dt;
  sample_measurements();
  advance_bolts(d, old_centroid);
}

}  // namespace dda::df3
