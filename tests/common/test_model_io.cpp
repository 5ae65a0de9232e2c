#include "dda/common/model_io.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <sys/wait.h>

#include "dda/common/error.hpp"
#include "scratch_dir_test.hpp"

namespace fs = std::filesystem;
using dda::Vec2;

namespace {

class ModelIoTest : public dda::testing::ScratchDirTest {
 protected:
  ModelIoTest() : ScratchDirTest("dda-model-io") {}
  static std::string slurp(const std::string& p) {
    std::ifstream f(p, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
  }
};

dda::Provenance sample_provenance() {
  dda::Provenance p;
  p.program_version = "9.8.7-test";
  p.scenario_path = "examples/tunnel/scenario.yaml";
  p.scenario_text = "# Tunnel — Überdeckung 30 m\nseed: 42\ndomain:\n  box: [0, 0, 50, 30]\n";
  p.seed = 18446744073709551557ULL;  // above 2^63: must survive as unsigned
  p.created_utc = "2024-05-06T07:08:09Z";
  return p;
}

dda::LineModel sample_lines() {
  dda::LineModel m;
  m.domain = {Vec2(0, 0), Vec2(50, 0), Vec2(50, 30), Vec2(0, 30)};
  m.excavations = {{Vec2(20, 10), Vec2(30, 10), Vec2(30, 15), Vec2(25, 17.5), Vec2(20, 15)},
                   {Vec2(1, 1), Vec2(2, 1), Vec2(1.5, 2)}};
  m.sets = {{"Schichtfläche", "bedding"}, {"節理 J1", "layered"}, {"user", "user"}};
  m.lines = {{Vec2(0, 10), Vec2(50, 10), 0, dda::LineKind::Bedding, -1},
             {Vec2(3.25, 0), Vec2(3.5, 10), 1, dda::LineKind::Joint, 0},
             {Vec2(7.0 / 3.0, 10), Vec2(1e-300, 20), 1, dda::LineKind::Joint, 1},
             {Vec2(40, 1), Vec2(45, 29), 2, dda::LineKind::Joint, -1}};
  m.points = {{"fix-1", dda::PointKind::Fixed, Vec2(0.5, 0.5)},
              {"Last ↓", dda::PointKind::Load, Vec2(10, 29)},
              {"M1", dda::PointKind::Measurement, Vec2(25, 18)},
              {"hole", dda::PointKind::Hole, Vec2(25, 12)}};
  m.layers = {{0, 10, 1.5, 1.25}, {10, 30, 0, 2.5}};
  m.bedding_dip_deg = 12.5;
  m.provenance = sample_provenance();
  return m;
}

dda::BlockModel sample_blocks() {
  dda::BlockModel m;
  dda::Block a;
  a.vertices = {Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(0, 1)};
  a.edge_set = {-1, 0, 1, -1};
  a.area = 2;
  a.centroid = Vec2(1, 0.5);
  a.sxx = 2.0 / 3.0;
  a.syy = 1.0 / 6.0;
  a.sxy = 0;
  a.layer = 0;
  dda::Block b;
  b.vertices = {Vec2(2, 0), Vec2(3, 0), Vec2(2.5, 1)};
  b.edge_set = {-1, -3, 0};
  b.area = 0.5;
  b.centroid = Vec2(2.5, 1.0 / 3.0);
  b.sxx = 0.01;
  b.syy = 0.02;
  b.sxy = -0.003;
  b.layer = 1;
  dda::Block c;
  c.vertices = {Vec2(0, 1), Vec2(2, 1), Vec2(2, 3), Vec2(1, 3.5), Vec2(0, 3)};
  c.edge_set = {1, -2, -2, -2, -1};
  c.area = 4.5;
  c.centroid = Vec2(1, 2.1);
  c.layer = -1;
  m.blocks = {a, b, c};
  m.sets = {{"Schichtfläche", "bedding"}, {"節理", "statistical"}};
  m.points = {{{"M1 Ω", dda::PointKind::Measurement, Vec2(1, 0.5)}, 0},
              {{"outside", dda::PointKind::Fixed, Vec2(9, 9)}, -1},
              {{"L", dda::PointKind::Load, Vec2(2.5, 0.2)}, 1}};
  m.layers = {{0, 1, 2, 2.5}, {1, 4, 0, 0}};
  m.bedding_dip_deg = 90;
  m.domain_area = 12.25;
  m.excavated_area = 0.75;
  m.provenance = sample_provenance();
  return m;
}

void expect_same(const dda::Provenance& a, const dda::Provenance& b) {
  EXPECT_EQ(a.program_version, b.program_version);
  EXPECT_EQ(a.scenario_path, b.scenario_path);
  EXPECT_EQ(a.scenario_text, b.scenario_text);
  EXPECT_EQ(a.seed, b.seed);
  EXPECT_EQ(a.created_utc, b.created_utc);
}

void expect_same(const std::vector<dda::JointSetInfo>& a, const std::vector<dda::JointSetInfo>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].name, b[i].name);
    EXPECT_EQ(a[i].origin, b[i].origin);
  }
}

