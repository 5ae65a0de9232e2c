#include "study_mpi.hpp"

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

#include "dda/common/error.hpp"
#include "study_case.hpp"
#include "study_progress.hpp"

#ifdef DDA_HAVE_MPI
// The C interface only: Open MPI's mpi.h otherwise pulls in its deprecated
// C++ bindings, which need a library of their own.
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

namespace dda::cli {

namespace fs = std::filesystem;

bool launched_by_mpi() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE", "MPI_LOCALNRANKS"})
    if (std::getenv(var)) return true;
  return false;
}

#ifdef DDA_HAVE_MPI
bool built_with_mpi() { return true; }
#else
bool built_with_mpi() { return false; }
#endif

int MpiWorld::threads_per_rank() const {
  if (case_ranks_on_node_ > 0) return std::max(1, machine_cores() / case_ranks_on_node_);
  int local = 1;
  for (const char* var : {"OMPI_COMM_WORLD_LOCAL_SIZE", "SLURM_NTASKS_PER_NODE", "MPI_LOCALNRANKS"})
    if (const char* v = std::getenv(var)) {
      local = std::max(1, std::atoi(v));
      break;
    }
  return std::max(1, machine_cores() / local);
}

#ifdef DDA_HAVE_MPI

namespace {

enum Tag : int { kAsk = 1, kResult = 2, kWork = 3, kStop = 4 };

// Waits for a message from any rank without spinning a core: rank 0 only
// hands out cases and shares its node with the ranks that run them.
MPI_Status probe_politely() {
  int flag = 0;
  MPI_Status status{};
  for (;;) {
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
    if (flag) return status;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

std::string receive_text(const MPI_Status& status) {
  int count = 0;
  MPI_Get_count(&status, MPI_CHAR, &count);
  std::string text(static_cast<std::size_t>(count), '\0');
  MPI_Recv(text.data(), count, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return text;
}

void send_text(const std::string& text, int to, int tag) {
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

}  // namespace

MpiWorld::MpiWorld() {
  if (!launched_by_mpi()) return;
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  initialised_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  // The ranks sharing this node's cores, less rank 0 if it is one of them
  // (it hands out cases and waits without spinning): with mpirun -n 2 on a
  // 2-core machine the one rank that runs cases gets both cores, as a
  // direct run does.
  MPI_Comm node = MPI_COMM_NULL;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
  int on_node = 1, runners = 0;
  MPI_Comm_size(node, &on_node);
  const int runs_cases = rank_ == 0 && size_ > 1 ? 0 : 1;
  MPI_Allreduce(&runs_cases, &runners, 1, MPI_INT, MPI_SUM, node);
  MPI_Comm_free(&node);
  case_ranks_on_node_ = std::max(1, runners);
}

MpiWorld::~MpiWorld() {
  if (initialised_) MPI_Finalize();
}

void MpiWorld::abort(int status) const {
  if (initialised_) MPI_Abort(MPI_COMM_WORLD, status);
  std::exit(status);
}

void MpiWorld::barrier() const {
  if (initialised_) MPI_Barrier(MPI_COMM_WORLD);
}

int MpiWorld::count_ranks(bool mine) const {
  if (!initialised_) return mine ? 1 : 0;
  int in = mine ? 1 : 0, total = 0;
  MPI_Allreduce(&in, &total, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  return total;
}

std::vector<study::CaseRecord> run_pipeline_cases_mpi(const study::Study& study, const std::vector<study::Case>& cases,
                                                      const fs::path& outdir, const PoolOptions& options,
                                                      const MpiWorld& world) {
  if (world.rank() != 0) {
    // A worker: ask, run what comes, send back its record with the next ask.
    send_text("", 0, kAsk);
    for (;;) {
      MPI_Status status{};
      MPI_Probe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
      const std::string text = receive_text(status);
      if (status.MPI_TAG == kStop) return {};
      const std::size_t i = std::stoul(text);
      const study::CaseRecord r =
          run_pipeline_case(study, case_scenario_text(study, cases[i]), case_dir(outdir, cases[i]), options.threads);
      send_text(std::to_string(i) + "\n" + study::record_json(r).dump(), 0, kResult);
    }
  }
  std::vector<study::CaseRecord> records(cases.size());
  std::vector<std::size_t> todo;
  std::size_t skipped_failed = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (auto done = finished_case(case_dir(outdir, cases[i]), case_scenario_text(study, cases[i]),
                                  study.measures.size(), options.retry_failed)) {
      records[i] = *done;
      skipped_failed += !done->ok;
    } else {
      todo.push_back(i);
    }
  }
  StudyProgress progress(options.quiet, cases.size(), cases.size() - todo.size(), skipped_failed);
  std::size_t next = 0;
  int working = world.size() - 1;
  while (working > 0) {
    const MPI_Status status = probe_politely();
    const std::string text = receive_text(status);
    if (status.MPI_TAG == kResult) {
      const std::size_t newline = text.find('\n');
      const std::size_t i = std::stoul(text.substr(0, newline));
      const auto record = study::record_from_json(nlohmann::json::parse(text.substr(newline + 1)), study.measures.size());
      if (!record || i >= records.size()) throw std::runtime_error("a rank sent a case record that does not parse");
      records[i] = *record;
      progress.case_done(record->ok);
    }
    if (next < todo.size()) {
      send_text(std::to_string(todo[next++]), status.MPI_SOURCE, kWork);
    } else {
      send_text("", status.MPI_SOURCE, kStop);
      --working;
    }
  }
  progress.finish();
  return records;
}

std::vector<study::CaseRecord> run_even_cases_mpi(std::size_t count, std::size_t measures,
                                                  const std::function<study::CaseRecord(std::size_t)>& run_case,
                                                  const MpiWorld& world) {
  const auto rank = static_cast<std::size_t>(world.rank()), size = static_cast<std::size_t>(world.size());
  if (rank != 0) {
    nlohmann::json mine = nlohmann::json::array();
    for (std::size_t i = rank; i < count; i += size) mine.push_back(study::record_json(run_case(i)));
    send_text(mine.dump(), 0, kResult);
    return {};
  }
  std::vector<study::CaseRecord> records(count);
  for (std::size_t i = 0; i < count; i += size) records[i] = run_case(i);
  for (std::size_t received = 1; received < size; ++received) {
    const MPI_Status status = probe_politely();
    const nlohmann::json theirs = nlohmann::json::parse(receive_text(status));
    std::size_t i = static_cast<std::size_t>(status.MPI_SOURCE);
    for (const nlohmann::json& j : theirs) {
      const auto record = study::record_from_json(j, measures);
      if (!record || i >= count) throw std::runtime_error("a rank sent case records that do not parse");
      records[i] = *record;
      i += size;
    }
  }
  return records;
}

#else  // without MPI: a world of one

MpiWorld::MpiWorld() {
  if (launched_by_mpi()) {
    const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
    if (!size) size = std::getenv("PMI_SIZE");
    if (size && std::atoi(size) > 1)
      throw InputError("this dda was built without MPI, so it cannot share a study among " + std::string(size) +
                       " ranks: rebuild it with Open MPI installed (libopenmpi-dev), or run the study without mpirun.");
  }
}

MpiWorld::~MpiWorld() = default;

void MpiWorld::abort(int status) const { std::exit(status); }

int MpiWorld::count_ranks(bool mine) const { return mine ? 1 : 0; }

void MpiWorld::barrier() const {}

std::vector<study::CaseRecord> run_pipeline_cases_mpi(const study::Study&, const std::vector<study::Case>&,
                                                      const fs::path&, const PoolOptions&, const MpiWorld&) {
  throw InputError("this dda was built without MPI.");
}

std::vector<study::CaseRecord> run_even_cases_mpi(std::size_t, std::size_t,
                                                  const std::function<study::CaseRecord(std::size_t)>&, const MpiWorld&) {
  throw InputError("this dda was built without MPI.");
}

#endif

}  // namespace dda::cli
