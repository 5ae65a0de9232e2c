// boundaries.viscous, boundaries.free_field and the earthquake's incident
// mode in a 3D scenario (scenario3d_waves.cpp, keys in docs/scenario.md):
// which faces get dashpots, the incident wave the record becomes, one sentence naming the
// file, line and key for each mistake, and a run read from a scenario
// against the 1D answer.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <unistd.h>

#include "dda/common/error.hpp"
#include "dda/df/io/scenario3d.hpp"
#include "dda/df/3d/simulation3d.hpp"
#include "df_io_test_models3d.hpp"
#include "../common/input_error_of.hpp"

namespace dda::df3 {
namespace {

// A column of `plates` plates of 5 x 5 x 2.5 m, plate k over z in
// [2.5 k, 2.5 (k + 1)]; every face is a domain-boundary face (as DC writes
// the outside of a model; the faces between plates lie inside the bounding
// box, so no side selects them). A measurement point at the second plate's
// centroid.
PolyhedronModel column_blocks(int plates) {
  PolyhedronModel m;
  for (int k = 0; k < plates; ++k) m.blocks.push_back(testing::box(Vec3(0, 0, 2.5 * k), Vec3(5, 5, 2.5 * (k + 1))));
  for (Polyhedron& p : m.blocks) refresh_geometry(p), p.body = -1;
  m.points = {{"second", PointKind::Measurement, Vec3(2.5, 2.5, 3.75)}};
  return m;
}

// nu = 0: a plate free at its sides carries a vertical wave at sqrt(E /
// rho) = 707.1 m/s, the P speed of the dashpots (Vp with nu = 0).
const char* kScenario = R"(dimension: 3
materials:
  default: {density: 2000, young: 1.0e9, poisson: 0}
loading:
  gravity: 0
  earthquake: {record: eq.csv, units: m/s2, direction: [0, 0, 1], baseline: 0, mode: incident}
boundaries:
  viscous: [bottom, top]
control: {dt: 0.0005, total_time: 0.15, normal_penalty: 2.5e12}
)";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// This process's own folder under the temporary one: ctest runs each test
// of this file as a process of its own, in parallel, and a record rewritten
// in a shared folder was read empty by a test running beside it.
// (tests/common/scratch_dir_test.hpp does this for a fixture; these tests
// share free functions.) Removed when the process ends.
std::string own_dir() {
  struct Folder {
    std::filesystem::path path =
        std::filesystem::path(::testing::TempDir()) / ("scenario3d_waves_" + std::to_string(::getpid()));
    Folder() { std::filesystem::create_directories(path); }
    ~Folder() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Folder folder;
  return folder.path.string() + "/";
}

// The record eq.csv in the test's own folder: a_z = the derivative of
// the outcrop velocity v_g(t) = 2 a sin^2(pi t / tau), 0 <= t <= tau (a =
// 1e-3 m/s, tau = 0.1 s), sampled every 0.25 ms (linear between samples:
// its exact integral, v_g, then matches the smooth pulse within 2.1e-5 of
// its peak: the trapezoidal rule's h^2 omega^2 / 12), then at rest. Returns the scenario's path next to it.
std::string write_record() {
  const std::string dir = own_dir();
  std::FILE* f = std::fopen((dir + "eq.csv").c_str(), "w");
  EXPECT_NE(f, nullptr);
  std::fputs("t,a\n", f);
  const double a = 1e-3, tau = 0.1;
  for (int k = 0; k <= 400; ++k) {
    const double t = tau * k / 400;
    std::fprintf(f, "%.17g,%.17g\n", t, 2 * a * M_PI / tau * std::sin(2 * M_PI * t / tau));
  }
  std::fprintf(f, "%.17g,0\n", 0.2);
  std::fclose(f);
  return dir + "s.yaml";
}

DfScenario3 read(const std::string& text, const PolyhedronModel& blocks = column_blocks(4)) {
  return read_df3_scenario(YamlNode::load_string(text, write_record()), blocks, "b3.h5");
}

// The message without the temporary folder the scenario is read from.
std::string error_of(const std::string& text, const PolyhedronModel& blocks = column_blocks(4)) {
  std::string message = dda::testing::input_error_of([&] { read(text, blocks); });
  const std::string dir = own_dir();
  if (message.rfind(dir, 0) == 0) message.erase(0, dir.size());
  return message;
}

// Side bottom is face 0 of plate 0 (box face 0, z = 0), top face 1 of the
// last plate; only the bottom is an input face. The incident wave is half
// the record's velocity: at t = tau / 2 the integral of the record is 2 a =
// 2e-3 m/s (the peak of v_g), so v_in = 1e-3; after the record's last row
// (0.2 s) plus one step the wave is at rest.
TEST(Scenario3dWaves, BottomAndTopFacesAndTheIncidentWave) {
  const DfScenario3 s = read(kScenario);
  ASSERT_TRUE(s.model.viscous);
  const ViscousBoundary3& v = *s.model.viscous;
  ASSERT_EQ(v.faces.size(), 2u);
  EXPECT_EQ(v.faces[0].block, 0);
  EXPECT_EQ(v.faces[0].face, 0);
  EXPECT_TRUE(v.faces[0].input);
  EXPECT_EQ(v.faces[1].block, 3);
  EXPECT_EQ(v.faces[1].face, 1);
  EXPECT_FALSE(v.faces[1].input);
  EXPECT_EQ(s.model.earthquake.mode->name, "incident");
  EXPECT_NEAR(v.incident_velocity.at(0.05).z(), 1e-3, 1e-3 * 1e-4);
  EXPECT_EQ(v.incident_velocity.at(0.05).x(), 0);
  EXPECT_EQ(v.incident_velocity.at(0.2 + 0.0005), Vec3::Zero());
  // The incident mode adds no body force.
  EXPECT_EQ(s.model.earthquake.mode->body_acceleration(*s.model.earthquake.motion, 0.0, 0.01), Vec3::Zero());
}

// A coarse record, a_z rising from 0 to 1 m/s^2 over its one interval of
// 10 ms: the outcrop velocity is t^2 / 0.02 (m/s), a parabola, which the
// incident wave's table (linear between rows) follows only if it is sampled
// at most a step (0.5 ms) apart: v_in(5 ms) = 0.5 x 0.005^2 / 0.02 =
// 6.25e-4 m/s (from the record's two rows alone, 1.25e-3).
TEST(Scenario3dWaves, IncidentWaveFollowsTheRecordBetweenItsRows) {
  const std::string path = write_record();
  std::FILE* f = std::fopen((own_dir() + "ramp.csv").c_str(), "w");
  ASSERT_NE(f, nullptr);
  std::fputs("t,a\n0,0\n0.01,1\n", f);
  std::fclose(f);
  const DfScenario3 s = read_df3_scenario(YamlNode::load_string(replaced(kScenario, "eq.csv", "ramp.csv"), path),
                                          column_blocks(4), "b3.h5");
  EXPECT_NEAR(s.model.viscous->incident_velocity.at(0.005).z(), 6.25e-4, 1e-15);
}

// Side faces: every plate has its west face (box face 4, x = 0) on the
// west side; no face is an input face without an incident wave.
TEST(Scenario3dWaves, SidesSelectEveryFaceOnThem) {
  const std::string text = replaced(replaced(kScenario, "[bottom, top]", "[west]"), ", mode: incident", "");
  const DfScenario3 s = read(text);
  ASSERT_TRUE(s.model.viscous);
  ASSERT_EQ(s.model.viscous->faces.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(s.model.viscous->faces[static_cast<std::size_t>(k)].block, k);
    EXPECT_EQ(s.model.viscous->faces[static_cast<std::size_t>(k)].face, 4);
    EXPECT_FALSE(s.model.viscous->faces[static_cast<std::size_t>(k)].input);
  }
  EXPECT_TRUE(s.model.viscous->incident_velocity.t.empty());
}

// Free-field sides (viscous_boundary3d.hpp): every face on them is a
// free-field face, the base is the input; the free field's base is the
// bottom of the blocks (z = 0) and its free surface the top of the
// free-field faces (the 4 plates of 2.5 m: z = 10).
TEST(Scenario3dWaves, FreeFieldSidesSelectEveryFaceOnThem) {
  const DfScenario3 s =
      read(replaced(kScenario, "[bottom, top]", "[bottom]\n  free_field: [west, east, south, north]"));
  ASSERT_TRUE(s.model.viscous);
  const ViscousBoundary3& v = *s.model.viscous;
  ASSERT_EQ(v.faces.size(), 1u + 4 * 4);  // the base, and 4 sides of 4 plates
  EXPECT_TRUE(v.faces[0].input);
  EXPECT_FALSE(v.faces[0].free_field);
  for (std::size_t k = 1; k < v.faces.size(); ++k) {
    EXPECT_TRUE(v.faces[k].free_field);
    EXPECT_FALSE(v.faces[k].input);
  }
  EXPECT_EQ(v.base_z, 0);
  EXPECT_EQ(v.surface_z, 10);
}

TEST(Scenario3dWaves, FreeFieldMistakesNameTheFileLineAndKey) {
  const std::string without_incident = replaced(kScenario, ", mode: incident", "");
  EXPECT_EQ(error_of(replaced(without_incident, "[bottom, top]", "[bottom]\n  free_field: [west]")),
            "s.yaml:9: boundaries.free_field needs an incident wave (loading.earthquake with mode: incident): the "
            "free field is the motion that wave gives the rock.");
  EXPECT_EQ(error_of(replaced(kScenario, "[bottom, top]", "[bottom, west]\n  free_field: [east, west]")),
            "s.yaml:9: boundaries.free_field[1] is also in boundaries.viscous; a side has plain dashpots or "
            "free-field ones, not both.");
  EXPECT_EQ(error_of(replaced(kScenario, "[bottom, top]", "[bottom]\n  free_field: [west, up]")),
            "s.yaml:9: boundaries.free_field[1] must be west, east, south or north (free-field boundaries stand on "
            "the lateral sides), got 'up'.");
  EXPECT_EQ(error_of(replaced(kScenario, "[bottom, top]", "[bottom]\n  free_field: [top]")),
            "s.yaml:9: boundaries.free_field[0] must be west, east, south or north (free-field boundaries stand on "
            "the lateral sides), got 'top'.");
  EXPECT_EQ(error_of(replaced(kScenario, "[bottom, top]", "[bottom]\n  free_field: [west, west]")),
            "s.yaml:9: boundaries.free_field[1] repeats side west.");
}

TEST(Scenario3dWaves, MistakesNameTheFileLineAndKey) {
  EXPECT_EQ(error_of(replaced(kScenario, "[bottom, top]", "[bottom, up]")),
            "s.yaml:8: boundaries.viscous[1] must be bottom, top, west, east, south or north, got 'up'.");
  EXPECT_EQ(error_of(replaced(kScenario, "[bottom, top]", "[bottom, top, bottom]")),
            "s.yaml:8: boundaries.viscous[2] repeats side bottom.");
  EXPECT_EQ(error_of(replaced(kScenario, "[bottom, top]", "[top]")),
            "s.yaml:6: loading.earthquake.mode incident sends the wave in through the viscous base, and "
            "boundaries.viscous does not list bottom (add it there).");
  EXPECT_EQ(error_of(replaced(kScenario, "boundaries:\n  viscous: [bottom, top]\n", "")),
            "s.yaml:6: loading.earthquake.mode incident sends the wave in through the viscous base, and "
            "boundaries.viscous does not list bottom (add it there).");
  EXPECT_EQ(error_of(replaced(kScenario, "  viscous: [bottom, top]", "  viscous: [bottom]\n  dashpots: 2")),
            "s.yaml:9: unknown key 'boundaries.dashpots'; allowed keys here are viscous, free_field.");
  // The incline's base is turned 20 degrees: none of its faces lies on the
  // bottom of the bounding box.
  EXPECT_EQ(error_of(replaced(kScenario, "[bottom, top]", "[bottom]"), testing::incline_blocks()),
            "s.yaml:8: boundaries.viscous lists bottom, but no block of b3.h5 has a domain-boundary face on that "
            "side.");
}

// The scenario run: the pulse v_in = a sin^2(pi t / tau) (a = 1e-3 m/s,
// tau = 0.1 s: 28 plates long, as the 2D bar's) enters through the base of
// the 10 m column and leaves through its viscous top, so nothing comes
// back: an up-going wave whose particle velocity is up compresses, so the
// contacts, which carry no tension, need no precompression. Each plate
// moves as the incident wave, v = v_in(t - z / c) (no free surface to
// double it): the second plate's centroid (z = 3.75 m) peaks at 1e-3 m/s
// at t = tau / 2 + 3.75 / 707.1 = 55.3 ms (within 5 % and 2 %, the 2D
// tests' tolerances). The ledger: the incident traction's work 2 Z A v_in
// . v (v = v_in at the matched base) and the radiation Z A v^2, of the
// entry at the base and of the exit at the top, come each to 2 E, E = Z A
// a^2 3 tau / 8 = 3.31 J (Z = rho c = 1.414e6 kg/m^2/s, A = 25 m^2), within
// 5 %; nothing is left in the column (below 1 % of 2 E). Obtained: 0.998e-3
// m/s at 55.5 ms, work 1.002 x 2 E, radiation 0.999 x 2 E.
TEST(Scenario3dWaves, IncidentPulseCrossesTheColumnAsThe1DWave) {
  const DfScenario3 s = read(kScenario);
  Simulation3 sim(s.model);
  sim.run();
  const MeasurementSample3* peak = nullptr;
  for (const MeasurementSample3& x : sim.histories()[0])
    if (!peak || x.velocity.z() > peak->velocity.z()) peak = &x;
  ASSERT_TRUE(peak);
  const double c = std::sqrt(1e9 / 2000.0), arrival = 0.05 + 3.75 / c;
  EXPECT_NEAR(peak->velocity.z(), 1e-3, 0.05 * 1e-3);
  EXPECT_NEAR(peak->time, arrival, 0.02 * arrival);
  const double carried = 2000 * c * 25 * 1e-6 * 3 * 0.1 / 8;
  const df::EnergyRecord& first = sim.energy_log().front();
  const df::EnergyRecord& last = sim.energy_log().back();
  EXPECT_NEAR(last.load_work, 2 * carried, 0.05 * 2 * carried);
  EXPECT_NEAR(last.radiation, 2 * carried, 0.05 * 2 * carried);
  EXPECT_LT(std::abs(last.stored() - first.stored()), 0.01 * 2 * carried);
  RecordProperty("peak_velocity", std::to_string(peak->velocity.z()));
  RecordProperty("peak_time", std::to_string(peak->time));
  RecordProperty("work_over_2E", std::to_string(last.load_work / (2 * carried)));
  RecordProperty("radiation_over_2E", std::to_string(last.radiation / (2 * carried)));
}

}  // namespace
}  // namespace dda::df3
