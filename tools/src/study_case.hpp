#pragma once
// One pipeline case of a study: its folder OUTDIR/cases/<id>/ with
// scenario.yaml (the base with the case's values), everything `dda run`
// writes there, log.txt (what it printed) and case.json (the case's record:
// status, seconds, error, measures), written last and atomically. A folder
// with a case.json for the same scenario.yaml is a finished case; anything
// else is a case that has not run or was killed, and runs (again) from an
// empty folder.
#include <filesystem>
#include <optional>
#include <string>

#include "dda/study/expand.hpp"
#include "dda/study/summary.hpp"

namespace dda::cli {

// The text of the case's scenario: the case document, with the file paths
// it names (keys file, geometry, record) made absolute from the base
// scenario's folder, since the case runs from its own folder.
std::string case_scenario_text(const study::Study& study, const study::Case& c);

// The record of a finished case in `dir` whose scenario is `scenario_text`;
// nullopt if it has not finished (or `retry_failed` and it failed).
std::optional<study::CaseRecord> finished_case(const std::filesystem::path& dir, const std::string& scenario_text,
                                               std::size_t measures, bool retry_failed);

// Runs the case in `dir` (made empty first): this program's `dda run` as a
// child process on `threads` OpenMP threads, then the measures. A case
// that fails is a record with its error, never an exception.
study::CaseRecord run_pipeline_case(const study::Study& study, const std::string& scenario_text,
                                    const std::filesystem::path& dir, int threads);

}  // namespace dda::cli
