#pragma once
// What a study writes once its cases have run: OUTDIR/summary.csv, one row
// per case, and OUTDIR/study.h5, the same columns plus the study file
// (docs/studies.md, docs/formats.md). Both are written atomically. Numbers
// are written in their shortest round-trip form, so a study run locally and
// under MPI gives the same summary value for value (all but `seconds`).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dda/study/expand.hpp"

namespace dda::study {

struct CaseRecord {
  bool ok = false;
  double seconds = 0;
  std::string error;             // the case's one-sentence error when it failed
  std::vector<double> measures;  // ok: one per measure, NaN where there is none; failed: none
};

// As each case's case.json holds it (and an MPI worker sends it).
nlohmann::json record_json(const CaseRecord& r);
// nullopt when the document is not a record of `measures` values (a
// damaged or foreign case.json: the case runs again).
std::optional<CaseRecord> record_from_json(const nlohmann::json& j, std::size_t measures);

// The summary's header and rows. `cases[i]` and `records[i]` belong together.
std::vector<std::string> summary_header(const Study& study);
std::string summary_csv(const Study& study, const std::vector<Case>& cases, const std::vector<CaseRecord>& records);
void write_summary_csv(const std::string& path, const Study& study, const std::vector<Case>& cases,
                       const std::vector<CaseRecord>& records);
void write_study_h5(const std::string& path, const Study& study, const std::vector<Case>& cases,
                    const std::vector<CaseRecord>& records);

}  // namespace dda::study
