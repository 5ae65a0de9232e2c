// The `control` keys both dimensions share (scenario_control.hpp).
#include "io/scenario_control.hpp"

#include <algorithm>

namespace dda::df {

RunLength read_run_length(const YamlNode& c, const RunLength& defaults) {
  RunLength r = defaults;
  // Absent: 0, chosen from the model when it is built (time_step.hpp).
  r.dt = c.has("dt") ? c.number("dt", Range::positive()) : 0.0;
  if (c.one_of({"total_time", "steps"}) == "total_time")
    r.total_time = c.number("total_time", Range::positive());
  else
    r.steps = static_cast<int>(c.integer("steps", Range::closed(1, 1e9)));
  r.max_displacement_ratio = c.number("max_displacement_ratio", defaults.max_displacement_ratio, Range{0, 1, true, true});
  r.min_dt_ratio = c.number("min_dt_ratio", defaults.min_dt_ratio, Range{0, 1, true, false});
  if (c.has("output_interval") && c.has("output_every"))
    c.fail_key("output_every", "cannot be given together with output_interval (give one)");
  if (c.has("output_interval")) r.output.interval = c.number("output_interval", Range::positive());
  if (c.has("output_every")) r.output.every = static_cast<int>(c.integer("output_every", Range::closed(1, 1e9)));
  return r;
}

ViscousDamping read_damping(const YamlNode& control) {
  ViscousDamping d;
  const auto node = control.optional_child("damping");
  if (!node) return d;
  node->allow({"ratio", "frequency"});
  // Below 1: an overdamped deformation is no use to anyone, and a ratio
  // given in per cent (5 for 5 %) is caught here.
  d.ratio = node->number("ratio", Range::half_open(0, 1));
  d.frequency = node->number("frequency", Range::positive());
  return d;
}

OutputSchedule resolve_output_schedule(OutputSchedule s, double total_time, int steps) {
  if (s.interval > 0 || s.every > 0) return s;
  if (total_time > 0)
    s.interval = total_time / 20;
  else
    s.every = std::max(1, steps / 20);
  return s;
}

OutputSchedule resolve_output_schedule(OutputSchedule s, const Control& control) {
  return resolve_output_schedule(s, control.total_time, control.steps);
}

}  // namespace dda::df
