// Time stepping: contact detection, open-close iteration, step control.
#include "dda/df/2d/simulation.hpp"

#include <Eigen/LU>  // Matrix3d::inverse
#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <tuple>

#include "2d/block_terms.hpp"
#include "core/open_close.hpp"
#include "core/step_control.hpp"
#include "dda/df/2d/contact_detection.hpp"
#include "dda/df/core/bond.hpp"

namespace dda::df {

Simulation::Simulation(Model model, std::unique_ptr<LinearSolver> solver)
    : model_(std::move(model)), solver_(std::move(solver)) {
  if (!solver_) solver_ = make_solver(model_.control.solver);
  for (const JointProperties& j : model_.joints) friction_.push_back(make_friction_law(j));
  for (std::size_t j = 0; j < model_.joints.size(); ++j)
    normal_.push_back(make_normal_law(model_.joints[j], model_.joint_pn[j]));
  for (const Material& m : model_.materials) {
    emat_.push_back(elastic_matrix(m));
    // Once per material: a factorisation of E per block and step (to solve
    // for the strain energy) was 1-2 % of a step on large models.
    compliance_.push_back(emat_.back().inverse());
  }
  for (int i = 0; i < model_.block_count(); ++i) {
    BlockState b;
    b.vertices = model_.blocks[i].vertices;
    b.geometry = block_geometry(b.vertices);
    b.velocity = b.velocity_end = model_.initial_velocity[i];
    b.stress = model_.initial_stress[i];
    blocks_.push_back(std::move(b));
  }
  for (const FixedPoint& f : model_.fixed_points) fixed_anchor_.push_back(f.position);
  fixed_pos_ = fixed_anchor_;
  for (const PointLoad& l : model_.loads) load_pos_.push_back(l.position);
  for (const MeasurementPoint& p : model_.measurements) measurement_pos_.push_back(p.position);
  histories_.resize(model_.measurements.size());
  dt_ = model_.control.dt;
  max_step_displacement_ = model_.control.max_displacement_ratio * *model_.control.w0;
  record_measurements();
  init_physics();
}

const StepRecord& Simulation::step() { return advance(std::numeric_limits<double>::infinity()); }

void Simulation::run() {
  const Control& c = model_.control;
  if (c.total_time > 0) {
    run_until(c.total_time);
  } else {
    for (int s = 0; s < c.steps; ++s) step();
  }
}

void Simulation::run_until(double t) {
  // Steps shorter than a millionth of dt are rounding left-overs, not steps.
  const double eps = 1e-6 * model_.control.dt;
  while (t - time_ > eps) advance(t - time_);
}

ContactLaw Simulation::law_of(const Contact& c) const {
  return {model_.joint_pn[c.joint], model_.joint_ps[c.joint], model_.joints[c.joint].tensile_strength,
          settling_stuck_ ? stuck_friction() : friction_[c.joint].get(), model_.contact_tolerance,
          normal_[c.joint].get()};
}

int Simulation::joint_of(int vblock, int vertex, int eblock, int edge) const {
  // The joint set of the edge; a boundary or artificial edge takes the set of
  // an edge at the vertex instead (the face of the other block it touches).
  const Block& e = model_.blocks[eblock];
  if (e.edge_set[edge] >= 0) return model_.joint_for_set(e.edge_set[edge]);
  const Block& v = model_.blocks[vblock];
  const int n = static_cast<int>(v.edge_set.size());
  for (const int k : {vertex, (vertex + n - 1) % n})
    if (v.edge_set[k] >= 0) return model_.joint_for_set(v.edge_set[k]);
  return model_.joint_for_set(-1);
}

void Simulation::detect_contacts() {
  const int nb = model_.block_count();
  const double d0 = model_.search_distance;
  polygons_.resize(nb);
#pragma omp parallel for schedule(static) if (nb > parallel_grain())
  for (int i = 0; i < nb; ++i) polygons_[i] = blocks_[i].vertices;  // into the last step's lists: no allocation
  // Contacts of the last step by (vertex block, vertex, edge block[, edge]):
  // a vertex that slides onto the next edge of the same block keeps its state.
  // The index made by the last detection still holds (building it read every
  // contact, 0.6 ms a step at 10k blocks): accept() swaps in the iterate's
  // copy of the contacts, the same keys in the same order. restore() and a
  // change of count make it anew.
  if (!contact_index_current_ || contact_index_.size() != contacts_.size()) contact_index_ = ContactIndex(contacts_);
  const ContactIndex& last = contact_index_;
  auto previous = [&last](int vb, int v, int eb) { return last.by_vertex(vb, v, eb) >= 0; };
  const auto candidates =
      find_contacts(polygons_, near_list_.update(polygons_, d0, moved_since_detection_), d0, previous);
  moved_since_detection_ = 0;
  timings_.near_searches = near_list_.searches();

  // Once a model rests on its contacts, they are those of the last step, key
  // for key: then they stay where they are, and the pass below resets the
  // fields that live within one step, exactly what carry_over() makes of a
  // contact found again. Copying every contact into a new list (then 432 bytes
  // each, 58k of them on a 10k-block model) was a third of the contact
  // search, and a pass of its own for the reset cost a read and a write of
  // every contact's first cache lines (300k contacts on a 50k-block model).
  const int n = static_cast<int>(candidates.size());
  const bool in_place = last.same_keys_in_order(candidates);
  if (!in_place) {
    keep_reference_.resize(candidates.size());
    carry_over(candidates, last);
    contact_index_ = ContactIndex(candidates);  // the keys of the new contacts, in their order
  }
  contact_index_current_ = true;

  // The geometry of each contact from where its blocks are now: the first
  // part of forming its springs, timed apart from the search. A locked
  // contact that was locked on this very edge keeps its reference point P0
  // (its spring holds the shear offset since it locked); any other measures
  // shear from where P is now.
  const ScopedTimer timer(timings_.contact_geometry);
  saved_states_.resize(contacts_.size());
#pragma omp parallel for schedule(static) if (nb > parallel_grain())
  for (int k = 0; k < n; ++k) {
    Contact& c = contacts_[static_cast<std::size_t>(k)];
    bool keep_reference = false;
    if (in_place) {
      c.friction_settled = true;
      c.broke = false;
      keep_reference = c.state == ContactState::Locked;
    } else {
      keep_reference = keep_reference_[static_cast<std::size_t>(k)];
    }
    const BlockState& bi = blocks_[c.vblock];
    const BlockState& bj = blocks_[c.eblock];
    c.geo = contact_geometry(bi.vertices, bi.geometry.centroid, bj.vertices, bj.geometry.centroid, c.vertex, c.edge,
                             c.ref_ratio);
    if (!keep_reference) {
      c.ref_ratio = c.geo.ratio0;
      c.geo.ds0 = 0;
      c.geo.reference_at_projection();
    }
    c.length = tributary_length(bi.vertices, c.vertex, c.geo.tangent);
    // What a step's attempt changes, saved while the contact is at hand: a
    // pass of its own read every contact again (3 % of a step on a
    // 50k-block model at rest).
    saved_states_[static_cast<std::size_t>(k)] = iteration_state(c);
  }
}

void Simulation::carry_over(const std::vector<ContactCandidate>& candidates, const ContactIndex& last) {
  const int nb = model_.block_count();
  const double d0 = model_.search_distance;
  // Each contact reads only the blocks and the last step: in parallel. The
  // list is built in work_ (free between steps) and swapped in.
  std::vector<Contact>& next = work_;
  next.resize(candidates.size());
  const long last_count = static_cast<long>(contacts_.size());
#pragma omp parallel if (nb > parallel_grain())
  {
    // Both lists are sorted by key and mostly hold the same contacts, so a
    // contact of the last step is first looked for where the last one found
    // on this thread suggests, and searched for only when it is not there
    // (a contact came or went in between). What is found does not depend on
    // where the threads' ranges start: it is what last.exact() returns (the
    // last contact with the key; detection makes keys unique anyway).
    auto same_key = [&](long at, const Contact& c) {
      const Contact& o = contacts_[static_cast<std::size_t>(at)];
      return o.vblock == c.vblock && o.vertex == c.vertex && o.eblock == c.eblock && o.edge == c.edge;
    };
    long shift = 0;  // position in contacts_ minus position in candidates
#pragma omp for schedule(static)
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      const ContactCandidate& cand = candidates[k];
      Contact c;
      c.vblock = cand.vblock;
      c.vertex = cand.vertex;
      c.eblock = cand.eblock;
      c.edge = cand.edge;
      keep_reference_[k] = false;
      const long guess = static_cast<long>(k) + shift;
      int ex = -1;
      if (guess >= 0 && guess < last_count && same_key(guess, c) && (guess + 1 == last_count || !same_key(guess + 1, c))) {
        ex = static_cast<int>(guess);
      } else {
        ex = last.exact(c.vblock, c.vertex, c.eblock, c.edge);
        if (ex >= 0) shift = ex - static_cast<long>(k);
      }
      // The joint set of a vertex against an edge is that of the last step.
      c.joint = ex >= 0 ? contacts_[ex].joint : joint_of(c.vblock, c.vertex, c.eblock, c.edge);
      const int bv = ex >= 0 ? ex : last.by_vertex(c.vblock, c.vertex, c.eblock);
      if (bv >= 0) {
        const Contact& old = contacts_[bv];
        c.state = old.state;
        c.slip_sign = old.slip_sign;
        c.normal_force = old.normal_force;
        c.shear_force = old.shear_force;
        c.slip_velocity = old.slip_velocity;
        c.bonded = old.bonded;
        c.glued = old.glued;
        c.friction = old.friction;
        c.ref_ratio = old.ref_ratio;
        keep_reference_[k] = ex >= 0 && old.state == ContactState::Locked;
      } else if (step_count_ == 0) {
        // Bonds exist only between faces in touch at the start.
        const JointProperties& j = model_.joints[c.joint];
        const bool touch = in_touch_at_start(cand.dn, d0);
        c.glued = touch && on_artificial_cut(model_.blocks[c.vblock], c.vertex, model_.blocks[c.eblock], c.edge);
        c.bonded = c.glued || (touch && forms_bonds(j));
        // Faces in touch at the start are in contact: they start closed and
        // open in the iteration if they pull apart. Starting them open made a
        // stack of beds close one contact layer per open-close iteration (the
        // blocks above fall together, so only the lowest joint penetrates), so
        // a 40-bed model never settled within the iteration limit.
        if (c.bonded || cand.dn <= model_.contact_tolerance) c.state = ContactState::Locked;
      }
      next[k] = std::move(c);
    }
  }
  contacts_.swap(next);
}

