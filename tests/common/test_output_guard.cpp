// Outputs never overwrite inputs (docs/reliability.md): the same file under
// any name it has is refused, with one sentence naming both paths.
#include "dda/common/output_guard.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "dda/common/error.hpp"

namespace fs = std::filesystem;
using dda::refuse_overwriting_inputs;

namespace {

class OutputGuardTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("dda-guard-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "sub");
    std::ofstream(path("s.yaml")) << "name: a\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  template <class F>
  static std::string error_of(F&& f) {
    try {
      f();
    } catch (const dda::InputError& e) {
      return e.what();
    }
    return "";
  }

  fs::path dir_;
};

}  // namespace

TEST_F(OutputGuardTest, TheInputItselfIsRefusedNamingBothPaths) {
  const std::string s = path("s.yaml");
  EXPECT_EQ(error_of([&] { refuse_overwriting_inputs({s}, {s}); }),
            s + ": will not write the output over the input " + s + "; choose another output name.");
}

TEST_F(OutputGuardTest, AnotherSpellingOfTheSamePathIsRefused) {
  const std::string s = path("s.yaml"), other = path("sub/../s.yaml");
  EXPECT_EQ(error_of([&] { refuse_overwriting_inputs({s}, {other}); }),
            other + ": will not write the output over the input " + s +
                " (they are the same file); choose another output name.");
}

TEST_F(OutputGuardTest, SymlinkAndHardLinkToTheInputAreRefused) {
  fs::create_symlink(path("s.yaml"), path("soft.yaml"));
  fs::create_hard_link(path("s.yaml"), path("sub/hard.yaml"));
  EXPECT_NE(error_of([&] { refuse_overwriting_inputs({path("s.yaml")}, {path("soft.yaml")}); }), "");
  EXPECT_NE(error_of([&] { refuse_overwriting_inputs({path("soft.yaml")}, {path("s.yaml")}); }), "");
  EXPECT_NE(error_of([&] { refuse_overwriting_inputs({path("s.yaml")}, {path("sub/hard.yaml")}); }), "");
}

TEST_F(OutputGuardTest, OtherFilesAndEmptyNamesPass) {
  EXPECT_NO_THROW(refuse_overwriting_inputs({path("s.yaml"), ""}, {path("l.h5"), "", path("sub/s.yaml")}));
  std::ofstream(path("copy.yaml")) << "name: a\n";  // equal content is not the same file
  EXPECT_NO_THROW(refuse_overwriting_inputs({path("s.yaml")}, {path("copy.yaml")}));
}

TEST_F(OutputGuardTest, AnInputInsideAnOutputFolderIsRefused) {
  std::ofstream(path("sub/t.yaml")) << "name: a\n";
  EXPECT_EQ(error_of([&] { refuse_overwriting_inputs({path("sub/t.yaml")}, {}, {path("sub")}); }),
            path("sub") + ": will not write into this output folder, it holds the input " + path("sub/t.yaml") +
                "; choose another output folder.");
  EXPECT_NO_THROW(refuse_overwriting_inputs({path("s.yaml")}, {}, {path("sub")}));
}
