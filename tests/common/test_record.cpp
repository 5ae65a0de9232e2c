// Acceleration records: CSV and PEER NGA AT2 reading, units, bad records
// (InputError naming file and line), scaling, resampling, ramp, integration
// with baseline correction. Expected numbers are hand calculations or closed
// forms given at each check.
#include "dda/common/record.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "dda/common/error.hpp"
#include "scratch_dir_test.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;

dda::RecordReadOptions in_g() {
  dda::RecordReadOptions o;
  o.units = dda::AccelUnits::g;
  return o;
}

// The InputError message of parsing `text` as CSV ("" if none).
std::string csv_error(const std::string& text, dda::RecordReadOptions o = in_g()) {
  try {
    dda::parse_record_csv(text, "rec.csv", o);
  } catch (const dda::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Record, CsvThreeAndFourColumnsWithHeader) {
  const auto r = dda::parse_record_csv("t,ax,ay,az\n0,0.1,0.2,-0.1\n0.01,0.2,0,0\n", "rec.csv", in_g());
  ASSERT_EQ(r.size(), 2u);
  EXPECT_DOUBLE_EQ(r.a[0][0], 0.1 * 9.81);
  EXPECT_DOUBLE_EQ(r.a[2][0], -0.1 * 9.81);
  dda::RecordReadOptions si;
  si.units = dda::AccelUnits::m_per_s2;
  const auto r3 = dda::parse_record_csv("# comment\n0 1 2\n1 3 4\n", "rec.csv", si);
  EXPECT_DOUBLE_EQ(r3.a[1][1], 4.0);
  EXPECT_DOUBLE_EQ(r3.a[2][1], 0.0);
  EXPECT_TRUE(r3.at(0.5).isApprox(Eigen::Vector3d(2.0, 3.0, 0.0)));
  EXPECT_TRUE(r3.at(1.5).isZero());
}

TEST(Record, CsvOneComponentAlongDirection) {
  dda::RecordReadOptions o = in_g();
  o.direction = Eigen::Vector3d(0, 2, 0);  // normalised: north
  const auto r = dda::parse_record_csv("0;0.5\n0.02;-0.5\n", "rec.csv", o);
  EXPECT_DOUBLE_EQ(r.a[1][0], 0.5 * 9.81);
  EXPECT_DOUBLE_EQ(r.a[0][0], 0.0);
}

TEST(Record, BadCsvNamesFileAndLine) {
  EXPECT_NE(csv_error("t,a\n0,1\n0.2,1\n0.1,1\n").find("rec.csv, line 4"), std::string::npos);
  EXPECT_NE(csv_error("t,a\n0,1\n0.2,1\n0.1,1\n").find("times must increase"), std::string::npos);
  EXPECT_NE(csv_error("0,1\n0.1,nan\n").find("rec.csv, line 2, column 2"), std::string::npos);
  EXPECT_NE(csv_error("0,1\n0.1,abc\n").find("is not a number"), std::string::npos);
  EXPECT_NE(csv_error("t,a\n").find("empty"), std::string::npos);
  EXPECT_NE(csv_error("").find("empty"), std::string::npos);
  EXPECT_NE(csv_error("0,1\n").find("at least two"), std::string::npos);
  EXPECT_NE(csv_error("0,1,2\n0.1,1\n").find("line 2"), std::string::npos);
  EXPECT_NE(csv_error("0,1,2,3,4\n").find("5 columns"), std::string::npos);
  EXPECT_NE(csv_error("0,1\n0.1,1\n", dda::RecordReadOptions{}).find("units"), std::string::npos);
  EXPECT_THROW(dda::parse_accel_units("gal", "--units"), dda::InputError);
  EXPECT_EQ(dda::parse_accel_units("m/s^2", "--units"), dda::AccelUnits::m_per_s2);
  EXPECT_THROW(dda::read_record("/nonexistent/rec.csv", in_g()), dda::InputError);
}

TEST(Record, At2) {
  const std::string text =
      "PEER NGA STRONG MOTION DATABASE RECORD\n"
      "TEST EVENT, STATION, 090\n"
      "ACCELERATION TIME SERIES IN UNITS OF G\n"
      "NPTS=    5, DT=   .0100 SEC\n"
      "  .1000000E+00  .2000000E+00 -.1000000E+00\n"
      "  .0000000E+00  .5000000E-01\n";
  dda::RecordReadOptions o;  // units from the header
  const auto r = dda::parse_record_at2(text, "rec.at2", o);
  ASSERT_EQ(r.size(), 5u);
  EXPECT_NEAR(r.t[4], 0.04, 1e-15);
  EXPECT_DOUBLE_EQ(r.a[0][1], 0.2 * 9.81);
  o.units = dda::AccelUnits::m_per_s2;
  EXPECT_THROW(dda::parse_record_at2(text, "rec.at2", o), dda::InputError);
  // Older header form "NPTS DT" and a count mismatch.
  const std::string old = "a\nb\nUNITS OF G\n3 0.02 NPTS, DT\n0.1 0.2 0.3\n";
  EXPECT_NEAR(dda::parse_record_at2(old, "old.at2", {}).t[2], 0.04, 1e-15);
  try {
    dda::parse_record_at2("a\nb\nUNITS OF G\nNPTS= 4, DT= .01\n0.1 0.2 0.3\n", "short.at2", {});
    FAIL();
  } catch (const dda::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("NPTS= 4"), std::string::npos);
  }
}