void Simulation::assemble(double dt, const std::vector<Contact>& contacts, std::vector<double>& friction) {
  // Every contact's pair is declared (open ones too: the pattern then holds
  // through the open-close iteration); see block_system.hpp for the rounds
  // that keep the parallel sums in a fixed order.
  std::vector<std::pair<int, int>> coupled(contacts.size());
  for (std::size_t k = 0; k < contacts.size(); ++k) coupled[k] = {contacts[k].vblock, contacts[k].eblock};
  system_.reset(model_.block_count(), coupled);
#pragma omp parallel for schedule(static) if (model_.block_count() > parallel_grain())
  for (int i = 0; i < model_.block_count(); ++i) {
    const int m = model_.block_material[i];
    add_block_terms(i, blocks_[i], model_.materials[m], emat_[m], model_.gravity, dt, damping_beta(), system_);
  }
  for (std::size_t k = 0; k < model_.fixed_points.size(); ++k) {
    const FixedPoint& f = model_.fixed_points[k];
    // The spring pulls the point back to where it was fixed, so anchors do
    // not drift however many steps are taken.
    add_point_spring(f.block, blocks_[f.block], fixed_pos_[k],
                     fixed_point_target(f, fixed_anchor_[k], settling_ ? time_ : time_ + dt) - fixed_pos_[k],
                     *f.penalty, system_);  // settling: time stands at 0 (a moving point must not move yet)
  }
  for (std::size_t k = 0; k < model_.loads.size(); ++k) {
    const PointLoad& l = model_.loads[k];
    add_point_load(l.block, blocks_[l.block], load_pos_[k], load_force(l, time_, time_ + dt), system_);
  }
  assemble_physics(dt);
  friction.resize(contacts.size());
  system_.scatter([&](int k) {
    const Contact& c = contacts[k];
    const ContactLaw law = law_of(c);
    friction[k] = friction_force(c, law, dt);
    add_contact_springs(c, law, 1.0, system_);
    add_contact_forces(c, law, friction[k], 1.0, system_);
  });
}

