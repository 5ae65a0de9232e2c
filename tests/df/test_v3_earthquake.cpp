// V3 (docs/validation.md) in 2D DF: a block on a plane dipping 20 degrees, phi = 30,
// under the horizontal ground acceleration a_g = -0.5 g sin(10 t) along x
// (body acceleration +0.5 g sin 10t: the x component of the V3 case; the 2D
// section is the vertical plane through the dip direction, x east, y up).
// The issue asks for the relative sliding at t = 2 pi s within 3 % of the
// rigid-block Newmark result, in loading mode and in displacement mode, and
// for the two modes to agree within a few percent.
//
// Expected numbers: computed here with the Newmark library of tools/analysis
// from the very record file the scenario reads, read as ground acceleration
// (same sign convention): 1.238 m (`dda newmark` gives 1.23812 m for V3,
// docs/validation.md 1.239 m). The DF run reads the record through the scenario path
// (loading.earthquake), so the test covers the scenario reader, the record
// processing, both modes and the solver.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

#include "dda/analysis/newmark.hpp"
#include "dda/common/record.hpp"
#include "dda/df/2d/simulation.hpp"
#include "earthquake_test_models.hpp"

namespace dda::df {
namespace {

namespace fs = std::filesystem;
using test::kV3Dip;
using test::kV3Phi;

fs::path work_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("dda_test_v3_" + name + "_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

// Newmark (rigid block, downslope only) on the same record, 0.1 ms steps.
double newmark_reference(const std::string& record_path, int baseline, double duration = 2 * M_PI) {
  RecordReadOptions o;
  o.units = AccelUnits::m_per_s2;
  auto rec = std::make_shared<AccelRecord>(read_record(record_path, o));
  if (baseline >= 2) rec->a = integrate_record(*rec, baseline).a;  // as the DF processing does
  analysis::NewmarkInput in;
  in.dip_deg = kV3Dip;
  in.dip_direction_deg = 90;  // dipping towards +x (east), as the 2D model
  in.phi_deg = kV3Phi;
  in.dt = 1e-4;
  in.duration = duration;
  const auto r = analysis::run_newmark(in, analysis::excitation_from_record(rec, analysis::InputMeaning::ground));
  return r.s.back();
}

struct DfSlide {
  double relative = 0;  // m, slider minus ground, along the plane (downslope positive)
  double ground = 0;    // m, |ground displacement| at the end
  int steps = 0;
};

DfSlide run_v3(const fs::path& dir, const std::string& earthquake, double total_time = 2 * M_PI) {
  Simulation sim(build_model(test::read_v3(dir, earthquake, total_time).input));
  sim.run();
  int slider = -1, ground = -1;
  for (int k = 0; k < static_cast<int>(sim.model().measurements.size()); ++k) {
    if (sim.model().measurements[k].name == "slider") slider = k;
    if (sim.model().measurements[k].name == "ground") ground = k;
  }
  const Vec2 us = sim.histories()[slider].back().displacement;
  const Vec2 ug = sim.histories()[ground].back().displacement;
  return {(us - ug).dot(test::v3_downslope()), ug.norm(), static_cast<int>(sim.log().size())};
}

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

// Both modes in one test: the comparison between them needs both runs.
TEST(V3Earthquake, LoadingAndDisplacementModesMatchNewmarkWithinThreePercent) {
  const fs::path dir = work_dir("modes");
  test::write_v3_record(dir);
  // No baseline correction in either mode: the record then is exactly the
  // V3 input. (Starting from rest, a sine has a mean ground velocity of
  // 0.05 g; the displacement mode's foundation drifts 3 m over the run,
  // which does not change the relative sliding.)
  const double expected = newmark_reference((dir / "v3_ground.csv").string(), 0);
  const DfSlide load = run_v3(dir, "{record: v3_ground.csv, units: m/s2, mode: loading}");
  const DfSlide disp = run_v3(dir, "{record: v3_ground.csv, units: m/s2, mode: displacement, baseline: 0}");
  std::printf("V3 2D: Newmark %.5f m; DF loading %.5f m (err %.2f %%, %d steps); DF displacement %.5f m "
              "(err %.2f %%, %d steps, ground moved %.3f m); modes differ %.2f %%\n",
              expected, load.relative, 100 * rel(load.relative, expected), load.steps, disp.relative,
              100 * rel(disp.relative, expected), disp.steps, disp.ground, 100 * rel(disp.relative, load.relative));
  EXPECT_NEAR(expected, 1.238, 0.002) << "the Newmark reference itself (dda newmark: 1.23812 m)";
  EXPECT_LE(rel(load.relative, expected), 0.03) << "loading mode: " << load.relative << " m";
  EXPECT_LE(rel(disp.relative, expected), 0.03) << "displacement mode: " << disp.relative << " m";
  EXPECT_LE(rel(disp.relative, load.relative), 0.03) << "the two modes disagree";
  EXPECT_LT(load.ground, 1e-6) << "the foundation is held in loading mode";
  EXPECT_GT(disp.ground, 1.0) << "the foundation follows the ground in displacement mode";
  fs::remove_all(dir);
}

TEST(V3Earthquake, DisplacementModeWithBaselineCorrectionMatchesNewmarkOnTheCorrectedInput) {
  // The default displacement mode corrects the baseline (degree 3), which
  // changes the ground acceleration by -P''(t) (up to 0.05 g here: the
  // sine's mean velocity is what the polynomial removes). The reference is
  // Newmark on that same corrected acceleration (integrate_record), which
  // slides 1.252 m instead of 1.238 m: the correction is part of the input.
  const fs::path dir = work_dir("baseline");
  test::write_v3_record(dir);
  const double expected = newmark_reference((dir / "v3_ground.csv").string(), 3);
  const DfSlide disp = run_v3(dir, "{record: v3_ground.csv, units: m/s2, mode: displacement}");
  const DfSlide load = run_v3(dir, "{record: v3_ground.csv, units: m/s2, mode: loading, baseline: 3}");
  std::printf("V3 2D baseline 3: Newmark %.5f m; DF displacement %.5f m (err %.2f %%), ground moved %.3f m; "
              "DF loading %.5f m\n",
              expected, disp.relative, 100 * rel(disp.relative, expected), disp.ground, load.relative);
  // Regression: the moving fixed points must stand still while the model
  // settles (initial_equilibrium); when they moved to d(10 dt) the
  // foundation started with a velocity ripple that cut the sliding to 1.14 m.
  EXPECT_LE(rel(disp.relative, expected), 0.03);
  EXPECT_LE(rel(load.relative, expected), 0.03) << "the same baseline gives the same motion in loading mode";
  EXPECT_LT(disp.ground, 1.0) << "the corrected ground does not drift away";
  fs::remove_all(dir);
}

TEST(V3Earthquake, DisplacementModeDoesNotDependOnTheStepMatchingTheRecord) {
  // Steps of 0.7 ms against a 1 ms record (so step ends fall between the
  // rows of the ground displacement table) over the first 2 s. With a
  // piecewise-linear table the foundation's velocity jumped at every row and
  // its step-to-step ripple (v1 = 2 d / dt - v0 never damps it) dithered the
  // slider: 0.24 m instead of 1.24 m at 0.5 ms steps. The table is a C1
  // Hermite curve with the ground velocity as slopes (TimeHistory::rate).
  // Expected: Newmark over the same 2 s from the same record.
  const fs::path dir = work_dir("steps");
  test::write_v3_record(dir);
  const double expected = newmark_reference((dir / "v3_ground.csv").string(), 0, 2.0);
  ModelInput in = test::read_v3(dir, "{record: v3_ground.csv, units: m/s2, mode: displacement, baseline: 0}", 2.0)
                      .input;
  in.control.dt = 7e-4;
  Simulation sim(build_model(in));
  sim.run();
  const Vec2 u = sim.histories()[1].back().displacement - sim.histories()[0].back().displacement;
  const double s = u.dot(test::v3_downslope());
  std::printf("V3 2D displacement mode, dt 0.7 ms, t = 2 s: DF %.5f m, Newmark %.5f m (err %.2f %%)\n", s, expected,
              100 * rel(s, expected));
  EXPECT_LE(rel(s, expected), 0.03);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace dda::df