void expect_same(const std::vector<dda::Layer>& a, const std::vector<dda::Layer>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].bottom, b[i].bottom);
    EXPECT_EQ(a[i].top, b[i].top);
    EXPECT_EQ(a[i].target_fsi, b[i].target_fsi);
    EXPECT_EQ(a[i].realised_fsi, b[i].realised_fsi);
  }
}

void expect_same(const dda::ModelPoint& a, const dda::ModelPoint& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.kind, b.kind);
  EXPECT_EQ(a.p, b.p);
}

void expect_same(const dda::LineModel& a, const dda::LineModel& b) {
  EXPECT_EQ(a.domain, b.domain);
  EXPECT_EQ(a.excavations, b.excavations);
  ASSERT_EQ(a.lines.size(), b.lines.size());
  for (std::size_t i = 0; i < a.lines.size(); ++i) {
    EXPECT_EQ(a.lines[i].a, b.lines[i].a);  // bit for bit: float64 on disk
    EXPECT_EQ(a.lines[i].b, b.lines[i].b);
    EXPECT_EQ(a.lines[i].set, b.lines[i].set);
    EXPECT_EQ(a.lines[i].kind, b.lines[i].kind);
    EXPECT_EQ(a.lines[i].layer, b.lines[i].layer);
  }
  expect_same(a.sets, b.sets);
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) expect_same(a.points[i], b.points[i]);
  expect_same(a.layers, b.layers);
  EXPECT_EQ(a.bedding_dip_deg, b.bedding_dip_deg);
  expect_same(a.provenance, b.provenance);
}

void expect_same(const dda::BlockModel& a, const dda::BlockModel& b) {
  ASSERT_EQ(a.blocks.size(), b.blocks.size());
  for (std::size_t i = 0; i < a.blocks.size(); ++i) {
    const dda::Block &x = a.blocks[i], &y = b.blocks[i];
    EXPECT_EQ(x.vertices, y.vertices);
    EXPECT_EQ(x.edge_set, y.edge_set);
    EXPECT_EQ(x.area, y.area);
    EXPECT_EQ(x.centroid, y.centroid);
    EXPECT_EQ(x.sxx, y.sxx);
    EXPECT_EQ(x.syy, y.syy);
    EXPECT_EQ(x.sxy, y.sxy);
    EXPECT_EQ(x.layer, y.layer);
  }
  expect_same(a.sets, b.sets);
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    expect_same(a.points[i].point, b.points[i].point);
    EXPECT_EQ(a.points[i].block, b.points[i].block);
  }
  expect_same(a.layers, b.layers);
  EXPECT_EQ(a.bedding_dip_deg, b.bedding_dip_deg);
  EXPECT_EQ(a.domain_area, b.domain_area);
  EXPECT_EQ(a.excavated_area, b.excavated_area);
  expect_same(a.provenance, b.provenance);
}

// --------------------------------------------------------------- round trips