void Simulation::reassemble(double dt, const std::vector<Contact>& contacts, const StateChanges& changes,
                            std::vector<double>& friction) {
  // F is updated, not formed again: between iterates only the contacts that
  // changed state and the friction of the sliding ones differ (a quarter of
  // the contacts or less; forming F afresh spent as long again on the
  // others). A contact that changed state takes its old forces out and puts
  // its new ones in. The updates go through the same rounds as the
  // assembly, so F does not depend on the thread count; `revisit` flags those
  // contacts, so that the others (most of them) are not even read. A contact
  // that changed state is rebuilt as it was assembled (from its springs
  // kept by the update) where it is needed, here in parallel.
  //
  // K: only the springs of the contacts that changed state differ (from a
  // few thousand of tens of thousands in the first iterates to none once
  // only friction is settling); they are swapped in the same rounds. (Swapped
  // serially after them, in contact order, they were 3 % of a 10k-block
  // transient step, with the other thread waiting.)
  auto update = [&](int k) {
    const Contact& c = contacts[k];
    const ContactLaw law = law_of(c);
    const double f = friction_force(c, law, dt);
    if (changes.is_changed[k]) {
      const Contact old = as_assembled(c, changes.assembled[k]);
      add_contact_springs(old, law, -1.0, system_);
      add_contact_springs(c, law, 1.0, system_);
      add_contact_forces(old, law, friction[k], -1.0, system_);
      add_contact_forces(c, law, f, 1.0, system_);
    } else if (f != friction[k]) {
      add_friction_change(c, f - friction[k], system_);
    }
    friction[k] = f;
  };
  system_.scatter(update, &changes.revisit);
}

