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
  // The cores of this node shared among the ranks on it (Open MPI's
  // OMPI_COMM_WORLD_LOCAL_SIZE, Slurm's SLURM_NTASKS_PER_NODE), at least 1.
  int threads_per_rank() const;

 private:
  int rank_ = 0, size_ = 1;
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

}  // namespace dda::cli
