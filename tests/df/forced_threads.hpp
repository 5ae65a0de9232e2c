#pragma once
// For the determinism tests: while a ForcedThreads lives, OpenMP runs on
// `threads` threads and DF's parallel loops run in parallel even on a few
// dozen blocks (parallel_grain 1); both are restored when it ends.
#include <omp.h>

#include "dda/df/core/block_system.hpp"

namespace dda::df::testing {

class ForcedThreads {
 public:
  explicit ForcedThreads(int threads) {
    omp_set_num_threads(threads);
    set_parallel_grain(1);
  }
  ForcedThreads(const ForcedThreads&) = delete;
  ForcedThreads& operator=(const ForcedThreads&) = delete;
  ~ForcedThreads() {
    omp_set_num_threads(saved_threads_);
    set_parallel_grain(saved_grain_);
  }

 private:
  int saved_threads_ = omp_get_max_threads();
  int saved_grain_ = parallel_grain();
};

}  // namespace dda::df::testing