bool Simulation::quiet_step() const {
  // A step that settles needs a full solve after the one that left the
  // states alone, so two solves are the fewest after a trial first solve,
  // one after a full one.
  if (log_.empty()) return false;
  const StepRecord& last = log_.back();
  return last.converged && last.dt_cuts == 0 && last.open_close_iterations <= 2;
}

Simulation::ContactUpdate Simulation::update_one(std::size_t k, std::vector<Contact>& contacts,
                                                const Eigen::VectorXd& d, double dt, std::vector<std::uint8_t>& changes) {
  StateChanges& sc = state_changes_;
  Contact& c = contacts[k];
  const ContactState old = c.state;
  const int old_sign = c.slip_sign;
  const AssembledSprings springs = assembled_springs(c);
  c.state = update_contact(c, law_of(c), dt, d.segment<kDofs>(kDofs * c.vblock), d.segment<kDofs>(kDofs * c.eblock),
                           changes[k] >= 2);
  ContactUpdate u;
  u.flipped = c.state != old || (c.state == ContactState::Sliding && c.slip_sign != old_sign);
  if (u.flipped && changes[k] < 255) ++changes[k];
  u.lags = !c.friction_settled;
  u.moved = c.state != old;
  sc.is_changed[k] = u.moved;
  sc.revisit[k] = u.moved || c.state == ContactState::Sliding;
  sc.unsettled[k] = u.moved || !c.friction_settled;
  if (u.moved) sc.assembled[k] = springs;
  return u;
}

