#pragma once
// What made a file: stored as attributes on every HDF5 file the project writes
// so that a lines, blocks or results file describes itself.
#include <cstdint>
#include <string>

namespace dda {

struct Provenance {
  std::string program_version;  // dda::version_string() of the writer
  std::string scenario_path;    // the scenario file as given on the command line
  std::string scenario_text;    // the whole scenario, verbatim
  std::uint64_t seed = 0;       // random seed used by DL (0 if none was drawn)
  std::string created_utc;      // ISO 8601, set by the writer
};

// Program version, e.g. "0.1.0"; defined in the generated version.cpp.
const char* version_string();

// The current time as ISO 8601 UTC, e.g. "2026-11-22T21:50:00Z" (the
// `created_utc` of every file the project writes).
std::string utc_now();

}  // namespace dda
