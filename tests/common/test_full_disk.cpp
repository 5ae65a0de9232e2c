// A disk that fills while an HDF5 output is written (docs/reliability.md,
// "Write errors"): one InputError naming the file, no temporary left, and a
// clean exit afterwards. HDF5 1.10 cannot close a file whose flush failed,
// and its exit handler used to crash on it after the error was printed.
//
// A file size limit stands in for the full disk; with SIGXFSZ ignored,
// write() fails with EFBIG as it would with ENOSPC. The limit and the exit
// are the death test's child's alone.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "dda/common/error.hpp"
#include "dda/common/line_model.hpp"
#include "dda/common/model_io.hpp"

namespace fs = std::filesystem;

namespace {

// Writes a lines file of about 700 KiB under an 8 KiB limit; the child
// exits 0 only if that failed with an InputError and left nothing behind.
[[noreturn]] void write_under_a_size_limit(const fs::path& dir) {
  std::signal(SIGXFSZ, SIG_IGN);
  const rlimit limit{8192, 8192};
  setrlimit(RLIMIT_FSIZE, &limit);
  dda::LineModel m;
  for (int i = 0; i < 20000; ++i) m.lines.push_back({dda::Vec2(i, 0), dda::Vec2(i, 1), 0, dda::LineKind::Joint, -1});
  try {
    dda::write_lines_h5((dir / "big.h5").string(), m);
  } catch (const dda::InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    std::size_t left = 0;
    for ([[maybe_unused]] const auto& f : fs::directory_iterator(dir)) ++left;
    std::exit(left == 0 ? 0 : 2);  // runs the exit handlers, as dda does
  }
  std::exit(3);
}

}  // namespace

TEST(FullDisk, Hdf5WriteFailsWithOneSentenceAndExitsCleanly) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const fs::path dir = fs::temp_directory_path() / ("dda-full-disk-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  EXPECT_EXIT(write_under_a_size_limit(dir), ::testing::ExitedWithCode(0),
              "big.h5: cannot write: .*\\(disk full\\?\\)\\.");
  fs::remove_all(dir);
}
