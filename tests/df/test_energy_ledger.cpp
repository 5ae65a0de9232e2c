// The energy ledger's bookkeeping shared by both dimensions
// (df/src/core/energy_ledger.hpp), on a kernel of its own: point masses falling
// in one dimension, plus scripted terms for the other columns. The 2D and
// 3D kernels are checked against physics in test_energy3d.cpp,
// test_waves*.cpp, test_viscous_damping.cpp and the other ledger tests;
// here, that the book puts every term in its column, opens and closes the
// records at the right time, and adds in a fixed order on any number of
// threads. Every expected number is worked by hand next to it.
#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

#include "core/energy_ledger.hpp"
#include "forced_threads.hpp"

namespace dda::df {
namespace {

// Masses on a vertical line under gravity (up positive), stepped with the
// constant acceleration of the implicit step: d = (v0 + v1) / 2 dt.
struct FallingMasses {
  struct Step {
    std::vector<double> d;  // m, one per mass
    double dt = 0;
  };
  std::vector<double> mass, velocity;  // kg, m/s
  double g = -10;                      // m/s^2
  // Scripted terms, J: booked as they stand.
  double load = 0, friction = 0, radiation = 0, released = 0;
  double contact = 0, fixed = 0, bolts = 0;

  std::size_t block_count() const { return mass.size(); }
  BlockEnergy block_energy(std::size_t b) const { return {0.5 * mass[b] * velocity[b] * velocity[b], 0.0}; }
  BlockWork block_work(std::size_t b, const Step& s) const {
    BlockWork w;
    w.gravity = mass[b] * g * s.d[b];
    return w;
  }
  void book_step_terms(const Step&, WorkBook& book) const {
    book.loads(load);
    book.friction(friction);
    book.radiation(radiation);
  }
  void book_released(WorkBook& book) const { book.breakage(released); }
  void book_springs(SpringBook& book) const {
    book.contact(contact);
    book.fixed(fixed);
    book.bolts(bolts);
  }

  // One step of length dt; the state moves after the record is opened, as
  // in both solvers.
  Step fall(double dt) {
    Step s{{}, dt};
    for (double& v : velocity) {
      const double v1 = v + g * dt;
      s.d.push_back(0.5 * (v + v1) * dt);
      v = v1;
    }
    return s;
  }
};
static_assert(EnergyKernel<FallingMasses>);

TEST(EnergyLedger, FreeFallKineticEnergyIsGravitysWork) {
  // 2 kg from rest, two steps of 0.1 s at g = 10: v = 1 then 2 m/s, the
  // drops 0.05 and 0.15 m. Gravity's work m g h = 2 * 10 * 0.05 = 1 J, then
  // 2 * 10 * 0.2 = 4 J in all; kinetic 1/2 m v^2 = 1 J, then 4 J: the
  // residual is 0 (to rounding, 0.1 s not being a binary number).
  FallingMasses k;
  k.mass = {2};
  k.velocity = {0};
  std::vector<EnergyRecord> log;
  start_energy_log(log, k, 0.0);
  ASSERT_EQ(log.size(), 1u);
  EXPECT_EQ(log[0].stored(), 0.0);
  for (int step = 1; step <= 2; ++step) {
    const FallingMasses::Step s = k.fall(0.1);
    open_step_record(log, k, s);
    close_step_record(log, k, 0.1 * step);
  }
  ASSERT_EQ(log.size(), 3u);
  EXPECT_NEAR(log[1].gravity_work, 1.0, 1e-15);
  EXPECT_NEAR(log[1].kinetic, 1.0, 1e-15);
  EXPECT_NEAR(log[2].gravity_work, 4.0, 4e-15);
  EXPECT_NEAR(log[2].kinetic, 4.0, 4e-15);
  EXPECT_NEAR(log[2].residual, 0.0, 4e-15);
  EXPECT_DOUBLE_EQ(log[2].time, 0.2);
}

TEST(EnergyLedger, EveryTermGoesToItsColumn) {
  // Powers of two, so that a term in a wrong column shows in the sums. A
  // mass at rest that does not move: no kinetic energy, no gravity work.
  FallingMasses k;
  k.mass = {1};
  k.velocity = {0};
  k.g = 0;
  k.contact = 1;  // at the start: stored 1 J
  std::vector<EnergyRecord> log;
  start_energy_log(log, k, 0.0);
  EXPECT_EQ(log[0].contact, 1.0);
  k.load = 2, k.friction = 4, k.radiation = 8;
  open_step_record(log, k, k.fall(0.5));
  // The record is open: the breaks and the stored energy come at its close.
  EXPECT_EQ(log[1].breakage, 0.0);
  k.released = 16, k.contact = 32, k.fixed = 64, k.bolts = 128;
  close_step_record(log, k, 0.5);
  const EnergyRecord& e = log[1];
  EXPECT_EQ(e.load_work, 2.0);
  EXPECT_EQ(e.friction, 4.0);
  EXPECT_EQ(e.radiation, 8.0);
  EXPECT_EQ(e.breakage, 16.0);
  EXPECT_EQ(e.contact, 32.0);
  EXPECT_EQ(e.fixed, 64.0);
  EXPECT_EQ(e.bolts, 128.0);
  EXPECT_EQ(e.gravity_work, 0.0);
  EXPECT_EQ(e.damping, 0.0);
  // residual = input 2 - (stored 224 - 1 at the start) - losses (4 + 16 + 8) = -249.
  EXPECT_EQ(e.residual, -249.0);
  // The next step adds to the sums (work and losses are cumulative); the
  // stored energy is that of the end of the step.
  k.released = 0;
  open_step_record(log, k, k.fall(0.5));
  close_step_record(log, k, 1.0);
  EXPECT_EQ(log[2].load_work, 4.0);
  EXPECT_EQ(log[2].friction, 8.0);
  EXPECT_EQ(log[2].breakage, 16.0);
  EXPECT_EQ(log[2].contact, 32.0);
}

TEST(EnergyLedger, BlocksAddUpInBlockOrderOnAnyNumberOfThreads) {
  // Kinetic energies 1e16, 1, -1e16, 1, ... (mass 2 e, velocity 1): added
  // in block order the 1 after each 1e16 is lost to rounding and the one
  // after -1e16 kept, so the order shows in the sum.
  FallingMasses k;
  for (int b = 0; b < 300; ++b) {
    const double e = b % 4 == 0 ? 1e16 : b % 4 == 2 ? -1e16 : 1.0;
    k.mass.push_back(2 * e);
    k.velocity.push_back(1);
  }
  double in_order = 0, reversed = 0;
  for (std::size_t b = 0; b < k.mass.size(); ++b) in_order += 0.5 * k.mass[b];
  for (std::size_t b = k.mass.size(); b-- > 0;) reversed += 0.5 * k.mass[b];
  ASSERT_NE(in_order, reversed);  // the order matters for these terms
  for (const int threads : {1, 2, 3}) {
    const testing::ForcedThreads forced(threads);
    std::vector<EnergyRecord> log;
    start_energy_log(log, k, 0.0);
    EXPECT_EQ(log[0].kinetic, in_order) << threads << " threads";
  }
}

}  // namespace
}  // namespace dda::df