bool Simulation::open_close(double dt, std::vector<Contact>& contacts, Eigen::VectorXd& d, int& iterations,
                            bool trial_first) {
  // State changes of each contact in this step: from the second on, the
  // contact is held (update_contact) so cycles between near-zero-force
  // states end.
  std::vector<std::uint8_t> changes(contacts.size(), 0);
  // The contacts whose state changed in the last update, as they were
  // assembled: the next assembly swaps their springs and forces only. A
  // state change alters them through the state, ds0 and gs alone
  // (update_contact), and the friction, which `friction` keeps as assembled.
  // Every flag is written by the first update, before the first reassembly.
  StateChanges& sc = state_changes_;
  sc.changed = 0;
  sc.is_changed.resize(contacts.size());
  sc.assembled.resize(contacts.size());
  sc.revisit.resize(contacts.size());
  sc.unsettled.resize(contacts.size());
  sc.blocks.resize(contacts.size());
  std::vector<double> friction;
  // After a quiet step the first solve is a full one (quiet_step).
  moved_blocks_.start(block_radii());
  const TrialScope trial_scope(*solver_);
  // The start-up relaxation has no shorter step to fall back on, so it may
  // iterate longer than a step (settle.cpp).
  const int limit = settling_ ? std::max(kSettleOpenClose, model_.control.max_open_close) : model_.control.max_open_close;

  // The 2D kernel of the open-close driver (open_close.hpp, where the rules
  // of the iteration are); a local class has the member function's access.
  struct Kernel {
    Simulation& sim;
    double dt;
    std::vector<Contact>& contacts;
    Eigen::VectorXd& d;
    std::vector<std::uint8_t>& changes;
    std::vector<double>& friction;

    bool solve(int iteration, bool trial) {
      StateChanges& sc = sim.state_changes_;
      {
        const ScopedTimer timer(sim.timings_.assembly);
        // Swapping a spring costs twice adding it: when many contacts changed
        // (the first iterate after a blast of new contacts) the whole system
        // is assembled afresh instead.
        if (iteration == 1 || 8 * sc.changed > static_cast<long>(contacts.size())) {
          sim.assemble(dt, contacts, friction);
        } else {
          sim.reassemble(dt, contacts, sc, friction);
        }
      }
      const ScopedTimer timer(sim.timings_.solve);
      sim.solver_->set_trial(trial);
      d = sim.solver_->solve_step(sim.system_, dt);
      ++sim.timings_.solves;
      return sim.solver_->last_was_trial();
    }

    bool update_contacts(int iteration, bool every) {
      StateChanges& sc = sim.state_changes_;
      const ScopedTimer timer(sim.timings_.contact_update);
      // After a trial solve (not the first) only the contacts that can
      // differ are updated: those of a block that moved more than a
      // thousandth of the dead band since its contacts were last updated
      // (Model::contact_update_tolerance, moved_blocks.hpp), those whose
      // state changed in the last update and those whose friction lags.
      // Another contact's state could flip only if it sat on the edge of the
      // band to within that thousandth, far inside the error of a trial
      // solve, and the full solve that ends the iteration updates it anyway;
      // its forces lag by at most pn times that distance meanwhile.
      // (Updating every contact after every solve was a sixth of a 10k-block
      // transient step.)
      sim.moved_blocks_.mark(d, sim.model_.contact_update_tolerance, every);
      bool changed = false, friction_lags = false;
      long updated = 0, changed_count = 0;
      // Each contact updates only itself: in parallel (|| is order-free).
#pragma omp parallel for schedule(static) reduction(|| : changed, friction_lags) reduction(+ : updated, changed_count) if (sim.model_.block_count() > parallel_grain())
      for (std::size_t k = 0; k < contacts.size(); ++k) {
        // Decided from compact arrays: the contact itself is not read.
        if (!every && !sc.unsettled[k] && !sim.moved_blocks_.moved(sc.blocks[k].first) &&
            !sim.moved_blocks_.moved(sc.blocks[k].second)) {
          sc.revisit[k] = 0;  // its forces, hence its friction, are those of the last update
          continue;
        }
        if (every) sc.blocks[k] = {contacts[k].vblock, contacts[k].eblock};
        ++updated;
        const ContactUpdate u = sim.update_one(k, contacts, d, dt, changes);
        changed = changed || u.flipped;
        friction_lags = friction_lags || u.lags;
        changed_count += u.moved;
      }
      sim.timings_.contact_updates += updated;
      sc.changed = changed_count;
      // The friction agreement is a fixed-point iteration that converges
      // linearly (thousands of sliding contacts on a layered model take 20+
      // iterations to agree to 0.1 %), so once the states hold, the last
      // iteration's friction is accepted rather than cutting dt for it; on
      // small models it agrees long before.
      return !changed && !friction_lags;
    }

    bool gives_up() const { return false; }

    bool settle_clusters() {
      const bool settled = sim.settle_clusters(dt, contacts, d, changes, friction);
      sim.solver_->set_warm_start({d, dt});
      return settled;
    }
  };
  static_assert(OpenCloseKernel<Kernel>);
  Kernel kernel{*this, dt, contacts, d, changes, friction};
  const OpenCloseRules rules{limit, trial_first, model_.control.contact_clusters};
  return iterate_open_close(kernel, rules, iterations);
}

void Simulation::restore_iteration_states() {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(contacts_.size());
#pragma omp parallel for schedule(static) if (model_.block_count() > parallel_grain())
  for (std::ptrdiff_t k = 0; k < n; ++k) restore_iteration_state(contacts_[k], saved_states_[k]);
}

