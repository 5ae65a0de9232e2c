#pragma once
// The rock bolts of a results file, 2D or 3D, for `dda history`: a summary
// table and the CSV of --bolts.
#include <string>
#include <vector>

#include "dda/df/core/bolt_law.hpp"

namespace dda::cli {

// One line per bolt: final force and length, largest force, and when it
// broke; "" for a file without bolts.
std::string bolt_summary(const std::vector<std::string>& names, const std::vector<std::vector<df::BoltSample>>& h);
// t, then NAME.force (N, tension positive), NAME.length (m) and NAME.broken
// (0 or 1) of every bolt, one row per sample (sample 0 the start of the run).
std::string bolts_csv(const std::vector<std::string>& names, const std::vector<std::vector<df::BoltSample>>& h);

}  // namespace dda::cli
