#include "dda/common/memory_policy.hpp"

// A standard header first: it brings in the C library's <features.h>, which
// defines __GLIBC__. Without it the test below was always false and
// keep_freed_memory() compiled to nothing.
#include <cstddef>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace dda {

void keep_freed_memory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);  // glibc's largest allowed value on 64-bit
  mallopt(M_TRIM_THRESHOLD, 1024 * 1024 * 1024);
#endif
}

}  // namespace dda