// Found by fuzzing (docs/reliability.md, "Fuzzing"): a count too large for
// a long was converted to one (undefined behaviour) before it was checked.
TEST(Record, At2HugeCountIsRefused) {
  for (const std::string count : {"8e65", "1e300", "-5", "nan"}) {
    try {
      dda::parse_record_at2("a\nb\nUNITS OF G\n" + count + " 0.01 NPTS, DT\n0.1 0.2\n", "big.at2", {});
      FAIL() << count;
    } catch (const dda::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("big.at2, line 4: no valid NPTS and DT"), std::string::npos) << e.what();
    }
  }
}

TEST(Record, ScaleResampleRamp) {
  dda::RecordReadOptions si;
  si.units = dda::AccelUnits::m_per_s2;
  auto r = dda::parse_record_csv("0,0\n1,2\n3,2\n", "rec.csv", si);
  dda::scale_record(r, 0.5);
  EXPECT_DOUBLE_EQ(r.a[0][1], 1.0);
  const auto u = dda::resample_record(r, 0.5);
  ASSERT_EQ(u.size(), 7u);  // 0, 0.5, ..., 3
  EXPECT_DOUBLE_EQ(u.a[0][1], 0.5);  // linear between (0,0) and (1,1)
  EXPECT_DOUBLE_EQ(u.a[0][6], 1.0);
  EXPECT_NEAR(dda::uniform_step(u, "test"), 0.5, 1e-15);
  EXPECT_THROW(dda::uniform_step(r, "test"), dda::InputError);
  auto ramped = u;
  dda::ramp_record(ramped, 2.0);
  EXPECT_DOUBLE_EQ(ramped.a[0][2], 1.0 * 0.5);  // t = 1: half-way up
  EXPECT_DOUBLE_EQ(ramped.a[0][6], 1.0);
}

// a = A w^2 cos(w t): from rest, v = A w sin(w t), d = A (1 - cos(w t)).
TEST(Record, IntegrationClosedForm) {
  dda::AccelRecord r;
  const double A = 0.01, w = 2 * kPi, dt = 1e-3;
  for (int i = 0; i <= 5000; ++i) {
    const double t = i * dt;
    r.t.push_back(t);
    r.a[0].push_back(A * w * w * std::cos(w * t));
    r.a[1].push_back(0);
    r.a[2].push_back(0);
  }
  const auto m = dda::integrate_record(r, 0);
  for (std::size_t i = 0; i < r.size(); i += 250) {
    EXPECT_NEAR(m.v[0][i], A * w * std::sin(w * r.t[i]), 1e-6);
    EXPECT_NEAR(m.d[0][i], A * (1 - std::cos(w * r.t[i])), 1e-6);
  }
}

// Baseline correction: a drift a0 + a1 t (displacement a0 t^2/2 + a1 t^3/6,
// exactly the tau^2, tau^3 terms of P) is removed exactly: the corrected
// record with drift equals the corrected record without it. The oscillation
// d = A sin(w1 t) sin(w2 t) (from rest, zero mean) loses only its own
// least-squares projection on tau^2, tau^3: 5.6% of A at most here, bound 8%.
// The corrected motion starts from rest.
TEST(Record, BaselineCorrection) {
  dda::AccelRecord r;
  const double A = 0.01, w1 = 2 * kPi * 1.0, w2 = 2 * kPi * 0.13, dt = 1e-3;
  auto d_true = [&](double t) { return A * std::sin(w1 * t) * std::sin(w2 * t); };
  auto a_true = [&](double t) {
    return A * (-(w1 * w1 + w2 * w2) * std::sin(w1 * t) * std::sin(w2 * t) +
                2 * w1 * w2 * std::cos(w1 * t) * std::cos(w2 * t));
  };
  for (int i = 0; i <= 20000; ++i) {
    const double t = i * dt;
    r.t.push_back(t);
    r.a[0].push_back(a_true(t) + 0.05 + 0.002 * t);
    r.a[1].push_back(0.05);  // pure drift: removed exactly
    r.a[2].push_back(0);
  }
  const auto raw = dda::integrate_record(r, 0);
  EXPECT_GT(std::abs(raw.d[0].back()), 10.0);  // 0.05 * 20^2 / 2 = 10 m of drift
  const auto m = dda::integrate_record(r, 3);
  double worst = 0;
  for (std::size_t i = 0; i < r.size(); ++i) worst = std::max(worst, std::abs(m.d[0][i] - d_true(r.t[i])));
  EXPECT_LT(worst, 0.08 * A);
  dda::AccelRecord clean = r;
  for (std::size_t i = 0; i < r.size(); ++i) clean.a[0][i] = a_true(r.t[i]);
  const auto mc = dda::integrate_record(clean, 3);
  for (std::size_t i = 0; i < r.size(); i += 100) EXPECT_NEAR(m.d[0][i], mc.d[0][i], 1e-9);
  double drift = 0;
  for (std::size_t i = 0; i < r.size(); ++i) drift = std::max(drift, std::abs(m.d[1][i]) + std::abs(m.v[1][i]));
  EXPECT_LT(drift, 1e-9);
  EXPECT_DOUBLE_EQ(m.d[0][0], 0.0);
  EXPECT_DOUBLE_EQ(m.v[0][0], 0.0);
}

