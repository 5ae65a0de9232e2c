#pragma once
// The threads a forward run uses. A small model's step is little work cut
// into dozens of parallel loops; a second thread then only adds the cost of
// waking it and of meeting it at the end of every loop, and on a machine
// whose cores are busy with other work each of those meetings can wait for
// a scheduler time slice. Measured in docs/solver2d.md and docs/solver3d.md
// ("Threads for small models").
namespace dda::df {

// A model of fewer blocks than this runs on one thread: the parallel grain
// of the block loops (block_system.hpp), below which they already ran on
// one. What still woke a second thread there (the contact loops, the 3D
// contact search) gained 4 % at best on a quiet machine and cost 1.3-14
// times the run when another program was using a core.
inline constexpr int kOneThreadBelowBlocks = 1000;

// While it lives, the threads of a run of a model of `blocks` blocks: below
// kOneThreadBelowBlocks one for OpenMP and, when the BLAS in use is
// OpenBLAS, one for it too (CHOLMOD's supernodal factorisation calls it);
// from there on both as they were (OMP_NUM_THREADS, else the cores). The
// counts before come back after. A run's result is the same bit for bit on
// one thread or more (tests/df/test_parallel_determinism.cpp).
class RunThreads {
 public:
  explicit RunThreads(int blocks);
  ~RunThreads();
  RunThreads(const RunThreads&) = delete;
  RunThreads& operator=(const RunThreads&) = delete;
  // The OpenMP threads the run uses.
  int threads() const { return threads_; }

 private:
  int threads_ = 1;
  int saved_omp_ = 0;   // 0: left alone
  int saved_blas_ = 0;  // 0: left alone
};

}  // namespace dda::df
