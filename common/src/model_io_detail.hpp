#pragma once
// Private to dda_common: the pieces the HDF5 files of the pipeline share
// (2D lines and blocks in model_io.cpp; 3D fractures and blocks3d in
// model_io3d_*.cpp). Readers turn every problem into one InputError naming
// the file (through h5::Reader::fail); the layout itself is documented in
// docs/formats.md.
#include <cstdint>
#include <string>
#include <vector>

#include "dda/common/fracture_model.hpp"
#include "dda/common/h5_util.hpp"

namespace dda::io {

constexpr int kFormatVersion = 1;
constexpr const char* kUnits3d =
    "SI: lengths m, areas m^2, volumes m^3, second moments m^5, angles deg";
constexpr const char* kSetCodes =
    "joint set index (0, 1, ...; see /sets), -1 domain boundary, -2 excavation, -3 artificial";

// ------------------------------------------------------------------ writing

// format, format_version, units and the provenance (program version and
// creation time filled in when empty).
// `root`: the object that carries them, the file by default (a group that
// embeds a model in another file, e.g. /model of a 3D results file).
void write_root_attributes(h5::Writer& w, const char* format, const char* units, const Provenance& p,
                           hid_t root = -1);
// Rows of x y z, for an (n, 3) dataset.
std::vector<double> flatten(const std::vector<Vec3>& v);
// `at`: the group prefix the groups are made under ("" the root, "model/").
void write_domain(h5::Writer& w, const Box3& box, const std::string& at = "");
void write_sets(h5::Writer& w, const std::vector<JointSetInfo>& sets, const std::string& at = "");
void write_points(h5::Writer& w, const std::vector<ModelPoint3>& points, const std::string& at = "");
// The /layers group with bottom, top, target_fsi and realised_fsi, whose
// descriptions name the bed coordinate and what was generated; returned so a
// file can add its own datasets.
h5::Id write_layer_table(h5::Writer& w, const std::vector<Layer>& layers, const std::string& coordinate,
                         const std::string& generated, const std::string& at = "");
void write_layers(h5::Writer& w, const std::vector<Layer>& layers, const Vec3& bed_normal,
                  const std::string& at = "");

// ------------------------------------------------------------------ reading

// "(2, 3)" or "(5,)": a dataset's shape as messages write it.
std::string shape_text(const std::vector<hsize_t>& dims);
// InputError naming `ds` if a value is not finite.
void check_finite(const h5::Reader& r, const std::string& ds, const std::vector<double>& v);

// `format` is `expected` and `format_version` one this code reads.
void check_format(const h5::Reader& r, const std::string& expected);
Provenance read_provenance(const h5::Reader& r, hid_t from = -1);  // the file's root by default
// A finite float64 root attribute, 0 if absent.
double root_number(const h5::Reader& r, const char* name);

// An (n, cols) float64 dataset with exactly n rows (one per `what`), finite.
std::vector<double> read_rows(const h5::Reader& r, const std::string& ds, std::size_t n,
                              std::size_t cols, const std::string& what);
// An (n, cols) float64 dataset of any n, finite; `rows` receives n.
std::vector<double> read_table(const h5::Reader& r, const std::string& ds, std::size_t cols,
                               std::size_t& rows);
// A 1-D float64 dataset of exactly n values, finite.
std::vector<double> read_vector(const h5::Reader& r, const std::string& ds, std::size_t n,
                                const std::string& what);
// A 1-D integer dataset of exactly n values, each in [lo, hi].
std::vector<int> read_ints(const h5::Reader& r, const std::string& ds, std::size_t n,
                           const std::string& what, long long lo, long long hi);
// A 1-D integer dataset of any length, each in [lo, hi].
std::vector<int> read_int_list(const h5::Reader& r, const std::string& ds, long long lo,
                               long long hi);
std::vector<std::string> read_strings(const h5::Reader& r, const std::string& ds, std::size_t n,
                                      const std::string& what);
// CSR offsets: at least one entry, starting at 0, ending at `total`, each
// step at least `min_step` (item i owns [offsets[i], offsets[i+1])). `item`
// names what an entry is ("polygon", "face") for the message.
std::vector<std::int64_t> read_offsets(const h5::Reader& r, const std::string& ds,
                                       std::size_t total, long long min_step,
                                       const std::string& item);
// A dataset of whole shape `dims`, finite (for fixed shapes like (2, 3)).
std::vector<double> read_fixed(const h5::Reader& r, const std::string& ds,
                               const std::vector<hsize_t>& dims);

// `at` as for the writers: "" the root, "model/" a group below it.
Box3 read_domain(const h5::Reader& r, const std::string& at = "");
std::vector<JointSetInfo> read_sets(const h5::Reader& r, const std::string& at = "");
std::vector<ModelPoint3> read_points(const h5::Reader& r, const std::string& at = "");
// The beds and, through `bed_normal`, their normal ((0, 0, 1) if absent).
std::vector<Layer> read_layers(const h5::Reader& r, Vec3& bed_normal, const std::string& at = "");

inline Vec3 row3(const std::vector<double>& v, std::size_t i) {
  return {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
}

}  // namespace dda::io
