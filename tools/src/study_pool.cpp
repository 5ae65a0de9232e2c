#include "study_pool.hpp"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <thread>

#include "study_case.hpp"
#include "study_progress.hpp"

namespace dda::cli {

namespace fs = std::filesystem;

fs::path case_dir(const fs::path& outdir, const study::Case& c) { return outdir / "cases" / c.id; }

int machine_cores() { return std::max(1u, std::thread::hardware_concurrency()); }

PoolOptions default_pool(int jobs_asked) {
  PoolOptions p;
  const int cores = machine_cores();
  p.jobs = jobs_asked > 0 ? jobs_asked : cores;
  p.threads = std::max(1, cores / p.jobs);
  return p;
}

std::vector<study::CaseRecord> run_pipeline_cases(const study::Study& study, const std::vector<study::Case>& cases,
                                                  const fs::path& outdir, const PoolOptions& options) {
  std::vector<study::CaseRecord> records(cases.size());
  std::vector<std::string> texts(cases.size());
  std::vector<std::size_t> todo;
  std::size_t skipped_failed = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    texts[i] = case_scenario_text(study, cases[i]);
    if (auto done = finished_case(case_dir(outdir, cases[i]), texts[i], study.measures.size(), options.retry_failed)) {
      records[i] = *done;
      skipped_failed += !done->ok;
    } else {
      todo.push_back(i);
    }
  }
  StudyProgress progress(options.quiet, cases.size(), cases.size() - todo.size(), skipped_failed);
  std::atomic<std::size_t> next{0};
  const auto worker = [&] {
    for (std::size_t k = next++; k < todo.size(); k = next++) {
      const std::size_t i = todo[k];
      records[i] = run_pipeline_case(study, texts[i], case_dir(outdir, cases[i]), options.threads);
      progress.case_done(records[i].ok);
    }
  };
  std::vector<std::thread> pool;
  const std::size_t workers = std::min<std::size_t>(static_cast<std::size_t>(std::max(1, options.jobs)), todo.size());
  for (std::size_t w = 0; w < workers; ++w) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
  progress.finish();
  return records;
}

}  // namespace dda::cli