TEST_F(ModelIoTest, LinesRoundTripAllFields) {
  const dda::LineModel m = sample_lines();
  dda::write_lines_h5(path("lines.h5"), m);
  expect_same(m, dda::read_lines_h5(path("lines.h5")));
  EXPECT_EQ(dda::h5_format_of(path("lines.h5")), "dda-lines");
  EXPECT_EQ(listing(), std::vector<std::string>{"lines.h5"});  // no temporary left
}

TEST_F(ModelIoTest, EmptyLineModelRoundTrips) {
  dda::LineModel m;  // no domain, no excavations, no lines, points, sets, layers
  m.provenance.created_utc = "2000-01-01T00:00:00Z";
  m.provenance.program_version = "x";
  dda::write_lines_h5(path("empty.h5"), m);
  expect_same(m, dda::read_lines_h5(path("empty.h5")));
}

TEST_F(ModelIoTest, BlocksRoundTripAllFields) {
  const dda::BlockModel m = sample_blocks();
  dda::write_blocks_h5(path("blocks.h5"), m);
  expect_same(m, dda::read_blocks_h5(path("blocks.h5")));
  EXPECT_EQ(dda::h5_format_of(path("blocks.h5")), "dda-blocks");
}

TEST_F(ModelIoTest, EmptyBlockModelRoundTrips) {
  dda::BlockModel m;
  m.provenance.created_utc = "2000-01-01T00:00:00Z";
  m.provenance.program_version = "x";
  dda::write_blocks_h5(path("empty.h5"), m);
  expect_same(m, dda::read_blocks_h5(path("empty.h5")));
}