TEST(Record, FilterNeedsUniformSteps) {
  dda::RecordReadOptions si;
  si.units = dda::AccelUnits::m_per_s2;
  auto r = dda::parse_record_csv("0,0\n1,2\n3,2\n", "rec.csv", si);
  EXPECT_THROW(dda::filter_record(r, {dda::FilterKind::lowpass, 2, 0, 0.1}), dda::InputError);
}

// The four record formats, each read from a small file written here
// (docs/formats.md, "Acceleration records"): a PEER NGA .AT2, SLAMMER's
// two-column time-acceleration file in g (tab separated), a plain column of
// values with the step given, and a CSV. Each holds the same 0.1, -0.2, 0.3 g
// at 0.01 s, so every reader must give the same record.
class RecordFiles : public dda::testing::ScratchDirTest {
 protected:
  RecordFiles() : ScratchDirTest("dda-record-files") {}
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(path(name)) << text;
    return path(name);
  }
  void expect_the_record(const dda::AccelRecord& r) {
    ASSERT_EQ(r.size(), 3u);
    EXPECT_NEAR(r.t[2], 0.02, 1e-15);
    EXPECT_NEAR(r.a[0][0], 0.1 * 9.81, 1e-14);
    EXPECT_NEAR(r.a[0][1], -0.2 * 9.81, 1e-14);
    EXPECT_NEAR(r.a[0][2], 0.3 * 9.81, 1e-14);
    EXPECT_EQ(r.a[1][2], 0.0);
  }
};

TEST_F(RecordFiles, EveryFormatGivesTheSameRecord) {
  dda::RecordReadOptions none;  // the AT2 declares g
  expect_the_record(dda::read_record(
      write("r.AT2", "PEER NGA\nEVENT\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=    3, DT=   .0100 SEC\n"
                     "  .1000000E+00 -.2000000E+00  .3000000E+00\n"),
      none));
  dda::RecordReadOptions o = in_g();
  o.require_uniform_step = true;
  expect_the_record(dda::read_record(write("slammer.txt", "0\t0.1\n0.01\t-0.2\n0.02\t0.3\n"), o));
  expect_the_record(dda::read_record(write("r.csv", "t,a\n0,0.1\n0.01,-0.2\n0.02,0.3\n"), o));
  o.sample_step = 0.01;
  expect_the_record(dda::read_record(write("values.txt", "# one value a line\n0.1\n\n-0.2\n0.3\n"), o));
}

// Bad records: one sentence naming the file and the line.
TEST_F(RecordFiles, BadRecordsNameFileAndLine) {
  dda::RecordReadOptions o = in_g();
  o.require_uniform_step = true;
  const std::string uneven = write("uneven.csv", "t,a\n0,0.1\n0.01,0.2\n0.03,0.3\n");
  EXPECT_EQ(error_of([&] { dda::read_record(uneven, o); }),
            uneven + ", line 4: time step 0.02 s where the first step is 0.01 s (the record must be uniformly sampled).");
  o.require_uniform_step = false;  // the same file is a record for tools that interpolate
  EXPECT_EQ(dda::read_record(uneven, o).size(), 3u);
  const std::string one = write("one.csv", "# header\n0,0.1\n");
  EXPECT_EQ(error_of([&] { dda::read_record(one, o); }),
            one + ", line 2: only one sample; a record needs at least two.");
  o.sample_step = 0.01;
  const std::string nan = write("nan.txt", "0.1\nnan\n");
  EXPECT_EQ(error_of([&] { dda::read_record(nan, o); }), nan + ", line 2: 'nan' is not a finite number.");
  const std::string two = write("two.txt", "0 0.1\n");
  EXPECT_NE(error_of([&] { dda::read_record(two, o); }).find(two + ", line 1: '0 0.1' is not a number"),
            std::string::npos);
  const std::string single = write("single.txt", "\n0.1\n");
  EXPECT_EQ(error_of([&] { dda::read_record(single, o); }),
            single + ", line 2: only one sample; a record needs at least two.");
  o.units = dda::AccelUnits::unspecified;
  EXPECT_NE(error_of([&] { dda::read_record(single, o); }).find("units"), std::string::npos);
}
