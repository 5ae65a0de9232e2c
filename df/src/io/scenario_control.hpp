#pragma once
// The keys of the scenario's `control` section that the 2D and the 3D run
// share (private to DF; docs/scenario.md): the time step, the run length,
// step control and the frame schedule. Each dimension reads its own keys
// (penalties, solver, ...) besides these.
#include "dda/common/yaml_reader.hpp"
#include "dda/df/core/damping.hpp"
#include "dda/df/io/scenario.hpp"

namespace dda::df {

struct RunLength {
  double dt = 0;                         // s
  double total_time = 0;                 // s, or
  int steps = 0;                         // steps (exactly one of the two is set)
  double max_displacement_ratio = 0.01;  // g2
  double min_dt_ratio = 1e-3;
  OutputSchedule output;                 // unset (both 0) unless given
};

// The keys these read (for YamlNode::allow, with the dimension's own).
inline constexpr const char* kRunLengthKeys[] = {"dt",           "total_time",      "steps",        "max_displacement_ratio",
                                                 "min_dt_ratio", "output_interval", "output_every"};

// Reads them from `control`; the defaults are those of `defaults`.
RunLength read_run_length(const YamlNode& control, const RunLength& defaults = {});

// `control.damping: {ratio, frequency}` (damping.hpp); none when absent.
// Its key is "damping" (for YamlNode::allow).
ViscousDamping read_damping(const YamlNode& control);

}  // namespace dda::df
