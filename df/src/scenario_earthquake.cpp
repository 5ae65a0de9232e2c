// loading.earthquake of the scenario into a GroundMotion and a mode
// (scenario_earthquake.hpp; keys documented in docs/scenario.md).
#include "scenario_earthquake.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include "dda/common/error.hpp"
#include "dda/common/scenario.hpp"

namespace dda::df {
namespace {

// A library message as the tail of a scenario sentence (YamlNode::fail adds
// the full stop).
std::string tail(const InputError& e) {
  std::string s = e.what();
  while (!s.empty() && (s.back() == '.' || s.back() == ' ')) s.pop_back();
  return s;
}

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

}  // namespace

EarthquakeEntry read_earthquake(const YamlNode& n) {
  n.allow({"record", "units", "direction", "components", "scale", "resample", "filter", "ramp", "baseline", "mode",
           "foundation"});
  EarthquakeEntry e{n, "loading", {}, {}, std::nullopt};
  GroundMotionSpec& s = e.spec;
  s.path = resolve_scenario_path(n, n.text("record"));
  if (n.has("units")) {
    try {
      s.units = parse_accel_units(n.text("units"), "units");
    } catch (const InputError&) {
      n.fail_key("units", "must be g or m/s2, got '" + n.text("units") + "'");
    }
  } else if (!is_at2(s.path)) {
    n.fail_key("units", "is required for a CSV record (g or m/s2; only an AT2 file declares its units)");
  }
  if (n.has("direction")) {
    s.direction = n.point("direction");
    if (!std::isfinite(s.direction.norm()) || !(s.direction.norm() > 0))
      n.fail_key("direction", "must be a non-zero direction [dx, dy]");
    s.direction.normalize();
  }
  if (n.has("components")) {
    const std::vector<YamlNode> items = n.list("components");
    if (items.empty()) n.fail_key("components", "must name at least one of x, y");
    s.use_x = s.use_y = false;
    for (const YamlNode& c : items) {
      const std::string name = c.as_text();
      if (name != "x" && name != "y") c.fail("must be x or y, got '" + name + "'");
      bool& use = name == "x" ? s.use_x : s.use_y;
      if (use) c.fail("repeats component " + name);
      use = true;
    }
  }
  s.scale = n.number("scale", 1.0, Range::any());
  if (!std::isfinite(s.scale)) n.fail_key("scale", "must be a finite number");
  if (n.has("resample")) s.resample = n.number("resample", Range::positive());
  if (n.has("filter")) s.filter = read_filter(n.child("filter"));
  s.ramp = n.number("ramp", 0.0, Range::non_negative());
  e.mode = n.choice("mode", {"loading", "displacement", "incident"}, "loading");
  s.baseline = static_cast<int>(
      n.integer("baseline", make_ground_motion_mode(e.mode)->default_baseline(), Range::closed(0, 8)));
  if (n.has("foundation")) {
    e.foundation.emplace();
    const std::vector<YamlNode> items = n.list("foundation");
    if (items.empty()) n.fail_key("foundation", "must name at least one fixed point or side");
    for (const YamlNode& item : items) e.foundation->emplace_back(item, item.as_text());
  }

  try {
    e.motion = load_ground_motion(s);
  } catch (const InputError& err) {
    // Reading problems are the record's; processing ones (a filter that
    // does not fit the sampling, mostly) the filter's.
    const bool read_ok = [&] {
      try {
        GroundMotionSpec plain;
        plain.path = s.path;
        plain.units = s.units;
        plain.direction = s.direction;
        load_ground_motion(plain);
        return true;
      } catch (const InputError&) {
        return false;
      }
    }();
    n.fail_key(read_ok && s.filter ? "filter" : "record", "cannot be used: " + tail(err));
  }
  return e;
}

namespace {

// Incident mode: marks the viscous edges of the entry sides as input.
void mark_input_sides(const EarthquakeEntry& e, const ViscousSides& viscous, ModelInput& in) {
  std::vector<std::pair<YamlNode, std::string>> sides;
  if (e.foundation) sides = *e.foundation;
  else sides.emplace_back(e.node, "bottom");
  for (const auto& [node, side] : sides) {
    const auto it = viscous.find(side);
    if (it == viscous.end()) {
      const std::string what = "the incident wave enters through side " + side +
                               ", which boundaries.viscous does not list (add it there)";
      if (e.foundation) node.fail(what);
      e.node.fail_key("mode", std::string("incident needs a viscous boundary: ") + what);
    }
    for (const std::size_t k : it->second) in.viscous_boundary->edges[k].input = true;
  }
}

}  // namespace

void apply_earthquake(const EarthquakeEntry& e, const std::vector<std::string>& boundary_sides,
                      const ViscousSides& viscous, ModelInput& in) {
  std::vector<std::size_t> foundation;
  if (e.mode == "incident") {
    mark_input_sides(e, viscous, in);
  } else if (!e.foundation) {
    for (std::size_t k = 0; k < in.fixed_points.size(); ++k) foundation.push_back(k);
  } else {
    std::set<std::size_t> chosen;
    for (const auto& [node, name] : *e.foundation) {
      const bool side = name == "bottom" || name == "top" || name == "left" || name == "right";
      const std::string prefix = "boundary_" + name + "_";
      std::size_t found = 0;
      for (std::size_t k = 0; k < in.fixed_points.size(); ++k) {
        const std::string& fp = in.fixed_points[k].name;
        if (side ? fp.rfind(prefix, 0) == 0 : fp == name) chosen.insert(k), ++found;
      }
      if (found > 0) continue;
      if (side) {
        const bool listed = std::find(boundary_sides.begin(), boundary_sides.end(), name) != boundary_sides.end();
        node.fail(listed ? "selects the fixed.boundary points of side " + name + ", but there are none"
                         : "names side " + name + ", which fixed.boundary does not hold (add it there)");
      }
      std::string known;
      for (const FixedPoint& f : in.fixed_points)
        if (f.name.rfind("boundary_", 0) != 0) known += (known.empty() ? "" : ", ") + f.name;
      node.fail("names '" + name + "', which is neither a fixed point nor a side of fixed.boundary (fixed points: " +
                (known.empty() ? "none" : known) + ")");
    }
    foundation.assign(chosen.begin(), chosen.end());
  }
  try {
    make_ground_motion_mode(e.mode)->apply(e.motion, foundation, in);
  } catch (const InputError& err) {
    e.node.fail_key(e.foundation ? "foundation" : "mode", "cannot be applied: " + tail(err));
  }
}

}  // namespace dda::df
