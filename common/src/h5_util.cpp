#include "dda/common/h5_util.hpp"

#include <filesystem>
#include <fstream>
#include <utility>

#include "dda/common/error.hpp"

namespace dda::h5 {
namespace {

// Frees the strings HDF5 allocated for a variable-length read.
herr_t reclaim_strings(hid_t type, hid_t space, void* buf) {
#if H5_VERSION_GE(1, 12, 0)
  return H5Treclaim(type, space, H5P_DEFAULT, buf);
#else
  return H5Dvlen_reclaim(type, space, H5P_DEFAULT, buf);
#endif
}

std::string describe_dims(const std::vector<hsize_t>& dims) {
  std::string s = "(";
  for (std::size_t i = 0; i < dims.size(); ++i) {
    if (i) s += ", ";
    s += std::to_string(dims[i]);
  }
  return s + (dims.size() == 1 ? ",)" : ")");
}

// Scalar string value of an attribute, fixed or variable length.
std::optional<std::string> read_text_attr(hid_t attr) {
  Id ftype(H5Aget_type(attr), H5Tclose);
  if (!ftype.valid() || H5Tget_class(ftype.get()) != H5T_STRING) return std::nullopt;
  const htri_t vlen = H5Tis_variable_str(ftype.get());
  if (vlen < 0) return std::nullopt;
  if (vlen > 0) {
    Id mtype = utf8_string_type();
    H5Tset_cset(mtype.get(), H5Tget_cset(ftype.get()));
    char* value = nullptr;
    if (H5Aread(attr, mtype.get(), &value) < 0) return std::nullopt;
    std::string out = value ? value : "";
    Id space(H5Screate(H5S_SCALAR), H5Sclose);
    reclaim_strings(mtype.get(), space.get(), &value);
    return out;
  }
  const std::size_t size = H5Tget_size(ftype.get());
  Id mtype(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(mtype.get(), size + 1);
  H5Tset_strpad(mtype.get(), H5T_STR_NULLTERM);
  H5Tset_cset(mtype.get(), H5Tget_cset(ftype.get()));
  std::string buf(size + 1, '\0');
  if (H5Aread(attr, mtype.get(), buf.data()) < 0) return std::nullopt;
  buf.resize(std::char_traits<char>::length(buf.c_str()));
  return buf;
}

}  // namespace

void silence_errors() {
  // No clean-up of the library at exit: after a failed write (a full disk)
  // HDF5 1.10 cannot close the file, and its exit handler then crashes on
  // the half-closed file (a segmentation fault after the error sentence).
  // Every file is closed explicitly, so the handler has nothing else to do.
  // It must be said before the library starts, hence in the first call that
  // every reader and writer makes; later calls change nothing.
  H5dont_atexit();
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

Id utf8_string_type() {
  Id t(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(t.get(), H5T_VARIABLE);
  H5Tset_cset(t.get(), H5T_CSET_UTF8);
  return t;
}

// ---------------------------------------------------------------- Writer

Writer::Writer(std::string shown_path, const std::string& real_path) : shown_(std::move(shown_path)) {
  silence_errors();
  Id fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  H5Pset_fclose_degree(fapl.get(), H5F_CLOSE_STRONG);
  file_ = Id(H5Fcreate(real_path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), H5Fclose);
  if (!file_.valid()) fail("cannot create the HDF5 file (is the folder writable?)");
}

void Writer::fail(const std::string& what) const {
  throw InputError(shown_ + ": cannot write: " + what + ".");
}

Id Writer::group(const std::string& name) {
  Id g(H5Gcreate2(file_.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (!g.valid()) fail("cannot create group /" + name);
  return g;
}

void Writer::write_numeric(hid_t loc, const std::string& name, hid_t file_type, hid_t mem_type,
                           const void* data, const std::vector<hsize_t>& dims,
                           const std::string& units, const std::string& description) {
  Id space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
  if (!space.valid()) fail("cannot make the dataspace of " + name);
  Id ds(H5Dcreate2(loc, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
        H5Dclose);
  if (!ds.valid()) fail("cannot create dataset " + name);
  hsize_t n = 1;
  for (hsize_t d : dims) n *= d;
  if (n > 0 && H5Dwrite(ds.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    fail("cannot write dataset " + name + " (disk full?)");
  attr_text(ds.get(), "units", units);
  attr_text(ds.get(), "description", description);
  if (!ds.close()) fail("cannot finish dataset " + name + " (disk full?)");
}

void Writer::f64(hid_t loc, const std::string& name, const std::vector<double>& data,
                 std::vector<hsize_t> dims, const std::string& units, const std::string& description) {
  write_numeric(loc, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data.data(), dims, units, description);
}

void Writer::i32(hid_t loc, const std::string& name, const std::vector<std::int32_t>& data,
                 const std::string& units, const std::string& description) {
  write_numeric(loc, name, H5T_STD_I32LE, H5T_NATIVE_INT32, data.data(), {data.size()}, units,
                description);
}

void Writer::i64(hid_t loc, const std::string& name, const std::vector<std::int64_t>& data,
                 const std::string& units, const std::string& description) {
  write_numeric(loc, name, H5T_STD_I64LE, H5T_NATIVE_INT64, data.data(), {data.size()}, units,
                description);
}

void Writer::strings(hid_t loc, const std::string& name, const std::vector<std::string>& data,
                     const std::string& units, const std::string& description) {
  Id type = utf8_string_type();
  std::vector<const char*> ptrs;
  ptrs.reserve(data.size());
  for (const std::string& s : data) ptrs.push_back(s.c_str());
  write_numeric(loc, name, type.get(), type.get(), ptrs.data(), {data.size()}, units, description);
}

void Writer::attr_scalar(hid_t obj, const std::string& name, hid_t file_type, hid_t mem_type,
                         const void* value) {
  Id space(H5Screate(H5S_SCALAR), H5Sclose);
  Id a(H5Acreate2(obj, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!a.valid()) fail("cannot create attribute " + name);
  if (H5Awrite(a.get(), mem_type, value) < 0) fail("cannot write attribute " + name);
  if (!a.close()) fail("cannot finish attribute " + name);
}

void Writer::attr_text(hid_t obj, const std::string& name, const std::string& value) {
  // Variable-length: the text lives in the global heap, so a long scenario
  // does not hit the 64 KiB limit of an object header.
  Id type = utf8_string_type();
  const char* p = value.c_str();
  attr_scalar(obj, name, type.get(), type.get(), &p);
}

void Writer::attr_i32(hid_t obj, const std::string& name, std::int32_t value) {
  attr_scalar(obj, name, H5T_STD_I32LE, H5T_NATIVE_INT32, &value);
}

void Writer::attr_u64(hid_t obj, const std::string& name, std::uint64_t value) {
  attr_scalar(obj, name, H5T_STD_U64LE, H5T_NATIVE_UINT64, &value);
}

void Writer::attr_f64(hid_t obj, const std::string& name, double value) {
  attr_scalar(obj, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

void Writer::close() {
  if (!file_.valid()) return;
  if (H5Fflush(file_.get(), H5F_SCOPE_GLOBAL) < 0) fail("cannot flush the file (disk full?)");
  if (!file_.close()) fail("cannot close the file (disk full?)");
}

// ---------------------------------------------------------------- Reader

Reader::Reader(std::string path) : path_(std::move(path)) {
  silence_errors();
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path_, ec)) throw InputError(path_ + ": file not found.");
  if (fs::is_directory(path_, ec)) throw InputError(path_ + ": is a folder, not a file.");
  {
    std::ifstream probe(path_, std::ios::binary);
    if (!probe) throw InputError(path_ + ": cannot open the file (permission denied?).");
  }
  const htri_t is = H5Fis_hdf5(path_.c_str());
  if (is <= 0) throw InputError(path_ + ": is not an HDF5 file.");
  Id fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  H5Pset_fclose_degree(fapl.get(), H5F_CLOSE_STRONG);
  file_ = Id(H5Fopen(path_.c_str(), H5F_ACC_RDONLY, fapl.get()), H5Fclose);
  if (!file_.valid())
    throw InputError(path_ + ": cannot open as HDF5 (the file is damaged or truncated).");
}

void Reader::fail(const std::string& what) const { throw InputError(path_ + ": " + what + "."); }

bool Reader::exists(const std::string& abs_path) const {
  // H5Lexists needs every parent to exist, so test the path piece by piece.
  if (abs_path.empty()) return false;
  std::string prefix;
  std::size_t start = abs_path.front() == '/' ? 1 : 0;
  while (start <= abs_path.size()) {
    std::size_t end = abs_path.find('/', start);
    if (end == std::string::npos) end = abs_path.size();
    prefix.push_back('/');
    prefix.append(abs_path, start, end - start);
    if (H5Lexists(file_.get(), prefix.c_str(), H5P_DEFAULT) <= 0) return false;
    start = end + 1;
  }
  return true;
}

Id Reader::open_scalar_attr(hid_t obj, const std::string& name, const std::string& where) const {
  if (H5Aexists(obj, name.c_str()) <= 0) return Id();
  Id a(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose);
  if (!a.valid()) fail("cannot read attribute " + name + " of " + where);
  Id space(H5Aget_space(a.get()), H5Sclose);
  if (!space.valid() || H5Sget_simple_extent_npoints(space.get()) != 1)
    fail("attribute " + name + " of " + where + " must hold a single value");
  return a;
}

std::optional<std::string> Reader::attr_text(hid_t obj, const std::string& name,
                                             const std::string& where) const {
  Id a = open_scalar_attr(obj, name, where);
  if (!a.valid()) return std::nullopt;
  auto v = read_text_attr(a.get());
  if (!v) fail("attribute " + name + " of " + where + " must be text");
  return v;
}

std::optional<std::int64_t> Reader::attr_int(hid_t obj, const std::string& name,
                                             const std::string& where) const {
  Id a = open_scalar_attr(obj, name, where);
  if (!a.valid()) return std::nullopt;
  Id t(H5Aget_type(a.get()), H5Tclose);
  std::int64_t v = 0;
  if (H5Tget_class(t.get()) != H5T_INTEGER || H5Aread(a.get(), H5T_NATIVE_INT64, &v) < 0)
    fail("attribute " + name + " of " + where + " must be an integer");
  return v;
}

std::optional<std::uint64_t> Reader::attr_u64(hid_t obj, const std::string& name,
                                              const std::string& where) const {
  Id a = open_scalar_attr(obj, name, where);
  if (!a.valid()) return std::nullopt;
  Id t(H5Aget_type(a.get()), H5Tclose);
  std::uint64_t v = 0;
  if (H5Tget_class(t.get()) != H5T_INTEGER || H5Aread(a.get(), H5T_NATIVE_UINT64, &v) < 0)
    fail("attribute " + name + " of " + where + " must be a non-negative integer");
  return v;
}

std::optional<double> Reader::attr_f64(hid_t obj, const std::string& name,
                                       const std::string& where) const {
  Id a = open_scalar_attr(obj, name, where);
  if (!a.valid()) return std::nullopt;
  Id t(H5Aget_type(a.get()), H5Tclose);
  const H5T_class_t c = H5Tget_class(t.get());
  double v = 0;
  if ((c != H5T_FLOAT && c != H5T_INTEGER) || H5Aread(a.get(), H5T_NATIVE_DOUBLE, &v) < 0)
    fail("attribute " + name + " of " + where + " must be a number");
  return v;
}

Id Reader::open_dataset(const std::string& abs_path) const {
  if (!exists(abs_path)) fail("dataset " + abs_path + " is missing");
  Id ds(H5Dopen2(file_.get(), abs_path.c_str(), H5P_DEFAULT), H5Dclose);
  if (!ds.valid()) fail(abs_path + " is not a readable dataset");
  return ds;
}

template <class T>
Array<T> Reader::numeric(const std::string& abs_path, hid_t mem_type) const {
  Id ds = open_dataset(abs_path);
  Id type(H5Dget_type(ds.get()), H5Tclose);
  const H5T_class_t c = H5Tget_class(type.get());
  if (c != H5T_INTEGER && c != H5T_FLOAT) fail("dataset " + abs_path + " must hold numbers");
  Id space(H5Dget_space(ds.get()), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0 || rank > 8) fail("dataset " + abs_path + " has an unreadable shape");
  Array<T> out;
  out.dims.resize(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space.get(), out.dims.data(), nullptr);
  hsize_t n = 1;
  for (hsize_t d : out.dims) n *= d;
  if (rank == 0) n = 1;  // a scalar dataset
  out.data.resize(n);
  if (n > 0 && H5Dread(ds.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data.data()) < 0)
    fail("cannot read dataset " + abs_path + " (the file is damaged, or a value does not fit " +
         describe_dims(out.dims) + ")");
  return out;
}

Array<double> Reader::f64(const std::string& abs_path) const {
  return numeric<double>(abs_path, H5T_NATIVE_DOUBLE);
}

Array<std::int64_t> Reader::i64(const std::string& abs_path) const {
  Id ds = open_dataset(abs_path);
  {
    Id type(H5Dget_type(ds.get()), H5Tclose);
    if (H5Tget_class(type.get()) != H5T_INTEGER)
      fail("dataset " + abs_path + " must hold integers");
  }
  ds.close();
  return numeric<std::int64_t>(abs_path, H5T_NATIVE_INT64);
}

std::vector<std::string> Reader::strings(const std::string& abs_path) const {
  Id ds = open_dataset(abs_path);
  Id ftype(H5Dget_type(ds.get()), H5Tclose);
  if (H5Tget_class(ftype.get()) != H5T_STRING) fail("dataset " + abs_path + " must hold text");
  Id space(H5Dget_space(ds.get()), H5Sclose);
  if (H5Sget_simple_extent_ndims(space.get()) != 1)
    fail("dataset " + abs_path + " must be one-dimensional");
  hsize_t n = 0;
  H5Sget_simple_extent_dims(space.get(), &n, nullptr);
  std::vector<std::string> out;
  out.reserve(n);
  if (n == 0) return out;
  const htri_t vlen = H5Tis_variable_str(ftype.get());
  if (vlen > 0) {
    Id mtype = utf8_string_type();
    H5Tset_cset(mtype.get(), H5Tget_cset(ftype.get()));
    std::vector<char*> ptrs(n, nullptr);
    if (H5Dread(ds.get(), mtype.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()) < 0)
      fail("cannot read dataset " + abs_path + " (the file is damaged)");
    for (char* p : ptrs) out.emplace_back(p ? p : "");
    reclaim_strings(mtype.get(), space.get(), ptrs.data());
  } else {
    const std::size_t size = H5Tget_size(ftype.get());
    Id mtype(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(mtype.get(), size + 1);
    H5Tset_strpad(mtype.get(), H5T_STR_NULLTERM);
    H5Tset_cset(mtype.get(), H5Tget_cset(ftype.get()));
    std::string buf(n * (size + 1), '\0');
    if (H5Dread(ds.get(), mtype.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data()) < 0)
      fail("cannot read dataset " + abs_path + " (the file is damaged)");
    for (hsize_t i = 0; i < n; ++i) out.emplace_back(buf.c_str() + i * (size + 1));
  }
  return out;
}

}  // namespace dda::h5