TEST_F(ModelIoTest, WriterFillsVersionAndCreationTime) {
  dda::LineModel m;  // provenance left empty
  dda::write_lines_h5(path("l.h5"), m);
  const dda::Provenance p = dda::read_lines_h5(path("l.h5")).provenance;
  EXPECT_EQ(p.program_version, dda::version_string());
  EXPECT_TRUE(std::regex_match(p.created_utc, std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")))
      << p.created_utc;
}

TEST_F(ModelIoTest, SelfDescribingAttributesAreInTheFile) {
  // Without HDF5 headers in the tests, look for the attribute names and the
  // variable-length text values in the raw bytes.
  dda::write_blocks_h5(path("b.h5"), sample_blocks());
  const std::string bytes = slurp(path("b.h5"));
  for (const char* s : {"format", "format_version", "units", "program_version", "scenario_path",
                        "scenario", "seed", "created_utc", "dda-blocks", "9.8.7-test",
                        "Überdeckung 30 m", "second_moments", "description"})
    EXPECT_NE(bytes.find(s), std::string::npos) << s;
}

TEST_F(ModelIoTest, LongScenarioTextFits) {
  dda::LineModel m;
  m.provenance.scenario_text = std::string(300000, 'x') + "\nend\n";  // > 64 KiB header limit
  dda::write_lines_h5(path("l.h5"), m);
  EXPECT_EQ(dda::read_lines_h5(path("l.h5")).provenance.scenario_text, m.provenance.scenario_text);
}

// ------------------------------------------------------------------- errors

TEST_F(ModelIoTest, WrongFormatNamesBothFormats) {
  dda::write_blocks_h5(path("blocks.h5"), sample_blocks());
  EXPECT_EQ(error_of([&] { dda::read_lines_h5(path("blocks.h5")); }),
            path("blocks.h5") + ": is a dda-blocks file, expected a dda-lines file.");
  dda::write_lines_h5(path("lines.h5"), sample_lines());
  EXPECT_EQ(error_of([&] { dda::read_blocks_h5(path("lines.h5")); }),
            path("lines.h5") + ": is a dda-lines file, expected a dda-blocks file.");
}

TEST_F(ModelIoTest, MissingFileIsNamed) {
  const std::string msg = error_of([&] { dda::read_lines_h5(path("nope.h5")); });
  EXPECT_EQ(msg, path("nope.h5") + ": file not found.");
  EXPECT_THROW(dda::h5_format_of(path("nope.h5")), dda::InputError);
}

TEST_F(ModelIoTest, GarbageFileIsNamed) {
  std::ofstream(path("junk.h5"), std::ios::binary) << "this is not HDF5\x01\x02\x03 at all";
  const std::string msg = error_of([&] { dda::read_blocks_h5(path("junk.h5")); });
  EXPECT_EQ(msg, path("junk.h5") + ": is not an HDF5 file.");
  EXPECT_EQ(dda::h5_format_of(path("junk.h5")), "");
}

TEST_F(ModelIoTest, TruncatedFileIsNamed) {
  dda::write_blocks_h5(path("good.h5"), sample_blocks());
  const std::string bytes = slurp(path("good.h5"));
  std::ofstream(path("cut.h5"), std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  const std::string msg = error_of([&] { dda::read_blocks_h5(path("cut.h5")); });
  EXPECT_EQ(msg.rfind(path("cut.h5") + ": ", 0), 0u) << msg;
}

TEST_F(ModelIoTest, FolderIsNotAFile) {
  fs::create_directories(dir_ / "d.h5");
  EXPECT_EQ(error_of([&] { dda::read_lines_h5(path("d.h5")); }),
            path("d.h5") + ": is a folder, not a file.");
}

TEST_F(ModelIoTest, OutOfRangeIndexIsNamed) {
  dda::LineModel m = sample_lines();
  m.lines[1].set = 7;  // only 3 sets
  dda::write_lines_h5(path("l.h5"), m);
  const std::string msg = error_of([&] { dda::read_lines_h5(path("l.h5")); });
  EXPECT_EQ(msg.rfind(path("l.h5") + ": dataset /lines/set entry 1 is 7", 0), 0u) << msg;
}

TEST_F(ModelIoTest, WriteIntoMissingFolderIsAnInputError) {
  const std::string p = path("missing/out.h5");
  const std::string msg = error_of([&] { dda::write_lines_h5(p, sample_lines()); });
  EXPECT_NE(msg.find(p), std::string::npos) << msg;
}

TEST_F(ModelIoTest, FailedWriteKeepsTheOldFileAndLeavesNoTemporary) {
  dda::write_blocks_h5(path("b.h5"), sample_blocks());
  const std::string before = slurp(path("b.h5"));
  dda::BlockModel bad = sample_blocks();
  bad.blocks[2].edge_set.pop_back();  // inconsistent: detected half way through the write
  EXPECT_THROW(dda::write_blocks_h5(path("b.h5"), bad), dda::InternalError);
  EXPECT_EQ(slurp(path("b.h5")), before);
  EXPECT_EQ(listing(), std::vector<std::string>{"b.h5"});
  expect_same(sample_blocks(), dda::read_blocks_h5(path("b.h5")));
}

// Files made by another HDF5 writer (h5py): fixed-length strings, broken
// shapes and offsets. Skipped when /usr/bin/python3 with h5py is not there.
class ForeignFileTest : public ModelIoTest {
 protected:
  bool run_python(const std::string& code) {
    if (std::system("/usr/bin/python3 -c 'import h5py' >/dev/null 2>&1") != 0) return false;
    const std::string script = path("make.py");
    std::ofstream(script) << code;
    return std::system(("/usr/bin/python3 " + script + " " + dir_.string()).c_str()) == 0;
  }
};

const char* kMakeBlocks = R"PY(
import sys, h5py, numpy as np
d = sys.argv[1]
def make(name, offsets=(0, 3, 7), verts=7, areas=2, fixed=False):
    with h5py.File(d + '/' + name, 'w') as f:
        f.attrs['format'] = np.bytes_(b'dda-blocks') if fixed else 'dda-blocks'
        f.attrs['format_version'] = np.int64(1)
        f.attrs['seed'] = np.int32(5)
        b = f.create_group('blocks')
        b['vertices'] = np.arange(2 * verts, dtype=float).reshape(verts, 2)
        b['offsets'] = np.array(offsets, dtype=np.int64)
        b['edge_set'] = np.full(verts, -1, dtype=np.int32)
        b['area'] = np.ones(areas)
        b['centroid'] = np.zeros((2, 2))
        b['second_moments'] = np.zeros((2, 3))
        b['layer'] = np.full(2, -1, dtype=np.int16)
        if fixed:
            s = f.create_group('sets')
            s['name'] = np.array([b'a', b'bb'], dtype='S2')
            s['origin'] = np.array([b'user', b'csv'], dtype='S4')
make('ok.h5')
make('fixed.h5', fixed=True)
make('offsets.h5', offsets=(0, 5, 4))
make('end.h5', offsets=(0, 3, 6))
make('area.h5', areas=3)
)PY";

TEST_F(ForeignFileTest, ShapesAndOffsetsAreChecked) {
  if (!run_python(kMakeBlocks)) GTEST_SKIP() << "/usr/bin/python3 with h5py not available";
  const dda::BlockModel ok = dda::read_blocks_h5(path("ok.h5"));
  ASSERT_EQ(ok.blocks.size(), 2u);
  EXPECT_EQ(ok.blocks[1].vertices.size(), 4u);
  EXPECT_EQ(ok.blocks[1].vertices[0], Vec2(6, 7));
  EXPECT_EQ(ok.provenance.seed, 5u);
  EXPECT_TRUE(ok.sets.empty());  // absent group = empty collection
  EXPECT_TRUE(ok.points.empty());

  const dda::BlockModel fixed = dda::read_blocks_h5(path("fixed.h5"));
  ASSERT_EQ(fixed.sets.size(), 2u);
  EXPECT_EQ(fixed.sets[1].name, "bb");
  EXPECT_EQ(fixed.sets[0].origin, "user");

  std::string msg = error_of([&] { dda::read_blocks_h5(path("offsets.h5")); });
  EXPECT_EQ(msg.rfind(path("offsets.h5") + ": dataset /blocks/offsets", 0), 0u) << msg;
  msg = error_of([&] { dda::read_blocks_h5(path("end.h5")); });
  EXPECT_EQ(msg, path("end.h5") +
                     ": dataset /blocks/offsets must end at 7, found 6.");
  msg = error_of([&] { dda::read_blocks_h5(path("area.h5")); });
  EXPECT_EQ(msg, path("area.h5") + ": dataset /blocks/area has shape (3,), expected (2,), one value per block.");
}

}  // namespace

namespace {

// Smoke test of tools/plot/dda_plot.py on files written by this library: it
// reads both formats, draws maps and histograms, and refuses a file that is
// not ours with exit status 2. Skipped without /usr/bin/python3 + h5py +
// matplotlib.
TEST_F(ModelIoTest, PlotScriptReadsOurFiles) {
  if (std::system("MPLBACKEND=Agg /usr/bin/python3 -c 'import h5py, matplotlib' >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "/usr/bin/python3 with h5py and matplotlib not available";
  dda::write_lines_h5(path("l.h5"), sample_lines());
  dda::write_blocks_h5(path("b.h5"), sample_blocks());
  std::ofstream(path("junk.h5")) << "junk";
  const std::string script = std::string(DDA_SOURCE_DIR) + "/tools/plot/dda_plot.py";
  auto run = [&](const std::string& args) {
    const int status = std::system(("MPLBACKEND=Agg /usr/bin/python3 " + script + " " + args +
                                    " 2>" + path("err.txt"))
                                       .c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  EXPECT_EQ(run(path("l.h5") + " " + path("b.h5") + " -o " + path("map.png")), 0);
  EXPECT_EQ(run(path("b.h5") + " " + path("b.h5") + " --kind histograms --labels A B -o " +
                path("h.svg")),
            0);
  EXPECT_GT(fs::file_size(path("map.png")), 1000u);
  EXPECT_NE(slurp(path("h.svg")).find("<svg"), std::string::npos);
  EXPECT_EQ(run(path("junk.h5") + " -o " + path("x.png")), 2);
  EXPECT_EQ(slurp(path("err.txt")), "dda_plot.py: " + path("junk.h5") + ": is not an HDF5 file.\n");
  EXPECT_FALSE(fs::exists(path("x.png")));
}

}  // namespace
