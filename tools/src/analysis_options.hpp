#pragma once
// Command-line options shared by the analytical subcommands (newmark,
// sliding3d, backfit, record): the dynamic input and the friction laws.
#include <CLI/CLI.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dda/analysis/excitation.hpp"
#include "dda/analysis/friction.hpp"
#include "dda/common/record.hpp"

namespace dda::cli {

// Record processing: file, units, direction of a one-component record, scale,
// resampling, ramp-up, zero-phase Butterworth filter.
struct RecordOptions {
  std::string path;
  std::string units;
  std::string axis = "x";
  double scale = 1.0;
  double resample = 0.0;
  double ramp = 0.0;
  double lowpass = 0.0, highpass = 0.0;
  int order = 4;
  double sample_step = 0.0;  // --record-dt: the file holds values only
};
void add_record_options(CLI::App* cmd, RecordOptions& o, bool positional);
// Reads and processes the record (order: scale, resample, filter, ramp).
// With uniform, a CSV must be uniformly sampled unless --resample makes it so.
AccelRecord load_record(const RecordOptions& o, bool uniform = false);
// load_record for another file with the same options.
AccelRecord load_record(const RecordOptions& o, const std::string& path, bool uniform);

// Dynamic input: a record or a sinusoid, as ground or body acceleration.
struct InputOptions {
  RecordOptions record;
  double sine_g = 0.0;
  double freq = 0.0, omega = 0.0;
  std::string meaning = "ground";
};
void add_input_options(CLI::App* cmd, InputOptions& o);
// The excitation, or gravity alone when neither --record nor --sine is given.
analysis::Excitation build_excitation(const InputOptions& o);

// "x", "y", "z" (or -x ...) or a horizontal azimuth in degrees.
analysis::Vec3 parse_axis(const std::string& text, const std::string& flag);

// Friction per plane: constant angles, a time table, or mu = a + b ln(v/v_ref).
struct FrictionOptions {
  std::vector<double> phi;
  std::string table;
  std::vector<double> mu_lnv;
  double v_ref = 1.0, v_min = 1e-6;
};
void add_friction_options(CLI::App* cmd, FrictionOptions& o);
std::vector<analysis::FrictionLaw> build_friction(const FrictionOptions& o, std::size_t planes);

// Formats a double for CSV with round-trip precision.
void put_number(std::string& out, double v);

}  // namespace dda::cli