double Simulation::max_vertex_displacement(const Eigen::VectorXd& d) const {
  // A maximum does not depend on the order it is taken in: in parallel. (A
  // NaN displacement is skipped in any order: std::max(worst, NaN) is worst.)
  double worst = 0;
#pragma omp parallel for schedule(static) reduction(max : worst) if (model_.block_count() > parallel_grain())
  for (int i = 0; i < model_.block_count(); ++i) {
    const Vector6d di = d.segment<kDofs>(kDofs * i);
    const Vec2& c = blocks_[i].geometry.centroid;
    for (const Vec2& v : blocks_[i].vertices) worst = std::max(worst, (move_point(c, di, v) - v).norm());
  }
  return worst;
}

std::vector<double> Simulation::block_radii() const {
  std::vector<double> r(blocks_.size(), 0.0);
#pragma omp parallel for schedule(static) if (model_.block_count() > parallel_grain())
  for (std::size_t i = 0; i < blocks_.size(); ++i)
    for (const Vec2& v : blocks_[i].vertices) r[i] = std::max(r[i], (v - blocks_[i].geometry.centroid).norm());
  return r;
}

Eigen::VectorXd Simulation::predicted_step(double dt) const {
  Eigen::VectorXd d(kDofs * model_.block_count());
  for (int i = 0; i < model_.block_count(); ++i)
    d.segment<kDofs>(kDofs * i) = dt * blocks_[i].velocity + 0.5 * dt * dt * blocks_[i].acceleration;
  return d;
}

const StepRecord& Simulation::advance(double max_dt) {
  const ScopedTimer step_timer(timings_.total);
  {
    const ScopedTimer timer(timings_.contact_search);
    if (!started_) settle();
    detect_contacts();
  }
  // Each attempt works on contacts_ in place; one thrown away (or one that
  // throws) puts back what the iteration changed (saved by detect_contacts),
  // so the next starts from the contacts of the start of the step.
  const Control& ctl = model_.control;
  const StepControl rule(ctl.dt, ctl.min_dt_ratio * ctl.dt, max_step_displacement_);
  StepRecord rec;
  Eigen::VectorXd d;
  for (;;) {
    const StepControl::Try attempt = StepControl::next_try(dt_, max_dt);
    const double dt = attempt.dt;
    // The first solve starts from the motion the last step predicts. Once a
    // model has come to rest under its loads this saves a third of the PCG
    // iterations of that solve (28 to 18 on the 10k layered model), against
    // starting from the last step's solution; in a transient it does as
    // well as that (docs/solver2d.md).
    solver_->set_warm_start({predicted_step(dt), dt});
    int iterations = 0;
    bool settled = false;
    double moved = 0;
    try {
      settled = open_close(dt, contacts_, d, iterations, !quiet_step());
      moved = max_vertex_displacement(d);
      check_runaway(d, moved, dt, rule.at_min_dt(dt));
    } catch (...) {
      restore_iteration_states();  // a checkpoint written after this holds the step's start
      throw;
    }
    if (const std::optional<double> shorter = rule.redo_dt(settled, moved, dt)) {
      dt_ = *shorter;
      ++rec.dt_cuts;
      restore_iteration_states();
      continue;
    }
    rec.open_close_iterations = iterations;
    rec.converged = settled;
    rec.max_displacement = moved;
    {
      const ScopedTimer timer(timings_.accept);
      accept(dt, d, contacts_, rec);
    }
    dt_ = rule.after_step(dt_, attempt.shortened, rec.dt_cuts);
    break;
  }
  log_.push_back(rec);
  return log_.back();
}

