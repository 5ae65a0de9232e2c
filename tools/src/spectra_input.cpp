// Signals of `dda spectra` (spectra_input.hpp).
#include "spectra_input.hpp"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "dda/common/error.hpp"
#include "results_points.hpp"

namespace dda::cli {

namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string column_list(const analysis::NamedTable& t) {
  std::string out;
  for (const std::string& h : t.header) out += (out.empty() ? "" : ", ") + h;
  return out;
}

}  // namespace

Quantity parse_quantity(const std::string& text, const std::string& flag) {
  if (text == "displacement") return Quantity::displacement;
  if (text == "velocity") return Quantity::velocity;
  if (text == "acceleration") return Quantity::acceleration;
  throw InputError(flag + ": '" + text + "' is not displacement, velocity or acceleration.");
}

const char* quantity_name(Quantity q) {
  switch (q) {
    case Quantity::displacement: return "displacement";
    case Quantity::velocity: return "velocity";
    case Quantity::acceleration: break;
  }
  return "acceleration";
}

SignalSource::SignalSource(const std::string& path, const std::string& record_units) : path_(path) {
  const std::string ext = lower_extension(path);
  if (ext == ".h5" || ext == ".hdf5") {
    if (!record_units.empty()) throw InputError("--units: applies to a CSV or AT2 record, not to " + path + ".");
    results_ = std::make_shared<const df::Results>(df::read_results_h5(path, df::ResultsParts::records()));
  } else if (ext == ".at2" || !record_units.empty()) {
    RecordReadOptions ro;
    if (!record_units.empty()) ro.units = parse_accel_units(record_units, "--units");
    record_ = std::make_shared<const AccelRecord>(read_record(path, ro));
  } else {
    table_ = std::make_shared<const analysis::NamedTable>(
        analysis::read_named_table(path, "t, then one column per series, e.g. `dda history --csv`"));
  }
}

RawSignal SignalSource::point(const std::string& name, char component, Quantity q) const {
  if (component != 'x' && component != 'y')
    throw InputError(std::string("--component: '") + component + "' is not x or y (a point of the 2D model).");
  RawSignal s;
  const char c = component;
  // Acceleration: stored in results files (constant within each DDA step),
  // else the velocity differentiated.
  const bool stored_acceleration = results_ && results_->has_acceleration && q == Quantity::acceleration;
  const bool derive = q == Quantity::acceleration && !stored_acceleration;
  const char letter = q == Quantity::displacement ? 'u' : stored_acceleration ? 'a' : 'v';
  s.units = q == Quantity::displacement ? "m" : q == Quantity::velocity ? "m/s" : "m/s^2";
  s.label = name + "." + (q == Quantity::acceleration ? 'a' : letter) + c;
  s.differentiate = derive;
  if (results_) {
    const std::size_t p = measurement_point_index(*results_, name, path_);
    for (const df::MeasurementSample& m : results_->histories[p]) {
      const Vec2 w = letter == 'u' ? m.displacement : letter == 'a' ? m.acceleration : m.velocity;
      const double v = c == 'x' ? w.x() : w.y();
      if (!std::isfinite(v))
        throw InputError(path_ + ": point '" + name + "' has a non-finite " +
                         (letter == 'u' ? "displacement" : letter == 'a' ? "acceleration" : "velocity") +
                         " at t = " + num(m.time) + " s.");
      if (!s.t.empty() && !(m.time > s.t.back()))
        throw InputError(path_ + ": the times of point '" + name + "' do not increase at t = " + num(m.time) + " s.");
      s.t.push_back(m.time);
      s.x.push_back(v);
    }
    return s;
  }
  if (!table_)
    throw InputError("--point: applies to a results file or a `dda history --csv` file, not to the record " + path_ +
                     ".");
  // A `dda history --csv` file: NAME.ax if someone added it, else NAME.vx differentiated.
  const std::string direct = name + "." + (derive ? 'a' : letter) + c;
  const std::string from_velocity = name + ".v" + c;
  int col = table_->column(direct);
  if (col < 0 && derive) {
    col = table_->column(from_velocity);
  } else {
    s.differentiate = false;
  }
  if (col < 0)
    throw InputError(path_ + ": has no column '" + (derive ? from_velocity : direct) + "' for point '" + name +
                     "' (its columns are " + column_list(*table_) + ").");
  for (const auto& row : table_->table.rows) {
    s.t.push_back(row[0]);
    s.x.push_back(row[static_cast<std::size_t>(col)]);
  }
  return s;
}

RawSignal SignalSource::column(const std::string& name) const {
  if (!table_)
    throw InputError("--column: applies to a CSV table with a header line, not to " + path_ +
                     (results_ ? " (give --point)." : " (a record: give --component)."));
  const int col = table_->column(name);
  if (col == 0) throw InputError(path_ + ": '" + name + "' is the time column; give one of the series after it.");
  if (col < 0)
    throw InputError(path_ + ": has no column '" + name + "' (its columns are " + column_list(*table_) + ").");
  RawSignal s;
  s.label = name;
  for (const auto& row : table_->table.rows) {
    s.t.push_back(row[0]);
    s.x.push_back(row[static_cast<std::size_t>(col)]);
  }
  return s;
}

RawSignal SignalSource::record_component(char component) const {
  if (!record_) throw InternalError("record_component on a source that is not a record");
  const int c = component == 'x' ? 0 : component == 'y' ? 1 : component == 'z' ? 2 : -1;
  if (c < 0) throw InputError(std::string("--component: '") + component + "' is not x, y or z (a record's axes).");
  RawSignal s;
  s.label = std::string("a") + component;
  s.units = "m/s^2";
  s.t = record_->t;
  s.x = record_->a[static_cast<std::size_t>(c)];
  return s;
}

std::vector<UniformSignal> make_uniform(const std::vector<RawSignal>& raw, double dt, const std::string& path,
                                        bool& resampled) {
  const std::vector<double>& t = raw.front().t;
  if (t.size() < 2)
    throw InputError(path + ": " + raw.front().label + " has " + std::to_string(t.size()) + " sample" +
                     (t.size() == 1 ? "" : "s") + "; a spectrum needs at least " +
                     std::to_string(kMinSpectraSamples) + ".");
  const double step = dt > 0.0 ? dt : analysis::median_step(t);
  const double natural = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  resampled = !(analysis::is_uniform(t) && std::abs(natural - step) <= 1e-6 * step);
  std::vector<UniformSignal> out;
  for (const RawSignal& r : raw) {
    UniformSignal u;
    u.label = r.label;
    u.units = r.units;
    if (resampled) {
      u.series = analysis::resample_uniform(r.t, r.x, step);
    } else {
      u.series.t0 = t.front();
      u.series.dt = natural;
      u.series.x = r.x;
    }
    if (u.series.x.size() < kMinSpectraSamples)
      throw InputError(path + ": " + r.label + " has " + std::to_string(u.series.x.size()) + " samples at the step " +
                       num(u.series.dt) + " s; a spectrum needs at least " + std::to_string(kMinSpectraSamples) +
                       ".");
    if (r.differentiate) u.series.x = analysis::central_difference(u.series.x, u.series.dt);
    out.push_back(std::move(u));
  }
  return out;
}

}  // namespace dda::cli
