// Damaged HDF5 files (docs/reliability.md, "Damaged files"): what the writer
// puts in every file so that damage is detected (Fletcher-32 on every
// dataset, fixed-length text), and what the reader refuses before it
// allocates or indexes (offsets beyond the vertices, counts beyond the file).
// Files written before the checksums (contiguous, variable-length text)
// must still be read.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "dda/common/error.hpp"
#include "dda/common/model_io.hpp"
#include "scratch_dir_test.hpp"

namespace fs = std::filesystem;

namespace {

// Two unit squares side by side, split by one joint (set 0).
dda::BlockModel two_blocks() {
  dda::BlockModel m;
  m.sets = {{"J1", "user"}};
  for (int i = 0; i < 2; ++i) {
    dda::Block b;
    const double x = i;
    b.vertices = {{x, 0}, {x + 1, 0}, {x + 1, 1}, {x, 1}};
    b.edge_set = {-1, i == 0 ? 0 : -1, -1, i == 0 ? -1 : 0};
    b.area = 1;
    b.centroid = {x + 0.5, 0.5};
    b.sxx = b.syy = 1.0 / 12;
    m.blocks.push_back(b);
  }
  m.domain_area = 2;
  m.provenance.scenario_text = "name: two\n";
  return m;
}

class H5Damage : public dda::testing::ScratchDirTest {
 protected:
  H5Damage() : ScratchDirTest("dda-h5-damage") {}
  void SetUp() override {
    ScratchDirTest::SetUp();
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
};

// Every object of a file, visited: datasets and their filters, attributes
// and their text types.
struct FileSurvey {
  int datasets = 0, checksummed = 0, empty = 0;
  std::vector<std::string> variable_length;  // objects or attributes with variable-length text
};

herr_t survey_attr(hid_t loc, const char* name, const H5A_info_t*, void* data) {
  auto& s = *static_cast<FileSurvey*>(data);
  const hid_t a = H5Aopen(loc, name, H5P_DEFAULT);
  const hid_t t = H5Aget_type(a);
  if (H5Tget_class(t) == H5T_STRING && H5Tis_variable_str(t) > 0) s.variable_length.push_back(name);
  H5Tclose(t);
  H5Aclose(a);
  return 0;
}

herr_t survey_object(hid_t root, const char* name, const H5O_info_t* info, void* data) {
  auto& s = *static_cast<FileSurvey*>(data);
  const hid_t o = H5Oopen(root, name, H5P_DEFAULT);
  H5Aiterate2(o, H5_INDEX_NAME, H5_ITER_NATIVE, nullptr, survey_attr, data);
  if (info->type == H5O_TYPE_DATASET) {
    ++s.datasets;
    const hid_t space = H5Dget_space(o);
    if (H5Sget_simple_extent_npoints(space) == 0) ++s.empty;
    H5Sclose(space);
    const hid_t dcpl = H5Dget_create_plist(o);
    unsigned flags = 0, config = 0;
    std::size_t nelmts = 0;
    if (H5Pget_filter_by_id2(dcpl, H5Z_FILTER_FLETCHER32, &flags, &nelmts, nullptr, 0, nullptr, &config) >= 0)
      ++s.checksummed;
    H5Pclose(dcpl);
    const hid_t t = H5Dget_type(o);
    if (H5Tget_class(t) == H5T_STRING && H5Tis_variable_str(t) > 0) s.variable_length.push_back(name);
    H5Tclose(t);
  }
  H5Oclose(o);
  return 0;
}

FileSurvey survey(const std::string& file) {
  FileSurvey s;
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  H5Ovisit2(f, H5_INDEX_NAME, H5_ITER_NATIVE, survey_object, &s, H5O_INFO_BASIC);
  H5Fclose(f);
  return s;
}

// Replaces dataset `name` of `file` by `dims` values of `type` from `data`
// (nullptr: nothing written, a sparse chunked dataset of that size).
void replace_dataset(const std::string& file, const std::string& name, hid_t type,
                     const std::vector<hsize_t>& dims, const void* data) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  H5Ldelete(f, name.c_str(), H5P_DEFAULT);
  const hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
  const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
  const hsize_t chunk[1] = {1024};
  if (!data) H5Pset_chunk(dcpl, 1, chunk);
  const hid_t ds = H5Dcreate2(f, name.c_str(), type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT);
  ASSERT_GE(ds, 0);
  if (data) {
    ASSERT_GE(H5Dwrite(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), 0);
  }
  H5Dclose(ds);
  H5Pclose(dcpl);
  H5Sclose(space);
  ASSERT_GE(H5Fclose(f), 0);
}

TEST_F(H5Damage, EveryDatasetCarriesFletcher32AndTextIsFixedLength) {
  dda::write_blocks_h5(path("b.h5"), two_blocks());
  const FileSurvey s = survey(path("b.h5"));
  EXPECT_GT(s.datasets, 10);
  EXPECT_EQ(s.checksummed + s.empty, s.datasets) << "a non-empty dataset without the Fletcher-32 filter";
  EXPECT_TRUE(s.variable_length.empty()) << "variable-length text: " << s.variable_length.front();
}

TEST_F(H5Damage, FlippedBitInDataIsReportedAsDamage) {
  dda::write_blocks_h5(path("b.h5"), two_blocks());
  // The file offset of the vertex data (its one chunk).
  haddr_t at = HADDR_UNDEF;
  {
    const hid_t f = H5Fopen(path("b.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const hid_t ds = H5Dopen2(f, "/blocks/vertices", H5P_DEFAULT);
    const hid_t space = H5Dget_space(ds);
    hsize_t offset[2];
    unsigned mask = 0;
    hsize_t size = 0;
    EXPECT_GE(H5Dget_chunk_info(ds, space, 0, offset, &mask, &at, &size), 0);
    H5Sclose(space);
    H5Dclose(ds);
    H5Fclose(f);
  }
  ASSERT_NE(at, HADDR_UNDEF);
  {
    std::fstream f(path("b.h5"), std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(static_cast<std::streamoff>(at + 13));  // inside vertex 1's x
    char c = 0;
    f.get(c);
    f.seekp(static_cast<std::streamoff>(at + 13));
    f.put(static_cast<char>(c ^ 0x10));
  }
  EXPECT_EQ(error_of([&] { dda::read_blocks_h5(path("b.h5")); }),
            path("b.h5") + ": is damaged (dataset /blocks/vertices fails its checksum or cannot be read).");
}

TEST_F(H5Damage, OffsetBeyondTheVerticesIsRefusedBeforeIndexing) {
  dda::write_blocks_h5(path("b.h5"), two_blocks());
  // Each step at least 3, first 0 and last the vertex count: only the middle
  // entry is wrong, as a flipped high bit makes it.
  const std::vector<std::int64_t> off{0, std::int64_t{1} << 40, 8};
  replace_dataset(path("b.h5"), "/blocks/offsets", H5T_NATIVE_INT64, {3}, off.data());
  EXPECT_EQ(error_of([&] { dda::read_blocks_h5(path("b.h5")); }),
            path("b.h5") + ": dataset /blocks/offsets entry 1 is 1099511627776, beyond the end 8.");
  const std::vector<std::int64_t> off2{0, 12, 8};
  replace_dataset(path("b.h5"), "/blocks/offsets", H5T_NATIVE_INT64, {3}, off2.data());
  EXPECT_EQ(error_of([&] { dda::read_blocks_h5(path("b.h5")); }),
            path("b.h5") + ": dataset /blocks/offsets entry 1 is 12, beyond the end 8.");
}

TEST_F(H5Damage, CountBeyondTheFileSizeIsDamageNotAnAllocation) {
  dda::write_blocks_h5(path("b.h5"), two_blocks());
  // 2^40 areas (8 TiB) in a file of a few KiB: HDF5 allows the sparse
  // dataset, but no file of this size can hold the values.
  replace_dataset(path("b.h5"), "/blocks/area", H5T_IEEE_F64LE, {hsize_t{1} << 40}, nullptr);
  EXPECT_EQ(error_of([&] { dda::read_blocks_h5(path("b.h5")); }),
            path("b.h5") + ": is damaged (dataset /blocks/area claims more values than the file could hold).");
}

// ---------------------------------------------------------------- old files

// The layout of files written before the checksums: contiguous datasets,
// variable-length text, the earliest HDF5 file format.
class OldStyleWriter {
 public:
  explicit OldStyleWriter(const std::string& p) : f_(H5Fcreate(p.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT)) {}
  ~OldStyleWriter() { H5Fclose(f_); }
  void text_attr(const char* name, const char* value) {
    const hid_t t = vlen();
    const hid_t s = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2(f_, name, t, s, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, t, &value);
    H5Aclose(a);
    H5Sclose(s);
    H5Tclose(t);
  }
  void int_attr(const char* name, std::int32_t v) {
    const hid_t s = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2(f_, name, H5T_STD_I32LE, s, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, H5T_NATIVE_INT32, &v);
    H5Aclose(a);
    H5Sclose(s);
  }
  void group(const char* name) { H5Gclose(H5Gcreate2(f_, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)); }
  void data(const char* name, hid_t ftype, hid_t mtype, std::vector<hsize_t> dims, const void* v) {
    const hid_t s = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
    const hid_t d = H5Dcreate2(f_, name, ftype, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(d, mtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, v);
    H5Dclose(d);
    H5Sclose(s);
  }
  void texts(const char* name, const std::vector<const char*>& v) {
    const hid_t t = vlen();
    data(name, t, t, {v.size()}, v.data());
    H5Tclose(t);
  }

 private:
  static hid_t vlen() {
    const hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, H5T_VARIABLE);
    H5Tset_cset(t, H5T_CSET_UTF8);
    return t;
  }
  hid_t f_;
};

TEST_F(H5Damage, FileWrittenBeforeTheChecksumsStillReads) {
  {
    OldStyleWriter w(path("old.h5"));
    w.text_attr("format", "dda-blocks");
    w.int_attr("format_version", 1);
    w.text_attr("scenario", "name: old\n");
    w.group("/blocks");
    const dda::BlockModel m = two_blocks();
    std::vector<double> xy, area, centroid, moments;
    std::vector<std::int64_t> offsets{0};
    std::vector<std::int32_t> edge_set, layer;
    for (const dda::Block& b : m.blocks) {
      for (const dda::Vec2& v : b.vertices) xy.insert(xy.end(), {v.x(), v.y()});
      edge_set.insert(edge_set.end(), b.edge_set.begin(), b.edge_set.end());
      offsets.push_back(static_cast<std::int64_t>(xy.size() / 2));
      area.push_back(b.area);
      centroid.insert(centroid.end(), {b.centroid.x(), b.centroid.y()});
      moments.insert(moments.end(), {b.sxx, b.syy, b.sxy});
      layer.push_back(-1);
    }
    w.data("/blocks/vertices", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {8, 2}, xy.data());
    w.data("/blocks/offsets", H5T_STD_I64LE, H5T_NATIVE_INT64, {3}, offsets.data());
    w.data("/blocks/edge_set", H5T_STD_I32LE, H5T_NATIVE_INT32, {8}, edge_set.data());
    w.data("/blocks/area", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {2}, area.data());
    w.data("/blocks/centroid", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {2, 2}, centroid.data());
    w.data("/blocks/second_moments", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {2, 3}, moments.data());
    w.data("/blocks/layer", H5T_STD_I32LE, H5T_NATIVE_INT32, {2}, layer.data());
    w.group("/sets");
    w.texts("/sets/name", {"J1"});
    w.texts("/sets/origin", {"user"});
  }
  const dda::BlockModel m = dda::read_blocks_h5(path("old.h5"));
  ASSERT_EQ(m.blocks.size(), 2u);
  EXPECT_EQ(m.blocks[1].vertices[2], dda::Vec2(2, 1));
  EXPECT_EQ(m.blocks[0].edge_set, (std::vector<int>{-1, 0, -1, -1}));
  ASSERT_EQ(m.sets.size(), 1u);
  EXPECT_EQ(m.sets[0].name, "J1");
  EXPECT_EQ(m.provenance.scenario_text, "name: old\n");
  EXPECT_EQ(dda::h5_format_of(path("old.h5")), "dda-blocks");
}

}  // namespace
