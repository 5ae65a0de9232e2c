// Text inputs read with limits (text_input.hpp, docs/reliability.md
// "Bounded reads"): a file without line ends, or with a line of more than
// 1 MiB, is refused in one sentence naming the file and the line, and
// /dev/zero ends instead of being read for ever.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "dda/common/error.hpp"
#include "dda/common/text_input.hpp"
#include "scratch_dir_test.hpp"

namespace {

class TextInputTest : public dda::testing::ScratchDirTest {
 protected:
  TextInputTest() : ScratchDirTest("dda-text-input") {}
};

TEST_F(TextInputTest, LinesAsGetlineWithoutTheirEnds) {
  std::istringstream in("a,b\r\n\nlast");
  std::string line;
  std::size_t n = 0;
  std::vector<std::string> lines;
  while (dda::read_text_line(in, line, "t.csv", ++n)) lines.push_back(line);
  EXPECT_EQ(lines, (std::vector<std::string>{"a,b", "", "last"}));
  std::istringstream empty("");
  EXPECT_FALSE(dda::read_text_line(empty, line, "t.csv", 1));
}

TEST_F(TextInputTest, ALineOverOneMebibyteIsNotText) {
  std::istringstream in("x\n" + std::string(dda::kMaxTextLineBytes + 1, 'y') + "\n");
  std::string line;
  EXPECT_TRUE(dda::read_text_line(in, line, "t.csv", 1));
  EXPECT_EQ(error_of([&] { dda::read_text_line(in, line, "t.csv", 2); }),
            "t.csv:2: is longer than 1 MiB, so this is not a text file.");
  // A line of exactly the limit is still a line.
  std::istringstream at("x" + std::string(dda::kMaxTextLineBytes - 1, 'y'));
  EXPECT_TRUE(dda::read_text_line(at, line, "t.csv", 1));
  EXPECT_EQ(line.size(), dda::kMaxTextLineBytes);
}

TEST_F(TextInputTest, WholeFileAndItsLimits) {
  std::ofstream(path("r.csv")) << "t,a\n0,1\n";
  EXPECT_EQ(dda::read_text_file(path("r.csv"), "record"), "t,a\n0,1\n");
  EXPECT_EQ(error_of([&] { dda::read_text_file(path("none.csv"), "record"); }),
            path("none.csv") + ": cannot open the record file.");
  // /dev/zero: no line end and no end; refused after 1 MiB, at its line 1.
  EXPECT_EQ(error_of([&] { dda::read_text_file("/dev/zero", "trace"); }),
            "/dev/zero:1: is longer than 1 MiB, so this is not a trace file.");
  // Lines of text, then one that never ends: its number is said.
  std::ofstream(path("long.csv")) << "x1,y1,x2,y2\n0,0,1,1\n" << std::string(dda::kMaxTextLineBytes + 10, '7');
  EXPECT_EQ(error_of([&] { dda::read_text_file(path("long.csv"), "trace"); }),
            path("long.csv") + ":3: is longer than 1 MiB, so this is not a trace file.");
}

TEST_F(TextInputTest, AFileThatMayBeBinaryHasTheSizeLimitOnly) {
  // A binary STL may hold no byte 0x0A for megabytes (normals 0, 0, 1 and
  // whole-number coordinates): it is no text, and must still be read.
  const std::string data(2 * dda::kMaxTextLineBytes, '\x3f');
  std::ofstream(path("box.stl"), std::ios::binary) << data;
  EXPECT_EQ(dda::read_input_file(path("box.stl"), "STL surface"), data);
  EXPECT_NE(error_of([&] { dda::read_text_file(path("box.stl"), "STL surface"); }), "");
}

}  // namespace
