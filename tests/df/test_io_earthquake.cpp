// loading.earthquake: the scenario keys, the two modes as they land in the
// model input, the body acceleration in the solver, and the messages for
// bad keys and bad records (each one sentence naming the scenario file, line
// and key, and the record file where the record is at fault).
#include <gtest/gtest.h>

#include <fstream>

#include "dda/common/error.hpp"
#include "dda/df/2d/simulation.hpp"
#include "earthquake_test_models.hpp"

namespace dda::df {
namespace {

namespace fs = std::filesystem;

class EarthquakeInput : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    dir_ = fs::temp_directory_path() / ("dda_test_eq_" + name + "_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    test::write_v3_record(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  void write(const std::string& name, const std::string& text) const { std::ofstream(dir_ / name) << text; }
  DfScenario read(const std::string& earthquake) const { return test::read_v3(dir_, earthquake); }
  // The message of the InputError reading the scenario throws ("" if none).
  std::string error_of(const std::string& earthquake) const {
    try {
      read(earthquake);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  std::string yaml() const { return (dir_ / "v3.yaml").string(); }

  fs::path dir_;
};

const FixedPoint& fixed(const ModelInput& in, const std::string& name) {
  for (const FixedPoint& f : in.fixed_points)
    if (f.name == name) return f;
  throw std::runtime_error("no fixed point " + name);
}

TEST_F(EarthquakeInput, LoadingModeIsABodyAccelerationOnTheBlocksOutsideTheFoundation) {
  const ModelInput in = read("{record: v3_ground.csv, units: m/s2}").input;  // mode defaults to loading
  ASSERT_TRUE(in.body_acceleration);
  EXPECT_EQ(in.body_acceleration->blocks, std::vector<int>{1});  // the slab holds every fixed point
  // b = -a_g = +0.5 g sin(10 t), linear between the 1 ms samples.
  for (const double t : {0.1234, 1.0, 3.3})
    EXPECT_NEAR(in.body_acceleration->history.at(t).x(), 0.5 * 9.81 * std::sin(10 * t), 2e-4) << t;
  EXPECT_EQ(in.body_acceleration->history.at(100.0), Vec2(0, 0)) << "no shaking after the record";
  for (const FixedPoint& f : in.fixed_points) EXPECT_FALSE(f.history) << f.name;
}

TEST_F(EarthquakeInput, DisplacementModeMovesEveryFixedPointWithTheIntegratedRecord) {
  const ModelInput in = read("{record: v3_ground.csv, units: m/s2, mode: displacement, baseline: 0}").input;
  EXPECT_FALSE(in.body_acceleration);
  // a_g = -0.5 g sin(10 t) from rest: d = 0.05 g (sin(10 t) / 10 - t).
  for (const char* name : {"base1", "base2", "base3"}) {
    const FixedPoint& f = fixed(in, name);
    ASSERT_TRUE(f.history) << name;
    for (const double t : {0.05, 1.0, 2.5, 6.0})
      // The record is the sine sampled every 1 ms and taken as linear
      // between samples; its exact double integral is off the sine's by at
      // most 2.57e-5 m over the record (1.03e-5 m at 2.5 s, 2.46e-5 m at 6 s;
      // computed independently in numpy).
      EXPECT_NEAR(f.history->at(t).x(), 0.05 * 9.81 * (std::sin(10 * t) / 10 - t), 3e-5) << name << " t " << t;
    EXPECT_EQ(f.history->at(1.0).y(), 0.0);
  }
  // After the record the ground keeps its last velocity (zero acceleration).
  const TimeHistory& h = *fixed(in, "base1").history;
  const double t1 = 6.294;  // the record's last sample (write_v3_record)
  const double v_end = 0.05 * 9.81 * (std::cos(10 * t1) - 1);
  EXPECT_NEAR((h.at(t1 + 2) - h.at(t1 + 1)).x(), v_end, 1e-4);
}

TEST_F(EarthquakeInput, FoundationNamesFixedPointsAndSides) {
  ModelInput in = read("{record: v3_ground.csv, units: m/s2, mode: displacement, foundation: [base2]}").input;
  EXPECT_TRUE(fixed(in, "base2").history);
  EXPECT_FALSE(fixed(in, "base1").history);
  EXPECT_FALSE(fixed(in, "base3").history);
  const std::string e = error_of("{record: v3_ground.csv, units: m/s2, foundation: [bottom]}");
  EXPECT_NE(e.find("loading.earthquake.foundation[0] names side bottom, which fixed.boundary does not hold"),
            std::string::npos)
      << e;
}

TEST_F(EarthquakeInput, ComponentsScaleRampAndFilter) {
  write("two.csv", "t,ax,ay\n0,1,2\n1,1,2\n2,1,2\n");
  ModelInput in = read("{record: two.csv, units: g, components: [y], scale: 0.5}").input;
  EXPECT_NEAR(in.body_acceleration->history.at(1.0).x(), 0.0, 1e-12);
  EXPECT_NEAR(in.body_acceleration->history.at(1.0).y(), -0.5 * 2 * 9.81, 1e-9);
  in = read("{record: two.csv, units: m/s2, ramp: 2}").input;
  EXPECT_NEAR(in.body_acceleration->history.at(1.0).x(), -0.5, 1e-12);
  // A one-component record acts along `direction`.
  write("one.csv", "t,a\n0,3\n1,3\n");
  in = read("{record: one.csv, units: m/s2, direction: [0, 1]}").input;
  EXPECT_NEAR(in.body_acceleration->history.at(0.5).y(), -3.0, 1e-12);
  // A low-pass at 1 Hz removes most of the 1.6 Hz sine (gain 1/(1+1.6^8) ~ 0.02).
  in = read("{record: v3_ground.csv, units: m/s2, filter: {type: lowpass, corner: 1, order: 4}}").input;
  EXPECT_LT(std::abs(in.body_acceleration->history.at(3.0 + M_PI / 20).x()), 0.05 * 0.5 * 9.81);
}

TEST_F(EarthquakeInput, BodyAccelerationMovesAFreeBlockExactly) {
  // One block, no contact, no fixed point, no gravity: under a constant
  // ground acceleration a_g = (1, 0) m/s^2 for 0 <= t <= 2 s, it moves by
  // -a_g t^2 / 2 (the step means of a constant are exact), and the work of
  // the body force is its kinetic energy.
  write("const.csv", "t,ax,ay\n0,1,0\n2,1,0\n");
  const std::string s =
      "materials: {default: {density: 2000, young: 5e10}}\nloading: {gravity: 0, earthquake: {record: const.csv, "
      "units: m/s2}}\ncontrol: {dt: 0.01, total_time: 1}\n";
  BlockModel blocks;
  blocks.blocks.push_back(test::make_block(test::rectangle(0, 0, 1, 1)));
  blocks.points.push_back({{"c", PointKind::Measurement, Vec2(0.5, 0.5)}, 0});
  const DfScenario sc = read_df_scenario(YamlNode::load_string(s, (dir_ / "free.yaml").string()), blocks, "b.h5");
  Simulation sim(build_model(sc.input));
  sim.run();
  EXPECT_NEAR(sim.histories()[0].back().displacement.x(), -0.5, 1e-9);
  EXPECT_NEAR(sim.histories()[0].back().displacement.y(), 0.0, 1e-12);
  const EnergyRecord& e = sim.energy_log().back();
  EXPECT_NEAR(e.load_work, 0.5 * 2000 * 1.0, 1e-6);  // m v^2 / 2, v = 1 m/s
  EXPECT_NEAR(e.residual, 0.0, 1e-6);
}

TEST_F(EarthquakeInput, BadKeysAreOneSentenceNamingFileLineAndKey) {
  const std::string f = yaml() + ":";
  struct Case {
    std::string entry, expected;
  };
  const std::vector<Case> cases = {
      {"{record: v3_ground.csv}", "loading.earthquake.units is required for a CSV record"},
      {"{record: v3_ground.csv, units: furlongs}", "loading.earthquake.units must be g or m/s2, got 'furlongs'"},
      {"{record: v3_ground.csv, units: g, mode: sideways}", "loading.earthquake.mode"},
      {"{record: v3_ground.csv, units: g, colour: red}", "colour"},
      {"{record: v3_ground.csv, units: g, ramp: -1}", "loading.earthquake.ramp"},
      {"{record: v3_ground.csv, units: g, baseline: 9}", "loading.earthquake.baseline"},
      {"{record: v3_ground.csv, units: g, components: [z]}", "loading.earthquake.components[0] must be x or y"},
      {"{record: v3_ground.csv, units: g, direction: [0, 0]}", "loading.earthquake.direction must be a non-zero"},
      {"{record: v3_ground.csv, units: g, filter: {type: lowpass, corner: 900}}",
       "loading.earthquake.filter cannot be used"},
      {"{record: v3_ground.csv, units: g, filter: {type: bandpass, corners: [5, 1]}}",
       "loading.earthquake.filter.corners must be [low, high] with 0 < low < high"},
      {"{record: v3_ground.csv, units: g, foundation: [nope]}",
       "loading.earthquake.foundation[0] names 'nope', which is neither a fixed point nor a side of fixed.boundary "
       "(fixed points: base1, base2, base3)"},
  };
  for (const Case& c : cases) {
    const std::string e = error_of(c.entry);
    EXPECT_EQ(e.rfind(f, 0), 0u) << c.entry << " -> " << e;
    EXPECT_NE(e.find(c.expected), std::string::npos) << c.entry << " -> " << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
}

TEST_F(EarthquakeInput, BadRecordsNameTheScenarioKeyAndTheRecordFile) {
  write("backwards.csv", "t,ax,ay\n0,0,0\n0.2,1,0\n0.1,1,0\n");
  write("nan.csv", "t,ax,ay\n0,0,0\n0.1,nan,0\n");
  write("empty.csv", "t,ax,ay\n");
  write("az.csv", "t,ax,ay,az\n0,0,0,1\n0.1,0,0,1\n");
  write("rec.at2", "PEER NGA\nTEST\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=    4, DT=   .0100 SEC\n"
                   "0.1 0.2 0.3 0.4\n");
  struct Case {
    std::string entry, expected;
  };
  const std::vector<Case> cases = {
      {"{record: backwards.csv, units: g}", "backwards.csv, line 4: time 0.1 s is not greater than the previous"},
      {"{record: nan.csv, units: g}", "nan.csv, line 3"},
      {"{record: empty.csv, units: g}", "empty.csv: no samples"},
      {"{record: missing.csv, units: g}", "missing.csv: file not found"},
      {"{record: az.csv, units: g}", "az.csv: has a fourth column (az)"},
      {"{record: rec.at2, units: m/s2}", "rec.at2: the AT2 header declares units of g, but m/s2 was asked for"},
  };
  for (const Case& c : cases) {
    const std::string e = error_of(c.entry);
    EXPECT_EQ(e.rfind(yaml() + ":", 0), 0u) << e;
    EXPECT_NE(e.find("loading.earthquake.record cannot be used: "), std::string::npos) << e;
    EXPECT_NE(e.find(c.expected), std::string::npos) << c.entry << " -> " << e;
  }
  // An AT2 file needs no units (it declares g).
  const ModelInput in = read("{record: rec.at2}").input;
  EXPECT_NEAR(in.body_acceleration->history.at(0.01).x(), -0.2 * 9.81, 1e-9);
}

TEST_F(EarthquakeInput, DisplacementModeRefusesAPointThatAlreadyMoves) {
  const std::string s = test::v3_scenario("{record: v3_ground.csv, units: m/s2, mode: displacement}") +
                        "fixed:\n  points:\n    - {point: base1, displacement: [[0, 0, 0], [1, 0.1, 0]]}\n";
  try {
    read_df_scenario(YamlNode::load_string(s, yaml()), test::v3_blocks(), "b.h5");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("loading.earthquake.mode cannot be applied: Fixed point 'base1' already "
                                         "follows its own displacement table"),
              std::string::npos)
        << e.what();
  }
}

TEST(TimeHistoryRates, HermiteTableReproducesACubicAndItsIntegral) {
  // x(t) = t^3 with its rates 3 t^2 at t = 0, 1, 2: a cubic Hermite table is
  // exact for a cubic; outside it continues along the end rate.
  TimeHistory h;
  for (const double t : {0.0, 1.0, 2.0}) {
    h.t.push_back(t);
    h.value.emplace_back(t * t * t, 0);
    h.rate.emplace_back(3 * t * t, 0);
  }
  EXPECT_NEAR(h.at(0.5).x(), 0.125, 1e-14);
  EXPECT_NEAR(h.at(1.7).x(), 1.7 * 1.7 * 1.7, 1e-13);
  EXPECT_NEAR(h.average(0.5, 1.5).x(), (std::pow(1.5, 4) - std::pow(0.5, 4)) / 4, 1e-13);
  EXPECT_NEAR(h.at(3.0).x(), 8 + 12 * 1.0, 1e-13);
  EXPECT_NEAR(h.average(2.0, 3.0).x(), 8 + 12 * 0.5, 1e-13);  // mean of 8 + 12 (t - 2) over [2, 3]
  EXPECT_NEAR(h.at(-1.0).x(), 0.0, 1e-14);                     // rate 0 at the start: held
}

}  // namespace
}  // namespace dda::df
