#pragma once
// What a case reports (`measure:` in a study file). The kinds are listed
// once, in measure.cpp, with the case kind they apply to and the keys they
// take; a pipeline measure is computed from the files `dda run` wrote into
// the case's folder (tools/src/study_measures.cpp), a wedge measure from the
// limit equilibrium (wedge_case.cpp).
#include <string>

#include "dda/common/yaml_reader.hpp"

namespace dda::study {

enum class CaseKind;

struct MeasureSpec {
  std::string name;   // the summary column
  std::string kind;   // e.g. "point_displacement"
  std::string point;  // point_displacement: the measurement point
  std::string of;     // point_displacement: "final" or "peak"
  std::string key;    // stats: a key of stats.json, dots for nested keys ("area.mean")
  double value = 0;   // blocks_displaced: the threshold (m); blocks_below: the level y (m)
};

// One entry of `measure:`: a kind's name alone, or a mapping {kind, name,
// ...}. InputError naming the file, line and key when the kind is unknown,
// belongs to the other case kind, or lacks a key it needs.
MeasureSpec read_measure(const YamlNode& node, CaseKind kind);

}  // namespace dda::study
