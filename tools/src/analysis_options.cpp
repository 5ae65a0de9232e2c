#include "analysis_options.hpp"

#include <charconv>
#include <cmath>

#include "dda/analysis/table.hpp"
#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"

namespace dda::cli {

using analysis::Vec3;

void add_record_options(CLI::App* cmd, RecordOptions& o, bool positional) {
  const char* formats =
      "Acceleration record: CSV (t, ax, ay[, az] or t, a; SLAMMER's two-column files too), PEER NGA .AT2, or "
      "values only with --record-dt";
  if (positional)
    cmd->add_option("record", o.path, formats)->required();
  else
    cmd->add_option("--record", o.path, formats);
  cmd->add_option("--units", o.units,
                  "Units of the record values: g or m/s2 (required for CSV and values; AT2 declares g)");
  cmd->add_option("--record-dt", o.sample_step,
                  "The record file holds values only (one a line, e.g. SLAMMER's constant-step files), this many "
                  "seconds apart");
  cmd->add_option("--axis", o.axis,
                  "Direction of a one-component record: x (east), y (north), z (up), -x ..., or a horizontal "
                  "azimuth in degrees (default x)");
  cmd->add_option("--scale", o.scale, "Multiply the record by this factor (default 1)");
  cmd->add_option("--resample", o.resample, "Resample to this step (s) by linear interpolation");
  cmd->add_option("--ramp", o.ramp, "Linear ramp-up of the record over this time (s) from its start");
  cmd->add_option("--lowpass", o.lowpass, "Zero-phase Butterworth low-pass cutoff (Hz)");
  cmd->add_option("--highpass", o.highpass, "Zero-phase Butterworth high-pass cutoff (Hz); with --lowpass: band-pass");
  cmd->add_option("--order", o.order, "Butterworth order (default 4)");
}

AccelRecord load_record(const RecordOptions& o, bool uniform) { return load_record(o, o.path, uniform); }

AccelRecord load_record(const RecordOptions& o, const std::string& path, bool uniform) {
  RecordReadOptions ro;
  if (!o.units.empty()) ro.units = parse_accel_units(o.units, "--units");
  ro.direction = parse_axis(o.axis, "--axis");
  if (o.sample_step < 0.0 || !std::isfinite(o.sample_step))
    throw InputError("--record-dt: the step between values must be positive.");
  ro.sample_step = o.sample_step;
  ro.require_uniform_step = uniform && o.resample == 0.0;
  AccelRecord rec = read_record(path, ro);
  if (o.scale != 1.0) scale_record(rec, o.scale);
  if (o.resample < 0.0) throw InputError("--resample: the step must be positive.");
  if (o.resample > 0.0) rec = resample_record(rec, o.resample);
  if (o.lowpass < 0.0 || o.highpass < 0.0) throw InputError("--lowpass/--highpass: cutoffs must be positive.");
  if (o.lowpass > 0.0 || o.highpass > 0.0) {
    ButterworthSpec spec;
    spec.order = o.order;
    spec.f_high = o.lowpass;
    spec.f_low = o.highpass;
    spec.kind = o.lowpass > 0.0 && o.highpass > 0.0 ? FilterKind::bandpass
                : o.lowpass > 0.0                  ? FilterKind::lowpass
                                                   : FilterKind::highpass;
    filter_record(rec, spec);
  }
  if (o.ramp != 0.0) ramp_record(rec, o.ramp);
  return rec;
}

void add_input_options(CLI::App* cmd, InputOptions& o) {
  add_record_options(cmd, o.record, false);
  cmd->add_option("--sine", o.sine_g, "Built-in input: sinusoid of this amplitude (g) along --axis");
  cmd->add_option("--freq", o.freq, "Frequency of --sine (Hz)");
  cmd->add_option("--omega", o.omega, "Angular frequency of --sine (rad/s), instead of --freq");
  cmd->add_option("--input", o.meaning,
                  "ground (default): the input is the ground acceleration a_g and the block feels -a_g; "
                  "body: the input is the block's body (inertial) acceleration itself");
}

Vec3 parse_axis(const std::string& text, const std::string& flag) {
  std::string s = text;
  double sign = 1.0;
  if (!s.empty() && (s[0] == '-' || s[0] == '+') && s.size() == 2 && std::isalpha(static_cast<unsigned char>(s[1]))) {
    sign = s[0] == '-' ? -1.0 : 1.0;
    s = s.substr(1);
  }
  if (s == "x" || s == "X") return sign * Vec3::UnitX();
  if (s == "y" || s == "Y") return sign * Vec3::UnitY();
  if (s == "z" || s == "Z") return sign * Vec3::UnitZ();
  double az = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), az);
  if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size() || !std::isfinite(az))
    throw InputError(flag + ": '" + text + "' is not x, y, z or an azimuth in degrees.");
  return analysis::horizontal(az);
}

