#pragma once
// The energy ledger's bookkeeping, once for the 2D and the 3D solver (the
// record, its terms and its checks: dda/df/core/energy.hpp; docs/solver3d.md,
// "Energy ledger"). Internal to df/src.
//
// A run's log holds record 0, the stored energy of the state the run starts
// from, then one record per accepted step. A step's record is opened from
// the last one with the work and losses of the step, taken from the
// configuration at its start with every force as assembled (F . T d), and
// closed once the blocks have moved: the energy the step's breaks released,
// the stored energy at its end and the residual.
//
// What differs between the dimensions is behind EnergyKernel: the 2D kernel
// is Simulation::EnergyTerms (simulation_physics.cpp), the 3D one
// Simulation3::EnergyTerms (simulation3d_energy.cpp). A kernel says what one
// block holds and does, and lists its other terms, each booked into its
// column here (WorkBook, SpringBook).
//
// The order of the sums is part of the result: every term is added to its
// column in turn, in a fixed order (blocks in block order, then the
// kernel's list, each list in model or contact order); the per-block terms
// are evaluated in parallel and added serially. So the ledger is the same
// bit for bit on any number of threads, and a kernel that keeps its list
// in order keeps its results (the 2D and 3D lists differ in order where
// their files did, e.g. 2D books the body acceleration after the water,
// 3D with the blocks: results.h5's energy columns stayed bit for bit).
//
// A new load, loss or stored part is one line in each kernel's list; its
// column is named by the book's function it calls.
#include <concepts>
#include <cstddef>
#include <vector>

#include "dda/df/core/block_system.hpp"
#include "dda/df/core/energy.hpp"

namespace dda::df {

// What one block holds at the end of a step (J, or J per unit thickness in 2D).
struct BlockEnergy {
  double kinetic = 0;  // 1/2 v^T M v
  double strain = 0;   // S/2 sigma^T E^-1 sigma (V in 3D)
};

// What the forces on one block itself do in a step: gravity, a body force
// counted with the loads (an earthquake's acceleration), and the damping's
// loss (a dynamic parameter k < 1 and the viscous damping of its strain).
struct BlockWork {
  double gravity = 0, loads = 0, damping = 0;
};

// The step's record: each call adds one term to one column.
class WorkBook {
 public:
  explicit WorkBook(EnergyRecord& e) : e_(e) {}
  void gravity(double work) { e_.gravity_work += work; }
  void loads(double work) { e_.load_work += work; }  // point loads, water, moving supports, incident waves
  void friction(double loss) { e_.friction += loss; }
  void damping(double loss) { e_.damping += loss; }
  void breakage(double released) { e_.breakage += released; }
  void radiation(double absorbed) { e_.radiation += absorbed; }

 private:
  EnergyRecord& e_;
};

// The stored energy outside the blocks: each call adds one term to one column.
class SpringBook {
 public:
  explicit SpringBook(EnergyRecord& e) : e_(e) {}
  void contact(double energy) { e_.contact += energy; }
  void fixed(double energy) { e_.fixed += energy; }
  void bolts(double energy) { e_.bolts += energy; }

 private:
  EnergyRecord& e_;
};

// What a dimension supplies (one instance per booking; it may hold the
// step's displacements):
//   Step                   what a step's work is taken from (increments, dt)
//   block_count()          the blocks, 0 .. block_count() - 1
//   block_energy(b)        what block b holds now
//   block_work(b, step)    what the forces on block b itself do in the step
//   book_step_terms(step, book)
//                          every other work and loss of the step, from the
//                          configuration at its start, in the kernel's order
//   book_released(book)    energy let go by parts that broke while the step
//                          was accepted (bolts), booked when it closes
//   book_springs(book)     the stored energy outside the blocks: contact
//                          springs, fixed points, bolts
// block_energy and block_work are called in parallel: they must only read.
template <class K>
concept EnergyKernel = requires(const K& k, std::size_t b, const typename K::Step& step, WorkBook& work,
                                SpringBook& springs) {
  { k.block_count() } -> std::convertible_to<std::size_t>;
  { k.block_energy(b) } -> std::same_as<BlockEnergy>;
  { k.block_work(b, step) } -> std::same_as<BlockWork>;
  k.book_step_terms(step, work);
  k.book_released(work);
  k.book_springs(springs);
};

namespace ledger_detail {

// term(b) for every block, in parallel (each block only read).
template <class Term>
auto per_block(std::size_t n, Term term) {
  std::vector<decltype(term(std::size_t{0}))> terms(n);
  const auto nb = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(static) if (nb > parallel_grain())
  for (std::ptrdiff_t b = 0; b < nb; ++b) terms[static_cast<std::size_t>(b)] = term(static_cast<std::size_t>(b));
  return terms;
}

// The stored fields of e, from the state now.
template <EnergyKernel K>
void store(const K& k, EnergyRecord& e) {
  e.kinetic = e.elastic = e.contact = e.fixed = e.bolts = 0;
  for (const BlockEnergy& held : per_block(k.block_count(), [&k](std::size_t b) { return k.block_energy(b); })) {
    e.kinetic += held.kinetic;
    e.elastic += held.strain;
  }
  SpringBook springs(e);
  k.book_springs(springs);
}

}  // namespace ledger_detail

// Record 0 of a new log: the stored energy at `time`, no work done yet.
// Called when a run starts, and again after the start-up relaxation.
template <EnergyKernel K>
void start_energy_log(std::vector<EnergyRecord>& log, const K& k, double time) {
  EnergyRecord e;
  e.time = time;
  ledger_detail::store(k, e);
  log.assign(1, e);
}

// Opens the step's record: the last record's sums plus the step's work and
// losses. Call before the step moves anything.
template <EnergyKernel K>
void open_step_record(std::vector<EnergyRecord>& log, const K& k, const typename K::Step& step) {
  EnergyRecord e = log.back();
  WorkBook book(e);
  const auto own = [&k, &step](std::size_t b) { return k.block_work(b, step); };
  for (const BlockWork& w : ledger_detail::per_block(k.block_count(), own)) {
    book.gravity(w.gravity);
    book.loads(w.loads);
    book.damping(w.damping);
  }
  k.book_step_terms(step, book);
  log.push_back(e);
}

// Closes the step's record once the step is accepted and the state has
// moved: the breaks' energy, the stored energy at `time` and the residual,
// input - (stored - stored at the start) - losses.
template <EnergyKernel K>
void close_step_record(std::vector<EnergyRecord>& log, const K& k, double time) {
  EnergyRecord& e = log.back();
  WorkBook book(e);
  k.book_released(book);
  e.time = time;
  ledger_detail::store(k, e);
  e.residual =
      e.input() - (e.stored() - log.front().stored()) - e.friction - e.damping - e.breakage - e.radiation;
}

}  // namespace dda::df
