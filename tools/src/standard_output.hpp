#pragma once
// Whether everything the command printed reached the standard output.
//
// Output to a full disk or a closed pipe fails only when a buffer is
// written, often at exit, where nobody checked: `dda stats b.h5 --json >
// /dev/full` used to exit 0 with nothing written. And the C library forgets
// why a write failed (it drops the buffer and errno moves on), so the
// reason is kept where the write happens (docs/reliability.md).
#include <optional>
#include <string>

namespace dda::cli {

// Gives std::cout a buffer of its own that writes to file descriptor 1 and
// remembers the first failure. Call once, first thing in main().
void watch_standard_output();

// Flushes std::cout (and stdout, for anything written through stdio); the
// reason ("No space left on device") if a write to the standard output
// failed at any time, else nothing.
std::optional<std::string> standard_output_failure();

}  // namespace dda::cli