analysis::Excitation build_excitation(const InputOptions& o) {
  const auto meaning = analysis::parse_input_meaning(o.meaning, "--input");
  const bool has_record = !o.record.path.empty();
  const bool has_sine = o.sine_g != 0.0;
  if (has_record && has_sine) throw InputError("--record and --sine: give one input, not both.");
  if (has_record) {
    auto rec = std::make_shared<const AccelRecord>(load_record(o.record));
    return analysis::excitation_from_record(rec, meaning);
  }
  if (has_sine) {
    if ((o.freq > 0.0) == (o.omega > 0.0))
      throw InputError("--sine: give its frequency with either --freq (Hz) or --omega (rad/s), positive.");
    const double omega = o.omega > 0.0 ? o.omega : 2.0 * kPi * o.freq;
    if (o.record.ramp < 0.0) throw InputError("--ramp: the ramp-up time must be zero or positive.");
    return analysis::sinusoid(parse_axis(o.record.axis, "--axis"), o.sine_g * kRecordGravity, omega, o.record.ramp,
                              meaning);
  }
  return analysis::no_input();
}

void add_friction_options(CLI::App* cmd, FrictionOptions& o) {
  cmd->add_option("--phi", o.phi, "Friction angle (deg): one value for every plane, or one per plane (a,b)")
      ->delimiter(',');
  cmd->add_option("--friction-table", o.table,
                  "CSV t, phi1[, phi2]: friction angle (deg) in time, piecewise linear; a repeated time is a step");
  cmd->add_option("--mu-lnv", o.mu_lnv, "Velocity-dependent friction mu = a + b ln(v / v_ref) on every plane: a,b")
      ->delimiter(',');
  cmd->add_option("--v-ref", o.v_ref, "Reference speed of --mu-lnv (m/s, default 1; 0.001 for v in mm/s)");
  cmd->add_option("--v-min", o.v_min, "Floor of the speed in --mu-lnv (m/s, default 1e-6)");
}

std::vector<analysis::FrictionLaw> build_friction(const FrictionOptions& o, std::size_t planes) {
  using analysis::FrictionLaw;
  const int given = (o.phi.empty() ? 0 : 1) + (o.table.empty() ? 0 : 1) + (o.mu_lnv.empty() ? 0 : 1);
  if (given != 1) throw InputError("Friction: give exactly one of --phi, --friction-table or --mu-lnv.");
  std::vector<FrictionLaw> out;
  if (!o.phi.empty()) {
    if (o.phi.size() != 1 && o.phi.size() != planes)
      throw InputError("--phi: give one angle for every plane or one per plane (" + std::to_string(planes) + ").");
    for (std::size_t k = 0; k < planes; ++k) {
      const double phi = o.phi[o.phi.size() == 1 ? 0 : k];
      if (!(phi >= 0.0 && phi < 90.0)) throw InputError("--phi: friction angles must lie in 0..90 degrees.");
      out.push_back(FrictionLaw::constant_angle(phi));
    }
  } else if (!o.table.empty()) {
    const analysis::NumericTable t = analysis::read_numeric_table(o.table, {2, 3}, true);
    if (t.columns == 3 && planes == 1)
      throw InputError(o.table + ": two friction columns for a single plane (expected t, phi).");
    for (std::size_t k = 0; k < planes; ++k) {
      std::vector<double> times, phis;
      for (const auto& row : t.rows) {
        times.push_back(row[0]);
        phis.push_back(row[t.columns == 3 ? 1 + k : 1]);
      }
      out.push_back(FrictionLaw::table(times, phis, o.table));
    }
  } else {
    if (o.mu_lnv.size() != 2) throw InputError("--mu-lnv: give two numbers a,b.");
    if (!(o.v_ref > 0.0) || !(o.v_min > 0.0)) throw InputError("--v-ref and --v-min must be positive.");
    for (std::size_t k = 0; k < planes; ++k)
      out.push_back(FrictionLaw::log_velocity(o.mu_lnv[0], o.mu_lnv[1], o.v_ref, o.v_min));
  }
  return out;
}

void put_number(std::string& out, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

}  // namespace dda::cli
