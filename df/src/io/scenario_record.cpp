// The record keys of loading.earthquake, 2D and 3D (scenario_record.hpp).
#include "io/scenario_record.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>

#include "dda/common/error.hpp"
#include "dda/common/scenario.hpp"
#include "io/scenario_joints.hpp"

namespace dda::df {
namespace {

bool is_at2(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".at2";
}

ButterworthSpec read_filter(const YamlNode& f) {
  f.allow({"type", "order", "corner", "corners"});
  ButterworthSpec s;
  const std::string type = f.choice("type", {"lowpass", "highpass", "bandpass"});
  s.kind = type == "lowpass" ? FilterKind::lowpass : type == "highpass" ? FilterKind::highpass : FilterKind::bandpass;
  s.order = static_cast<int>(f.integer("order", 4, Range::closed(1, 12)));
  if (s.kind == FilterKind::bandpass) {
    if (f.has("corner")) f.fail_key("corner", "is for low- and high-pass filters; a band-pass takes corners: [low, high]");
    const YamlNode c = f.child("corners");
    const std::vector<double> v = c.as_numbers();
    if (v.size() != 2) c.fail("must be [low, high] (two frequencies in Hz), got " + std::to_string(v.size()) + " numbers");
    if (!(v[0] > 0) || !std::isfinite(v[1]) || !(v[1] > v[0]))
      c.fail("must be [low, high] with 0 < low < high (Hz)");
    s.f_low = v[0];
    s.f_high = v[1];
  } else {
    if (f.has("corners")) f.fail_key("corners", "is for a band-pass filter; a " + type + " takes one corner (Hz)");
    const double fc = f.number("corner", Range::positive());
    (s.kind == FilterKind::lowpass ? s.f_high : s.f_low) = fc;
  }
  return s;
}

Vec3 read_direction(const YamlNode& n, int dimension) {
  const YamlNode d = n.child("direction");
  const std::vector<double> v = d.as_numbers();
  const std::string form = dimension == 3 ? "[dx, dy, dz]" : "[dx, dy]";
  if (v.size() != static_cast<std::size_t>(dimension))
    d.fail("must be a direction " + form + ", got " + std::to_string(v.size()) + " numbers");
  Vec3 dir(v[0], v[1], dimension == 3 ? v[2] : 0.0);
  if (!std::isfinite(dir.norm()) || !(dir.norm() > 0)) n.fail_key("direction", "must be a non-zero direction " + form);
  return dir.normalized();
}

struct RecordEntry {
  std::string path;                            // resolved against the scenario's folder
  AccelUnits units = AccelUnits::unspecified;  // required for CSV
  Vec3 direction{1, 0, 0};                     // of a one-component record, unit
  RecordProcessing processing;
};

RecordEntry read_record_entry(const YamlNode& n, int dimension, int default_baseline) {
  RecordEntry e;
  e.path = resolve_scenario_path(n, n.text("record"));
  if (n.has("units")) {
    try {
      e.units = parse_accel_units(n.text("units"), "units");
    } catch (const InputError&) {
      n.fail_key("units", "must be g or m/s2, got '" + n.text("units") + "'");
    }
  } else if (!is_at2(e.path)) {
    n.fail_key("units", "is required for a CSV record (g or m/s2; only an AT2 file declares its units)");
  }
  if (n.has("direction")) e.direction = read_direction(n, dimension);
  RecordProcessing& p = e.processing;
  if (n.has("components")) {
    const std::vector<YamlNode> items = n.list("components");
    const std::string names = dimension == 3 ? "x, y, z" : "x, y";
    if (items.empty()) n.fail_key("components", "must name at least one of " + names);
    p.use = {false, false, dimension == 2};  // a 2D record has no z column to keep
    for (const YamlNode& c : items) {
      const std::string name = c.as_text();
      const int k = name == "x" ? 0 : name == "y" ? 1 : name == "z" && dimension == 3 ? 2 : -1;
      if (k < 0) c.fail(dimension == 3 ? "must be x, y or z, got '" + name + "'" : "must be x or y, got '" + name + "'");
      if (p.use[static_cast<std::size_t>(k)]) c.fail("repeats component " + name);
      p.use[static_cast<std::size_t>(k)] = true;
    }
  }
  p.scale = n.number("scale", 1.0, Range::any());
  if (!std::isfinite(p.scale)) n.fail_key("scale", "must be a finite number");
  if (n.has("resample")) p.resample = n.number("resample", Range::positive());
  if (n.has("filter")) p.filter = read_filter(n.child("filter"));
  p.ramp = n.number("ramp", 0.0, Range::non_negative());
  p.baseline = static_cast<int>(n.integer("baseline", default_baseline, Range::closed(0, 8)));
  return e;
}

// Reports `err`, raised while reading and processing the record of `e`, at
// the key it belongs to: `filter` when the record reads on its own
// (`read_plain` does not throw: the filter does not fit the sampling),
// else `record`.
[[noreturn]] void fail_record(const YamlNode& n, const RecordEntry& e, const std::function<void()>& read_plain,
                              const InputError& err) {
  bool read_ok = true;
  try {
    read_plain();
  } catch (const InputError&) {
    read_ok = false;
  }
  n.fail_key(read_ok && e.processing.filter ? "filter" : "record", "cannot be used: " + sentence_tail(err));
}

}  // namespace

template <int dim>
EarthquakeRecord<dim> read_earthquake_record(const YamlNode& n) {
  const std::string name = n.has("mode") ? n.text("mode") : "loading";
  const std::vector<std::string> names = ground_motion_mode_names();
  if (std::find(names.begin(), names.end(), name) == names.end())
    n.child("mode").fail("must be one of " + join_names(names) + ", got '" + name + "'");
  const GroundMotionMode& mode = ground_motion_mode(name);
  const RecordEntry r = read_record_entry(n, dim, mode.default_baseline);
  RecordReadOptions options;
  options.units = r.units;
  options.direction = r.direction;
  // The plain record must fit the model before any processing (a 2D model
  // refuses a z column even when `components` would drop it).
  const auto read_plain = [&] {
    AccelRecord rec = read_record(r.path, options);
    check_record_fits<dim>(rec);
    return rec;
  };
  try {
    AccelRecord rec = read_plain();
    process_record(rec, r.processing);
    return {mode, ground_motion_of<dim>(rec)};
  } catch (const InputError& err) {
    fail_record(n, r, [&] { read_plain(); }, err);
  }
}

template EarthquakeRecord<2> read_earthquake_record<2>(const YamlNode&);
template EarthquakeRecord<3> read_earthquake_record<3>(const YamlNode&);

void require_incident_for_free_field(const YamlNode& root, bool free_field, bool incident) {
  if (free_field && !incident)
    root.child("boundaries").fail_key("free_field", "needs an incident wave (loading.earthquake with mode: "
                                                    "incident): the free field is the motion that wave gives the rock");
}

}  // namespace dda::df
