#pragma once
// The record keys of loading.earthquake that the 2D and the 3D scenario
// share (private to DF; documented in docs/scenario.md): record, units,
// direction, components, scale, resample, filter, ramp, baseline. What the
// motion then does (the modes, the foundation) is each dimension's own.
#include <functional>
#include <string>

#include "dda/common/error.hpp"
#include "dda/common/geometry3d.hpp"
#include "dda/common/record.hpp"
#include "dda/common/yaml_reader.hpp"
#include "dda/common/sentence_tail.hpp"

namespace dda::df {

struct RecordEntry {
  std::string path;                            // resolved against the scenario's folder
  AccelUnits units = AccelUnits::unspecified;  // required for CSV
  Vec3 direction{1, 0, 0};                     // of a one-component record, unit
  RecordProcessing processing;
};

// Reads the shared keys of `n` (which the caller has allow()ed).
// `dimension` 2: direction [dx, dy] and components x, y (y vertical);
// 3: [dx, dy, dz] and x, y, z (z up). `default_baseline`: the mode's.
RecordEntry read_record_entry(const YamlNode& n, int dimension, int default_baseline);

// Reports `err`, raised while reading and processing the record of `e`, at
// the key it belongs to: `filter` when the record reads on its own
// (`read_plain` does not throw: the filter does not fit the sampling),
// else `record`.
[[noreturn]] void fail_record(const YamlNode& n, const RecordEntry& e, const std::function<void()>& read_plain,
                              const InputError& err);

// boundaries.free_field (both dimensions) only beside an incident wave: the
// free field is the motion that wave gives the rock, so without one the
// sides would be plain dashpots under another name. InputError at
// boundaries.free_field when `free_field` but not `incident`.
void require_incident_for_free_field(const YamlNode& root, bool free_field, bool incident);

}  // namespace dda::df
