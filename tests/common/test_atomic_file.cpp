#include "dda/common/atomic_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "dda/common/error.hpp"

namespace fs = std::filesystem;

namespace {

class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("dda-atomic-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::size_t entries() const {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_)) ++n;
    return n;
  }
  static std::string slurp(const std::string& p) {
    std::ifstream f(p, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
  }

  fs::path dir_;
};

TEST_F(AtomicFileTest, WritesTextAndLeavesNoTemporary) {
  dda::write_text_atomically(path("a.txt"), "hello\n");
  EXPECT_EQ(slurp(path("a.txt")), "hello\n");
  EXPECT_EQ(entries(), 1u);
  dda::write_text_atomically(path("a.txt"), "again");  // replaces
  EXPECT_EQ(slurp(path("a.txt")), "again");
  EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, TemporaryIsHiddenInTheSameFolder) {
  dda::AtomicOutput out(path("b.h5"));
  EXPECT_EQ(fs::path(out.temp_path()).parent_path(), dir_);
  EXPECT_EQ(fs::path(out.temp_path()).filename().string().rfind(".b.h5.tmp-", 0), 0u);
  EXPECT_EQ(out.final_path(), path("b.h5"));
}

TEST_F(AtomicFileTest, UncommittedOutputIsRemovedAndOldFileKept) {
  dda::write_text_atomically(path("c.txt"), "good");
  {
    dda::AtomicOutput out(path("c.txt"));
    std::ofstream(out.temp_path()) << "half";
    EXPECT_TRUE(fs::exists(out.temp_path()));
    // no commit: as if the writer threw half way
  }
  EXPECT_EQ(slurp(path("c.txt")), "good");
  EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, CommitReplacesTheFinalFile) {
  dda::AtomicOutput out(path("d.txt"));
  std::ofstream(out.temp_path()) << "new";
  out.commit();
  EXPECT_EQ(slurp(path("d.txt")), "new");
  EXPECT_FALSE(fs::exists(out.temp_path()));
}

TEST_F(AtomicFileTest, MissingFolderIsAnInputErrorNamingThePath) {
  const std::string p = path("no/such/folder/e.txt");
  try {
    dda::write_text_atomically(p, "x");
    FAIL() << "expected InputError";
  } catch (const dda::InputError& e) {
    EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what();
  }
}

TEST_F(AtomicFileTest, CommitWithoutWritingIsAnInputError) {
  dda::AtomicOutput out(path("f.txt"));
  EXPECT_THROW(out.commit(), dda::InputError);
  EXPECT_FALSE(fs::exists(path("f.txt")));
}

TEST_F(AtomicFileTest, WritingOntoAFolderIsAnInputError) {
  fs::create_directories(dir_ / "sub");
  EXPECT_THROW(dda::write_text_atomically(path("sub"), "x"), dda::InputError);
}

}  // namespace
