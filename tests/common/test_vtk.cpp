#include "dda/common/vtk.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "dda/common/error.hpp"

namespace fs = std::filesystem;
using dda::Vec2;

namespace {

class VtkTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("dda-vtk-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  static std::string slurp(const std::string& p) {
    std::ifstream f(p, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
  }
  fs::path dir_;
};

// Well-formedness by simple means: every start tag is closed by the matching
// end tag in the right order, one root element, quotes balanced in tags.
// Returns "" if fine, else what is wrong.
std::string check_xml(const std::string& xml, std::string* root = nullptr) {
  std::vector<std::string> stack;
  int roots = 0;
  std::size_t i = 0;
  while ((i = xml.find('<', i)) != std::string::npos) {
    const std::size_t end = xml.find('>', i);
    if (end == std::string::npos) return "unterminated tag";
    const std::string tag = xml.substr(i + 1, end - i - 1);
    i = end + 1;
    if (tag.empty()) return "empty tag";
    if (tag.front() == '?') {
      if (tag.back() != '?') return "bad declaration";
      continue;
    }
    if (std::count(tag.begin(), tag.end(), '"') % 2 != 0) return "unbalanced quotes in <" + tag + ">";
    if (tag.front() == '/') {
      const std::string name = tag.substr(1);
      if (stack.empty() || stack.back() != name) return "unexpected </" + name + ">";
      stack.pop_back();
      continue;
    }
    const std::string name = tag.substr(0, tag.find_first_of(" \t\n/"));
    if (stack.empty()) {
      ++roots;
      if (root) *root = name;
    }
    if (tag.back() != '/') stack.push_back(name);
  }
  if (!stack.empty()) return "unclosed <" + stack.back() + ">";
  if (roots != 1) return std::to_string(roots) + " root elements";
  return "";
}

// Text between <DataArray ... Name="name" ...> and </DataArray>, whitespace
// collapsed to single spaces.
std::string array_text(const std::string& xml, const std::string& name) {
  const std::size_t at = xml.find("Name=\"" + name + "\"");
  if (at == std::string::npos) return "<missing>";
  const std::size_t start = xml.find('>', at) + 1;
  const std::size_t stop = xml.find("</DataArray>", start);
  std::istringstream in(xml.substr(start, stop - start));
  std::string word, out;
  while (in >> word) out += (out.empty() ? "" : " ") + word;
  return out;
}

dda::BlockModel two_blocks() {
  dda::BlockModel m;
  dda::Block a;
  a.vertices = {Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(0, 1)};
  a.edge_set = {-1, -1, 0, -1};
  a.area = 2;
  a.layer = 0;
  dda::Block b;
  b.vertices = {Vec2(2, 0), Vec2(3, 0), Vec2(2, 1)};
  b.edge_set = {-1, -1, 0};
  b.area = 0.5;
  b.layer = 1;
  m.blocks = {a, b};
  return m;
}

TEST_F(VtkTest, BlocksAsPolygons) {
  dda::write_blocks_vtu(path("b.vtu"), two_blocks());
  const std::string xml = slurp(path("b.vtu"));
  std::string root;
  EXPECT_EQ(check_xml(xml, &root), "");
  EXPECT_EQ(root, "VTKFile");
  EXPECT_NE(xml.find("type=\"UnstructuredGrid\""), std::string::npos);
  EXPECT_NE(xml.find("NumberOfPoints=\"7\" NumberOfCells=\"2\""), std::string::npos);
  EXPECT_EQ(array_text(xml, "Points"), "0 0 0 2 0 0 2 1 0 0 1 0 2 0 0 3 0 0 2 1 0");
  EXPECT_EQ(array_text(xml, "connectivity"), "0 1 2 3 4 5 6");
  EXPECT_EQ(array_text(xml, "offsets"), "4 7");
  EXPECT_EQ(array_text(xml, "types"), "7 7");
  EXPECT_EQ(array_text(xml, "block_id"), "0 1");
  EXPECT_EQ(array_text(xml, "area"), "2 0.5");
  EXPECT_EQ(array_text(xml, "layer"), "0 1");
  EXPECT_EQ(xml.find("<PointData"), std::string::npos);
}

TEST_F(VtkTest, LinesWithOutlines) {
  dda::LineModel m;
  m.domain = {Vec2(0, 0), Vec2(4, 0), Vec2(4, 3)};
  m.lines = {{Vec2(0.5, 0.25), Vec2(3, 2), 1, dda::LineKind::Joint, 2},
             {Vec2(0, 1), Vec2(4, 1), 0, dda::LineKind::Bedding, -1}};
  dda::write_lines_vtu(path("l.vtu"), m);
  const std::string xml = slurp(path("l.vtu"));
  EXPECT_EQ(check_xml(xml), "");
  // 2 lines + 3 domain edges, 2 points each.
  EXPECT_NE(xml.find("NumberOfPoints=\"10\" NumberOfCells=\"5\""), std::string::npos);
  EXPECT_EQ(array_text(xml, "connectivity"), "0 1 2 3 4 5 6 7 8 9");
  EXPECT_EQ(array_text(xml, "offsets"), "2 4 6 8 10");
  EXPECT_EQ(array_text(xml, "types"), "3 3 3 3 3");
  EXPECT_EQ(array_text(xml, "set"), "1 0 -1 -1 -1");
  EXPECT_EQ(array_text(xml, "kind"), "0 1 2 2 2");
  EXPECT_EQ(array_text(xml, "layer"), "2 -1 -1 -1 -1");
  EXPECT_EQ(array_text(xml, "Points").substr(0, 18), "0.5 0.25 0 3 2 0 0");
}

TEST_F(VtkTest, EmptyModelsAreValid) {
  dda::write_blocks_vtu(path("b.vtu"), dda::BlockModel{});
  dda::write_lines_vtu(path("l.vtu"), dda::LineModel{});
  for (const char* f : {"b.vtu", "l.vtu"}) {
    const std::string xml = slurp(path(f));
    EXPECT_EQ(check_xml(xml), "") << f;
    EXPECT_NE(xml.find("NumberOfPoints=\"0\" NumberOfCells=\"0\""), std::string::npos) << f;
  }
}

TEST_F(VtkTest, DoublesSurviveTheText) {
  dda::BlockModel m;
  dda::Block a;
  a.vertices = {Vec2(0.1, 1.0 / 3.0), Vec2(1e6 + 0.123456789, 0), Vec2(0, 2.5e-9)};
  a.edge_set = {0, 0, 0};
  m.blocks = {a};
  dda::write_blocks_vtu(path("b.vtu"), m);
  std::istringstream in(array_text(slurp(path("b.vtu")), "Points"));
  double x[9];
  for (double& v : x) in >> v;
  EXPECT_EQ(x[0], 0.1);
  EXPECT_EQ(x[1], 1.0 / 3.0);
  EXPECT_EQ(x[3], 1e6 + 0.123456789);
  EXPECT_EQ(x[7], 2.5e-9);
}

TEST_F(VtkTest, PvdCollection) {
  dda::write_pvd(path("run.pvd"), {{"run/step_0000.vtu", 0.0, 0, "blocks"},
                                   {"run/step_0001.vtu", 0.25, 0, "blocks"},
                                   {"run/contacts \"A&B\".vtu", 0.25, 1, ""}});
  const std::string xml = slurp(path("run.pvd"));
  std::string root;
  EXPECT_EQ(check_xml(xml, &root), "");
  EXPECT_EQ(root, "VTKFile");
  EXPECT_NE(xml.find("type=\"Collection\""), std::string::npos);
  EXPECT_NE(xml.find("<DataSet timestep=\"0.25\" group=\"\" part=\"0\" file=\"run/step_0001.vtu\" "
                     "name=\"blocks\"/>"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("file=\"run/contacts &quot;A&amp;B&quot;.vtu\""), std::string::npos);
  std::size_t n = 0;
  for (std::size_t at = 0; (at = xml.find("<DataSet ", at)) != std::string::npos; ++at) ++n;
  EXPECT_EQ(n, 3u);
}

TEST_F(VtkTest, MissingFolderIsAnInputError) {
  EXPECT_THROW(dda::write_blocks_vtu(path("no/b.vtu"), two_blocks()), dda::InputError);
  EXPECT_THROW(dda::write_pvd(path("no/r.pvd"), {}), dda::InputError);
}

}  // namespace
