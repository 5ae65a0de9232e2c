#pragma once
// Acceleration records (strong-motion or shaking-table input), solver-agnostic.
//
// Conventions:
//  * Axes x east, y north, z up; three components are always stored (absent
//    ones are zero).
//  * Values are stored in m/s^2. The units of a file are never guessed: a CSV
//    file needs them from the caller; a PEER NGA AT2 file declares g in its
//    header ("UNITS OF G"), and a caller's different choice is an error.
//  * What the numbers mean (ground acceleration or body acceleration of the
//    moving block) is the caller's business: a record is only a time series.
//
// Formats:
//  * CSV: columns t, ax, ay[, az] (time in s) or t, a (one component, placed
//    along a caller-given direction). Separators: comma, semicolon, blank or
//    tab. One optional header line (any line whose first field is not a
//    number); lines starting with '#' and empty lines are ignored.
//    SLAMMER's time-acceleration files (two columns, blank or tab
//    separated, acceleration in g) are this format with units g.
//  * PEER NGA AT2: four header lines, the fourth holding "NPTS= n, DT= dt"
//    (or the older "n dt ..." form), then the values, any number per line.
//    The one component is placed along the caller-given direction.
//  * Values only (a plain one-column file, SLAMMER's constant-step form):
//    one acceleration per line, '#' lines and empty lines ignored, sampled at
//    the caller-given step (RecordReadOptions::sample_step) from t = 0.
#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "dda/common/butterworth.hpp"

namespace dda {

enum class AccelUnits { unspecified, g, m_per_s2 };

// "g", "m/s2", "m/s^2" (case-insensitive); anything else is an InputError
// naming `what` (e.g. "--units").
AccelUnits parse_accel_units(const std::string& text, const std::string& what);
// Standard gravity used for unit conversion: 9.81 m/s^2 (the project's g).
constexpr double kRecordGravity = 9.81;

struct AccelRecord {
  std::vector<double> t;                  // s, strictly increasing
  std::array<std::vector<double>, 3> a;   // m/s^2, x east, y north, z up
  std::string source;                     // file it came from, for messages

  std::size_t size() const { return t.size(); }
  double duration() const { return t.empty() ? 0.0 : t.back() - t.front(); }
  // Linear interpolation; zero before the first and after the last sample.
  Eigen::Vector3d at(double time) const;
  double peak_magnitude() const;  // max over samples of |a| (m/s^2)
};

struct RecordReadOptions {
  AccelUnits units = AccelUnits::unspecified;
  // Direction along which a one-component record acts (normalised on use).
  Eigen::Vector3d direction{1.0, 0.0, 0.0};
  // > 0: the file holds values only, this many seconds apart (any extension).
  double sample_step = 0.0;
  // A CSV whose time steps differ (by more than 1e-6 of the first step) is an
  // InputError naming the file and line: the intensity measures and the
  // Newmark analyses of a record series need a uniform step.
  bool require_uniform_step = false;
};

// Reads values only when options.sample_step > 0; otherwise by extension:
// .at2 (any case) is PEER NGA AT2, anything else is CSV.
AccelRecord read_record(const std::string& path, const RecordReadOptions& options);
AccelRecord read_record_csv(const std::string& path, const RecordReadOptions& options);
AccelRecord read_record_at2(const std::string& path, const RecordReadOptions& options);
// Parsers of text already in memory (`name` is used in messages).
AccelRecord parse_record_csv(const std::string& text, const std::string& name, const RecordReadOptions& options);
AccelRecord parse_record_at2(const std::string& text, const std::string& name, const RecordReadOptions& options);
AccelRecord parse_record_values(const std::string& text, const std::string& name, const RecordReadOptions& options);

// Writes t, ax, ay, az (m/s^2) with a header line, atomically.
void write_record_csv(const AccelRecord& record, const std::string& path);

// Multiplies every component by `factor`.
void scale_record(AccelRecord& record, double factor);
// Samples at t0, t0 + dt, ... up to the last time (linear interpolation).
AccelRecord resample_record(const AccelRecord& record, double dt);
// Multiplies by a linear ramp from 0 at the first sample to 1 at first + ramp.
void ramp_record(AccelRecord& record, double ramp_seconds);
// Zero-phase Butterworth filtering of each component (uniform step needed).
void filter_record(AccelRecord& record, const ButterworthSpec& spec);
// Step of a uniformly sampled record; InputError if it is not uniform (to
// 1e-6 relative) or has fewer than two samples. `what` names the operation.
double uniform_step(const AccelRecord& record, const std::string& what);

// What a solver does to a record before using it as ground motion (the
// earthquake of the 2D and the 3D scenario alike), in this order: keep the
// chosen components (the others become zero), scale, resample, filter, ramp
// up, baseline correction (the corrected acceleration, a - P'', replaces the
// record's; see integrate_record).
struct RecordProcessing {
  std::array<bool, 3> use{true, true, true};  // x, y, z
  double scale = 1.0;
  double resample = 0.0;                      // s; 0: keep the record's samples
  std::optional<ButterworthSpec> filter;      // zero-phase Butterworth
  double ramp = 0.0;                          // s, linear ramp-up from the first sample
  int baseline = 0;                           // polynomial degree; < 2: none
};
void process_record(AccelRecord& record, const RecordProcessing& p);

// Velocity and displacement by the trapezoidal rule from rest (v = d = 0 at
// the first sample), with an optional baseline correction:
// a least-squares polynomial P(tau) = sum_{k=2..degree} c_k tau^k,
// tau = t - t0, is fitted to each displacement component and removed:
// d -= P, v -= P', a -= P''. It has no constant or linear term, so the
// corrected motion still starts from rest at the origin. degree < 2: none.
struct IntegratedRecord {
  std::vector<double> t;
  std::array<std::vector<double>, 3> a, v, d;
};
IntegratedRecord integrate_record(const AccelRecord& record, int baseline_degree);

}  // namespace dda
