#pragma once
// The keys of loading.earthquake that the 2D and the 3D scenario share
// (private to DF; documented in docs/scenario.md): mode, record, units,
// direction, components, scale, resample, filter, ramp, baseline. Where the
// motion goes (the foundation, the viscous sides) is each kernel's own.
#include <string>

#include "dda/common/error.hpp"
#include "dda/common/geometry3d.hpp"
#include "dda/common/record.hpp"
#include "dda/common/yaml_reader.hpp"
#include "dda/common/sentence_tail.hpp"
#include "dda/df/core/ground_motion.hpp"

namespace dda::df {

// What loading.earthquake gives both dimensions: the mode and the motion.
template <int dim>
struct EarthquakeRecord {
  GroundMotionMode mode;
  GroundMotion<dim> motion;  // read and processed (so bad records fail early)
};

// Reads `mode` and the record keys of `n` (which the caller has allow()ed)
// and the record itself, processed. Components: 2D x, y (y vertical; a
// direction is [dx, dy]); 3D x, y, z (z up; [dx, dy, dz]). The baseline
// default is the mode's. InputError with the scenario file, line and key
// (`filter` when the record reads but the filter does not fit its
// sampling, else `record`, with the record file and line of a bad record).
template <int dim>
EarthquakeRecord<dim> read_earthquake_record(const YamlNode& n);

// boundaries.free_field (both dimensions) only beside an incident wave: the
// free field is the motion that wave gives the rock, so without one the
// sides would be plain dashpots under another name. InputError at
// boundaries.free_field when `free_field` but not `incident`.
void require_incident_for_free_field(const YamlNode& root, bool free_field, bool incident);

}  // namespace dda::df