void Simulation::accept(double dt, const Eigen::VectorXd& d, std::vector<Contact>& contacts, StepRecord& rec) {
  // One pass over the contacts (each only its own, in parallel; the counts
  // are order-free): the energy ledger's terms of each, then its friction
  // state advanced. The ledger reads the terms (before_accept, after_accept),
  // and sums them serially in contact order. (A pass each for the friction
  // loss, the friction states and the spring energies read every contact
  // three times a step.)
  int open = 0, sliding = 0, locked = 0;
  contact_energy_.resize(contacts.size());
#pragma omp parallel for schedule(static) reduction(+ : open, sliding, locked) if (model_.block_count() > parallel_grain())
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    Contact& c = contacts[k];
    contact_energy_[k] = contact_energy(c, d.segment<kDofs>(kDofs * c.vblock), d.segment<kDofs>(kDofs * c.eblock));
    const FrictionLaw& law = *friction_[c.joint];
    law.advance({c.normal_force, c.slip_velocity, c.length, dt, c.bonded,
                 c.state == ContactState::Sliding ? c.slip_sign : 0},
                c.friction);
    if (c.state == ContactState::Sliding) c.friction.slip += c.slip_velocity * dt;
    switch (c.state) {
      case ContactState::Open: ++open; break;
      case ContactState::Sliding: ++sliding; break;
      case ContactState::Locked: ++locked; break;
    }
  }
  rec.open += open;
  rec.sliding += sliding;
  rec.locked += locked;
  before_accept(dt, d);
  // Points ride with their blocks; move them before the centroids change.
  auto move = [&](int block, Vec2& p) {
    p = move_point(blocks_[block].geometry.centroid, d.segment<kDofs>(kDofs * block), p);
  };
  for (std::size_t k = 0; k < fixed_pos_.size(); ++k) move(model_.fixed_points[k].block, fixed_pos_[k]);
  for (std::size_t k = 0; k < load_pos_.size(); ++k) move(model_.loads[k].block, load_pos_[k]);
  for (std::size_t k = 0; k < measurement_pos_.size(); ++k) move(model_.measurements[k].block, measurement_pos_[k]);

  // Each block moves only itself: in parallel. The energies are summed
  // afterwards, serially in block order, so the sums do not depend on the
  // thread count.
  const int nb = model_.block_count();
  std::vector<double> twice_kinetic(nb), twice_strain_density(nb);  // v1' M v1, sigma' E^-1 sigma
#pragma omp parallel for schedule(static) if (nb > parallel_grain())
  for (int i = 0; i < nb; ++i) {
    BlockState& b = blocks_[i];
    const Vector6d di = d.segment<kDofs>(kDofs * i);
    const int mat = model_.block_material[i];
    const Vector6d v1 = 2.0 / dt * di - b.velocity;  // end velocity, constant acceleration
    b.acceleration = (v1 - b.velocity) / dt;
    twice_kinetic[i] = v1.dot(mass_matrix(b.geometry, model_.materials[mat].density) * v1);
    for (Vec2& v : b.vertices) v = move_point(b.geometry.centroid, di, v);
    b.geometry = block_geometry(b.vertices);
    b.stress = rotate_stress(b.stress, di[2]) + emat_[mat] * di.tail<3>();
    twice_strain_density[i] = b.stress.dot(compliance_[mat] * b.stress);
    b.velocity = model_.control.dynamic * v1;
    b.velocity_end = v1;
  }
  // The farthest a vertex moved (max_vertex_displacement(d), which the
  // caller measured to accept the step), for the near list's bound.
  moved_since_detection_ += rec.max_displacement;
  double kinetic = 0, elastic = 0;
  for (int i = 0; i < nb; ++i) {
    kinetic += 0.5 * twice_kinetic[i];
    elastic += 0.5 * blocks_[i].geometry.area * twice_strain_density[i];
  }

  // A swap, not a move: the caller's vector keeps the old list's memory
  // (settle's working copy; a step works on contacts_ itself).
  if (&contacts != &contacts_) contacts_.swap(contacts);
  time_ += dt;
  ++step_count_;
  rec.step = step_count_;
  rec.time = time_;
  rec.dt = dt;
  rec.kinetic_energy = kinetic;
  rec.elastic_energy = elastic;
  record_measurements();
  after_accept(dt);
}

void Simulation::record_measurements() {
  for (std::size_t k = 0; k < measurement_pos_.size(); ++k) {
    const int b = model_.measurements[k].block;
    const BlockState& s = blocks_[b];
    MeasurementSample m;
    m.time = time_;
    m.position = measurement_pos_[k];
    m.displacement = measurement_pos_[k] - model_.measurements[k].position;
    m.velocity = t_matrix(s.geometry.centroid, m.position) * s.velocity_end;
    m.acceleration = t_matrix(s.geometry.centroid, m.position) * s.acceleration;
    m.stress = s.stress;
    histories_[k].push_back(m);
  }
}

}  // namespace dda::df
