#include "dda/df/core/run_threads.hpp"

#include <dlfcn.h>
#include <omp.h>

namespace dda::df {
namespace {

// OpenBLAS's own thread count, when the BLAS loaded is OpenBLAS (Debian's
// libblas.so.3 may as well be the reference BLAS, which has no threads):
// looked up at run time, so the program links with any BLAS.
using GetThreads = int (*)();
using SetThreads = void (*)(int);

int blas_threads() {
  void* f = dlsym(RTLD_DEFAULT, "openblas_get_num_threads");
  return f ? reinterpret_cast<GetThreads>(f)() : 0;
}

void set_blas_threads(int threads) {
  if (void* f = dlsym(RTLD_DEFAULT, "openblas_set_num_threads")) reinterpret_cast<SetThreads>(f)(threads);
}

}  // namespace

RunThreads::RunThreads(int blocks) {
  if (blocks < kOneThreadBelowBlocks) {
    saved_omp_ = omp_get_max_threads();
    omp_set_num_threads(1);
    saved_blas_ = blas_threads();
    if (saved_blas_ > 1) set_blas_threads(1);
  }
  threads_ = omp_get_max_threads();
}

RunThreads::~RunThreads() {
  if (saved_omp_ > 0) omp_set_num_threads(saved_omp_);
  if (saved_blas_ > 1) set_blas_threads(saved_blas_);
}

}  // namespace dda::df
