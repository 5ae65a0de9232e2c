#pragma once
// Running a study's pipeline cases on this machine: a pool of `jobs`
// worker threads, each running one case at a time as a child process
// (study_case.hpp), each case on `threads` OpenMP threads. Finished cases
// (their case.json) are skipped; a failed case is recorded and the study
// goes on.
#include <filesystem>
#include <vector>

#include "dda/study/expand.hpp"
#include "dda/study/summary.hpp"

namespace dda::cli {

struct PoolOptions {
  int jobs = 1;
  int threads = 1;
  bool quiet = false;
  bool retry_failed = false;
};

// The folder of a case: OUTDIR/cases/<id>.
std::filesystem::path case_dir(const std::filesystem::path& outdir, const study::Case& c);

// Cores of this machine (at least 1), and the pool and threads a study uses
// when -j is not given: one case per core, one thread each (most cases are
// small models, which run on one thread anyway: run_threads.hpp); with -j N,
// the cores shared out among the N cases.
int machine_cores();
PoolOptions default_pool(int jobs_asked);

// Records of all `cases`, in order.
std::vector<study::CaseRecord> run_pipeline_cases(const study::Study& study, const std::vector<study::Case>& cases,
                                                  const std::filesystem::path& outdir, const PoolOptions& options);

}  // namespace dda::cli
