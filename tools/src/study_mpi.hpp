#pragma once
// A study under MPI (`mpirun -n 64 dda study ...`, or srun under Slurm;
// docs/studies.md). Rank 0 hands out the cases one at a time to the ranks
// that ask (cases differ a lot in cost, so a fixed split would leave ranks
// idle) and writes the summary; every other rank runs the cases it is given,
// each as on one machine (study_case.hpp), into the shared OUTDIR.
//
// MPI is used only when this program was built with it (CMake finds MPI
// when it is installed) and started by an MPI launcher; otherwise the world
// is this one process. Nothing of MPI is seen outside study_mpi.cpp.
#include <filesystem>
#include <functional>
#include <memory>
#include <vector>

#include "dda/study/expand.hpp"
#include "dda/study/summary.hpp"
#include "study_pool.hpp"

namespace dda::cli {

class MpiWorld {
 public:
  MpiWorld();  // MPI_Init when started by an MPI launcher
  ~MpiWorld();  // MPI_Finalize
  MpiWorld(const MpiWorld&) = delete;
  MpiWorld& operator=(const MpiWorld&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }
  // The cores of this node shared among the ranks on it that run cases:
  // rank 0 only hands them out, so on its node one rank fewer shares them
  // (found by MPI when it runs; else from Open MPI's
  // OMPI_COMM_WORLD_LOCAL_SIZE or Slurm's SLURM_NTASKS_PER_NODE). At least 1.
  int threads_per_rank() const;
  // Ends every rank with `status` (MPI_Abort): for an error on one rank
  // while the others may be waiting for it. Without MPI, exits this process.
  [[noreturn]] void abort(int status) const;
  // How many ranks have `mine` true (every rank calls it: MPI_Allreduce).
  int count_ranks(bool mine) const;
  // Waits until every rank has come here (MPI_Barrier).
  void barrier() const;

 private:
  int rank_ = 0, size_ = 1;
  int case_ranks_on_node_ = 0;  // ranks of this node that run cases; 0: not known (no MPI)
  bool initialised_ = false;
};

// True when this process was started by an MPI launcher (its environment
// says so), whether or not this program was built with MPI.
bool launched_by_mpi();
// Whether this program was built with MPI.
bool built_with_mpi();

// Runs `cases` across the world's ranks; rank 0 returns the records of all
// cases, the other ranks an empty list. Needs at least two ranks.
std::vector<study::CaseRecord> run_pipeline_cases_mpi(const study::Study& study, const std::vector<study::Case>& cases,
                                                      const std::filesystem::path& outdir, const PoolOptions& options,
                                                      const MpiWorld& world);

// Runs `count` cases of about equal cost (the in-process wedge cases, a few
// microseconds each) across the world's ranks, rank r taking cases r,
// r + size, ...: no handing out, one message a rank. Each record holds
// `measures` values. Rank 0 returns the records of all cases in order, the
// other ranks an empty list.
std::vector<study::CaseRecord> run_even_cases_mpi(std::size_t count, std::size_t measures,
                                                  const std::function<study::CaseRecord(std::size_t)>& run_case,
                                                  const MpiWorld& world);

}  // namespace dda::cli
