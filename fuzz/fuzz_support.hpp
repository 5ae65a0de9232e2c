#pragma once
// What every fuzz target shares (docs/reliability.md, "Fuzzing").
//
// A reader may refuse an input only with dda's own InputError (the damaged-
// file error h5::DamagedFile is one): that is the one sentence and exit 1 a
// user sees. Anything else that escapes it — std::bad_alloc, an
// out_of_range, an InternalError — and every sanitizer report is a finding,
// so only InputError is caught here.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <fcntl.h>
#include <unistd.h>

#include "dda/common/error.hpp"

namespace dda::fuzz {

// Runs `read` on one input, taking an InputError as the right answer to a
// bad input.
template <class Read>
void refuse_only_with_input_errors(Read&& read) {
  try {
    read();
  } catch (const InputError&) {
  }
}

// The bytes as a string (text readers parse strings).
inline std::string as_text(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

// Writes the bytes to a file of this process and returns its path, for the
// readers that take a path (the file is rewritten for every input). The
// name ends in `suffix` for readers that go by the extension.
// The file is removed when the process ends normally (libFuzzer ends a run
// with exit()).
//
// The old bytes are overwritten in place and the file then cut to the new
// size, never truncated to zero first: ext4 flushes a file to the disk when
// it is closed after such a truncation (its auto_da_alloc), which made every
// input cost a few milliseconds of waiting for the disk (300 inputs a
// second instead of 10,000 for the STL target here).
inline std::string scratch_file(const std::uint8_t* data, std::size_t size, const std::string& suffix) {
  struct RemovedAtExit {
    std::string path;
    ~RemovedAtExit() { std::remove(path.c_str()); }
  };
  const char* tmp = std::getenv("TMPDIR");
  static const RemovedAtExit scratch{std::string(tmp && *tmp ? tmp : "/tmp") + "/dda_fuzz_" +
                                     std::to_string(static_cast<long>(getpid())) + suffix};
  const std::string& path = scratch.path;
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT, 0644);
  bool ok = fd >= 0;
  for (std::size_t done = 0; ok && done < size;) {
    const ssize_t w = ::pwrite(fd, data + done, size - done, static_cast<off_t>(done));
    ok = w > 0;
    done += ok ? static_cast<std::size_t>(w) : 0;
  }
  ok = ok && ::ftruncate(fd, static_cast<off_t>(size)) == 0;
  if (fd >= 0 && ::close(fd) != 0) ok = false;
  if (!ok) {
    std::perror(path.c_str());
    std::abort();  // the machine, not the reader: stop rather than fuzz nothing
  }
  return path;
}

}  // namespace dda::fuzz
