// Outputs never overwrite inputs (docs/reliability.md): the same file under
// any name it has is refused, with one sentence naming both paths.
#include "dda/common/output_guard.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "dda/common/error.hpp"
#include "scratch_dir_test.hpp"

namespace fs = std::filesystem;
using dda::refuse_overwriting_inputs;

namespace {

class OutputGuardTest : public dda::testing::ScratchDirTest {
 protected:
  OutputGuardTest() : ScratchDirTest("dda-guard") {}
  void SetUp() override {
    ScratchDirTest::SetUp();
    std::filesystem::create_directories(dir_ / "sub");
    std::ofstream(path("s.yaml")) << "name: a\n";
  }
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
