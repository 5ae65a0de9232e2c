// Slip weakening under a slab of bonded blocks pressed on a plane and
// dragged at one end through a spring (docs/friction.md, "A flexible slab";
// examples/friction_instabilities, whose analyse_slab.py measures the same
// runs at length): tests/df/slab_model.hpp. Slab 1 m x 0.1 m of 20 blocks,
// rho = 2000, surcharge sigma = 1e5 Pa, N = sigma L + rho g H L = 101 962 N;
// interface mu from 0.6 to 0.5 over Dc = 0.1 mm; driver at vd = 1 cm/s;
// the spring starts at 0.3 sigma L. Rigid-slab critical stiffness
// k_c = sigma L (mu_s - mu_d) / Dc = 1e8 N/m; the spring is 0.5 k_c.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "dda/df/2d/simulation.hpp"
#include "slab_model.hpp"
#include "spring_slider_ode.hpp"

namespace dda::df {
namespace {

constexpr double kSigma = 1e5, kLength = 1.0, kHeight = 0.1, kRho = 2000, kDc = 1e-4, kVd = 0.01;
constexpr double kNormal = kSigma * kLength + kRho * 9.81 * kHeight * kLength;  // 101 962 N
constexpr double kKc = kSigma * kLength * 0.1 / kDc;                            // 1e8 N/m
constexpr double kMass = kRho * kHeight * kLength;                               // 200 kg

test::Slab slab(double young, double t_end) {
  test::Slab s;
  s.young = young;
  s.sigma = kSigma;
  s.spring = 0.5 * kKc;
  s.pull = 0.3 * kSigma * kLength;
  s.vd = kVd;
  s.t_end = t_end;
  s.dt = 1e-5;
  s.interface.friction_law = "slip_weakening";
  s.interface.friction_parameters = {{"mu_s", 0.6}, {"mu_d", 0.5}, {"dc", kDc}};
  return s;
}

// What the tests read off a run: the drag force at each step, the peak
// slip speed of the slab's bottom corners (after the start, 5 ms), whether
// a bond between the slab's blocks broke, and, at the first step the drag
// reaches 0.5 N, which interface contacts slip and which stick (by their
// vertex's x).
struct SlabRun {
  std::vector<double> t, force;
  double peak_speed = 0;
  bool bond_broke = false;
  std::vector<double> sliding_x, stuck_x;  // at drag = 0.5 N
};

SlabRun run(const test::Slab& s) {
  Simulation sim(build_model(test::slab_model(s)));
  SlabRun r;
  bool looked = false;
  while (sim.time() < s.t_end - 1e-12) {
    sim.step();
    r.t.push_back(sim.time());
    r.force.push_back(sim.bolts()[0].force);
    for (const Contact& c : sim.contacts()) {
      if (c.joint == 1 && !c.bonded && !c.glued) r.bond_broke = true;
      if (!looked && sim.bolts()[0].force > 0.5 * kNormal && c.joint == 0 && c.eblock == 0) {
        const double x = sim.model().blocks[c.vblock].vertices[c.vertex].x();
        // Slipping: faster than vd / 5 (as analyse_slab.py classes the
        // corners; a contact in the sliding state may creep far slower);
        // open contacts, corners DDA's point contacts leave hanging a
        // fraction of a micrometre above the base, are neither.
        const bool slipping = c.state == ContactState::Sliding && c.slip_velocity > 0.2 * kVd;
        if (slipping) r.sliding_x.push_back(x);
        if (!slipping && c.state != ContactState::Open) r.stuck_x.push_back(x);
      }
    }
    if (sim.bolts()[0].force > 0.5 * kNormal) looked = true;
  }
  for (const auto& h : sim.histories())
    for (const MeasurementSample& m : h)
      if (m.time > 5e-3) r.peak_speed = std::max(r.peak_speed, std::abs(m.velocity.x()));
  return r;
}

// The peak drag force and the drop from it within one period of the slab on
// the spring, 2 pi sqrt(m / k) (the event and its overshoot).
std::pair<double, double> peak_and_drop(const std::vector<double>& t, const std::vector<double>& f) {
  const std::size_t i = std::max_element(f.begin(), f.end()) - f.begin();
  const double period = 2 * kPi * std::sqrt(kMass / (0.5 * kKc));
  double low = f[i];
  for (std::size_t j = i; j < f.size() && t[j] < t[i] + period; ++j) low = std::min(low, f[j]);
  return {f[i], f[i] - low};
}

// The rigid slab: the spring-slider integrated directly (RK4, h = 1 us;
// h = 0.1 us gives the same to 0.1 %) from the run's settled spring force.
std::vector<test::OdeSample> rigid_slab(double f0, double t_end) {
  test::SliderOde o;
  o.m = kMass, o.n = kNormal, o.k = 0.5 * kKc, o.vd = kVd, o.u0 = f0 / o.k;
  o.sticks = true;
  o.mu = [](double, const std::array<double, 2>& s) { return 0.6 - 0.1 * std::min(s[0] / kDc, 1.0); };
  o.rates = [](double v, const std::array<double, 2>&) { return std::array<double, 2>{std::abs(v), 0}; };
  return test::integrate(o, t_end, 1e-6, 1e-5);
}

TEST(FrictionSlab, StiffSlabSlipsAsTheRigidSlider) {
  // E = 100 GPa: the slab's nucleation length (pi / 2) sqrt(E' H Dc /
  // (sigma (mu_s - mu_d))) = 16 m is far beyond its 1 m, so the whole
  // interface weakens together and the slab is the rigid spring-slider. The
  // bounds: the pulled end still weakens a little first (the contacts'
  // shear springs concentrate the pull on the last block or two), which
  // lowers the peak by 2 % and the drop by 5 % (measured when this test
  // was written: peak 0.596 N against 0.609 N, drop 0.196 N against 0.206 N,
  // peak slip speed 10.5 vd against 10.9 vd).
  const double t_end = 0.08;  // the event at 63 ms, its overshoot by 76 ms
  const SlabRun r = run(slab(1e11, t_end));
  const auto [peak, drop] = peak_and_drop(r.t, r.force);
  std::vector<double> rt, rf;
  double rigid_speed = 0;
  // The spring's force at t = 0 after the settling: the first step's force
  // less what the driver added in it.
  const double f0 = r.force.front() - 0.5 * kKc * kVd * r.t.front();
  for (const test::OdeSample& s : rigid_slab(f0, t_end)) {
    rt.push_back(s.t), rf.push_back(s.spring_force);
    rigid_speed = std::max(rigid_speed, s.v);
  }
  const auto [rigid_peak, rigid_drop] = peak_and_drop(rt, rf);
  std::printf("stiff slab: peak drag %.4f N (rigid slider %.4f), drop %.4f N (%.4f), peak slip speed %.2f vd (%.2f)\n",
              peak / kNormal, rigid_peak / kNormal, drop / kNormal, rigid_drop / kNormal, r.peak_speed / kVd,
              rigid_speed / kVd);
  EXPECT_FALSE(r.bond_broke);
  EXPECT_NEAR(peak, rigid_peak, 0.03 * rigid_peak);
  EXPECT_NEAR(drop, rigid_drop, 0.07 * rigid_drop);
  EXPECT_NEAR(r.peak_speed, rigid_speed, 0.06 * rigid_speed);
}

TEST(FrictionSlab, FlexibleSlabSlipsFromThePulledEndAndHoldsLessThanTheRigidOne) {
  // E = 1 GPa: the slab's axial stiffness E' H / L = 1.07e8 N/m is that of
  // k_c, so the pull concentrates at the pulled end. Slip starts there and
  // its front moves toward the free end as the drag rises (at 0.5 N the
  // last 0.45 m slip, the rest sticks: measured when this test was
  // written); the whole interface lets go
  // at a drag well below mu_s N (0.534 N when this test was written, the
  // rigid slab 0.609 N) and the drop is less than half the rigid slab's
  // (0.080 N against 0.206 N): the weakened precursor zone had already
  // given up part of the strength. The slab stays one body.
  const double t_end = 0.09;  // the event at 77 ms
  const SlabRun r = run(slab(1e9, t_end));
  const auto [peak, drop] = peak_and_drop(r.t, r.force);
  std::vector<double> rt, rf;
  for (const test::OdeSample& s : rigid_slab(r.force.front() - 0.5 * kKc * kVd * r.t.front(), t_end))
    rt.push_back(s.t), rf.push_back(s.spring_force);
  const double rigid_drop = peak_and_drop(rt, rf).second;
  ASSERT_FALSE(r.sliding_x.empty());
  ASSERT_FALSE(r.stuck_x.empty());
  const double first_sliding = *std::min_element(r.sliding_x.begin(), r.sliding_x.end());
  const double last_stuck = *std::max_element(r.stuck_x.begin(), r.stuck_x.end());
  std::printf("flexible slab: at drag 0.5 N contacts slide from x = %.3f m to the pulled end, stick up to x = %.3f m; "
              "peak drag %.4f N, drop %.4f N (rigid slab %.4f N)\n",
              first_sliding, last_stuck, peak / kNormal, drop / kNormal, rigid_drop / kNormal);
  EXPECT_FALSE(r.bond_broke);
  // Every sliding contact lies nearer the pulled end (x = 1) than every stuck one, and
  // the front is inside the slab: a slip front from the pulled end.
  EXPECT_GT(first_sliding, last_stuck - 1e-9);
  EXPECT_GT(first_sliding, 0.2);
  EXPECT_LT(first_sliding, 0.9);
  EXPECT_LT(peak, 0.57 * kNormal);  // mu_s N = 0.6 N is what a rigid slab holds
  EXPECT_LT(drop, 0.5 * rigid_drop);
}

}  // namespace
}  // namespace dda::df
