// A committed output is on the disk (docs/reliability.md, "Durable writes"):
// the temporary file is synced before the rename and its folder after it,
// for text and HDF5 outputs alike.
//
// This program's own fsync() stands in for the C library's (the static
// dda_common code links to it), notes which file each call reached, and
// then does the real system call.
#include <gtest/gtest.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "dda/common/atomic_file.hpp"
#include "dda/common/line_model.hpp"
#include "dda/common/model_io.hpp"

namespace fs = std::filesystem;

namespace {
std::vector<std::string>* g_synced = nullptr;  // set while a test listens
}  // namespace

extern "C" int fsync(int fd) {
  if (g_synced) {
    char target[4096];
    const std::string link = "/proc/self/fd/" + std::to_string(fd);
    const ssize_t n = ::readlink(link.c_str(), target, sizeof target - 1);
    g_synced->push_back(n > 0 ? std::string(target, static_cast<std::size_t>(n)) : "?");
  }
  return static_cast<int>(::syscall(SYS_fsync, fd));
}

namespace {

class DurableWriteTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("dda-durable-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    dir_ = fs::canonical(dir_);  // /proc names the real path
    g_synced = &synced_;
  }
  void TearDown() override {
    g_synced = nullptr;
    fs::remove_all(dir_);
  }

  // The file (under its temporary name, so before the rename), then the
  // folder, last. Other calls may come first (a library's own syncs).
  void expect_file_then_folder(const std::string& name) const {
    ASSERT_GE(synced_.size(), 2u) << "expected the file and its folder to be synced";
    const std::string& file = synced_[synced_.size() - 2];
    EXPECT_EQ(file.rfind((dir_ / ("." + name + ".tmp-")).string(), 0), 0u) << file;
    EXPECT_EQ(synced_.back(), dir_.string());
    EXPECT_TRUE(fs::exists(dir_ / name));
  }

  fs::path dir_;
  std::vector<std::string> synced_;
};

}  // namespace

TEST_F(DurableWriteTest, TextFileIsSyncedBeforeTheRenameAndItsFolderAfter) {
  dda::write_text_atomically((dir_ / "a.txt").string(), "hello\n");
  expect_file_then_folder("a.txt");
}

TEST_F(DurableWriteTest, Hdf5FileIsSyncedBeforeTheRenameAndItsFolderAfter) {
  dda::write_lines_h5((dir_ / "lines.h5").string(), dda::LineModel{});
  expect_file_then_folder("lines.h5");
}
