#pragma once
#include <vector>

// Energy bookkeeping of a run (J per unit thickness in 2D, J in 3D), one
// record per step; the 3D terms are those of simulation3d_energy.cpp.
//
// Stored energy: kinetic (of the velocities the next step starts from),
// elastic (block strain energy S/2 sigma^T E^-1 sigma), contact (penalty
// springs of closed contacts, N^2 / 2 pn, plus their shear springs, S^2 / 2
// ps, which a sliding contact keeps stretched by its friction), fixed (fixed-point springs) and bolts (T^2 / 2k).
// Input work: gravity (m g . centroid displacement) and loads (point loads,
// as assembled, plus the work of moving fixed points on their springs and of
// a body acceleration, m b . centroid displacement, e.g. an earthquake).
// Losses that are accounted for: friction (sliding force times slip at every
// sliding contact), damping (the kinetic energy a dynamic parameter k < 1
// removes, (1 - k^2) of it, plus the work of the blocks' viscous damping,
// beta/dt S de^T E de a step, control.damping), breakage (energy released by broken bolts, and in 3D by broken joint bonds) and
// radiation (what the viscous boundaries let out of the model; the work of
// an incident wave's traction on them counts with the loads).
// residual = input work - (stored - stored at the start) - friction -
// damping - breakage - radiation: what the time integrator and the penalty springs
// dissipate (the implicit step loses pn/2 (change of dn)^2 per step and
// spring, and a contact that opens loses its spring energy). It is 0 to
// rounding for blocks without contacts.
namespace dda::df {

struct EnergyRecord {
  double time = 0;                 // s, end of the step
  // Stored, at the end of the step.
  double kinetic = 0, elastic = 0, contact = 0, fixed = 0, bolts = 0;
  // Cumulative since t = 0.
  double gravity_work = 0, load_work = 0;
  double friction = 0, damping = 0, breakage = 0, radiation = 0;
  double residual = 0;

  double stored() const { return kinetic + elastic + contact + fixed + bolts; }
  double input() const { return gravity_work + load_work; }
  double losses() const { return friction + damping + breakage + radiation; }
};

// The record of a run at which it had created the most energy for the
// energy it had moved. The penalty springs and the implicit step only
// dissipate, so the residual stays >= 0 but for rounding and the lag of
// friction behind the normal force: the tests' and examples' runs stay
// above -1.3 % of the energy moved. A residual far below zero means energy
// came from an error (a contact that started centimetres deep in a block
// made 119 kJ in the first step of a 192k-block model, with 243 J of work
// done). `scale` is the largest energy_moved() up to that record.
struct EnergyCreated {
  double time = 0;      // s
  double residual = 0;  // J (per unit thickness); < 0: created
  double scale = 0;     // J
  double ratio() const { return scale > 0 ? residual / scale : 0.0; }
};
// The energy moved between the start and record e: the larger of the work
// done and of the stored change plus the losses.
double energy_moved(const EnergyRecord& start, const EnergyRecord& e);
// Record 0 is the start (as in Simulation::energy_log()); a log of it alone
// gives a zero ratio.
EnergyCreated most_energy_created(const std::vector<EnergyRecord>& log);
// Energy created beyond this share of the energy moved is reported (dda df
// warns, dda info shows it).
inline constexpr double kEnergyCreatedWarning = 0.1;

}  // namespace dda::df
