#include "dda/common/h5_util.hpp"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
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

// Raw data of one chunk at most this big: HDF5's default chunk cache holds
// one such chunk, and a small file is then one chunk a dataset (one
// checksum over all of it).
constexpr hsize_t kChunkBytes = hsize_t{1} << 20;

// Chunk shape for `dims`: whole rows of the inner dimensions while they fit
// in kChunkBytes, the outer dimensions cut to fit.
std::vector<hsize_t> chunk_shape(const std::vector<hsize_t>& dims, std::size_t element_bytes) {
  std::vector<hsize_t> chunk(dims);
  hsize_t inner = element_bytes;  // bytes of one index of dimension i
  for (std::size_t i = dims.size(); i-- > 0;) {
    const hsize_t fit = std::max<hsize_t>(1, kChunkBytes / inner);
    chunk[i] = std::min(dims[i], fit);
    inner *= chunk[i];
  }
  return chunk;
}

// A fixed-length UTF-8 string type of `size` bytes (at least 1: HDF5 has no
// zero-length strings), padded with NULs.
Id fixed_string_type(std::size_t size) {
  Id t(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(t.get(), std::max<std::size_t>(size, 1));
  H5Tset_strpad(t.get(), H5T_STR_NULLPAD);
  H5Tset_cset(t.get(), H5T_CSET_UTF8);
  return t;
}

// The memory type that reads fixed-length text of `size` bytes as C strings
// of size + 1 (the extra byte ends a string that fills its field).
Id nul_terminated_type(hid_t file_type, std::size_t size) {
  Id t(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(t.get(), size + 1);
  H5Tset_strpad(t.get(), H5T_STR_NULLTERM);
  H5Tset_cset(t.get(), H5Tget_cset(file_type));
  return t;
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
  // The HDF5 1.10 file format checksums every piece of metadata (superblock,
  // object headers, link and attribute heaps, chunk indexes), so a flipped
  // bit there is an error HDF5 reports, not a structure it walks. Pinned to
  // 1.10 (not "latest") so that any HDF5 from 1.10 on reads the files.
  if (H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V110, H5F_LIBVER_V110) < 0)
    fail("cannot select the HDF5 1.10 file format");
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
  hsize_t n = 1;
  for (hsize_t d : dims) n *= d;
  // Every value carries the Fletcher-32 checksum, which needs chunked
  // storage: a flipped bit in the data is then a read error, not a number.
  // An empty dataset has no data to check (and HDF5 has no empty chunk).
  Id dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  if (n > 0) {
    const std::vector<hsize_t> chunk = chunk_shape(dims, H5Tget_size(file_type));
    if (H5Pset_chunk(dcpl.get(), static_cast<int>(chunk.size()), chunk.data()) < 0 ||
        H5Pset_fletcher32(dcpl.get()) < 0)
      fail("cannot set the checksum of dataset " + name);
  }
  Id ds(H5Dcreate2(loc, name.c_str(), file_type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
        H5Dclose);
  if (!ds.valid()) fail("cannot create dataset " + name);
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

void Writer::i32(hid_t loc, const std::string& name, const std::vector<std::int32_t>& data,
                 std::vector<hsize_t> dims, const std::string& units, const std::string& description) {
  write_numeric(loc, name, H5T_STD_I32LE, H5T_NATIVE_INT32, data.data(), dims, units, description);
}

void Writer::i64(hid_t loc, const std::string& name, const std::vector<std::int64_t>& data,
                 const std::string& units, const std::string& description) {
  write_numeric(loc, name, H5T_STD_I64LE, H5T_NATIVE_INT64, data.data(), {data.size()}, units,
                description);
}

void Writer::strings(hid_t loc, const std::string& name, const std::vector<std::string>& data,
                     const std::string& units, const std::string& description) {
  // Fixed-length, as wide as the longest: the text is then in the chunk the
  // checksum covers (variable-length text lives in HDF5's global heap, which
  // has no checksum and which HDF5 reads without checking).
  std::size_t width = 1;
  for (const std::string& s : data) width = std::max(width, s.size());
  Id type = fixed_string_type(width);
  std::string packed(data.size() * width, '\0');
  for (std::size_t i = 0; i < data.size(); ++i) packed.replace(i * width, data[i].size(), data[i]);
  write_numeric(loc, name, type.get(), type.get(), packed.data(), {data.size()}, units, description);
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
  // Fixed-length, in the object header whose checksum covers it. A long
  // scenario (beyond the 64 KiB of a header message) goes to the file
  // format's dense attribute storage, checksummed as well.
  Id type = fixed_string_type(value.size());
  std::string padded = value;
  padded.resize(std::max<std::size_t>(value.size(), 1), '\0');
  attr_scalar(obj, name, type.get(), type.get(), padded.data());
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

namespace {
const FileImage* active_image = nullptr;
}  // namespace

FileImage::FileImage(std::string path, const void* data, std::size_t size)
    : path_(std::move(path)), data_(data), size_(size) {
  if (active_image) throw InternalError("h5::FileImage: another image is already in use.");
  active_image = this;
}

FileImage::~FileImage() { active_image = nullptr; }

void Reader::open_image(const FileImage& image) {
  file_bytes_ = image.size();
  // The signature test of H5Fis_hdf5, which reads only files: HDF5 looks for
  // it at offset 0, 512, 1024, ...; the project's files have it at 0.
  static const char signature[8] = {'\x89', 'H', 'D', 'F', '\r', '\n', '\x1a', '\n'};
  if (image.size() < sizeof signature || std::memcmp(image.data(), signature, sizeof signature) != 0)
    throw InputError(path_ + ": is not an HDF5 file.");
  Id fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  H5Pset_fclose_degree(fapl.get(), H5F_CLOSE_STRONG);
  // No backing store: nothing is ever written to a file of that name.
  H5Pset_fapl_core(fapl.get(), 1 << 16, false);
  if (H5Pset_file_image(fapl.get(), const_cast<void*>(image.data()), image.size()) < 0)
    damaged("HDF5 cannot take it as a file image");
  file_ = Id(H5Fopen(path_.c_str(), H5F_ACC_RDONLY, fapl.get()), H5Fclose);
  if (!file_.valid()) damaged("HDF5 cannot open it; is it truncated?");
}

Reader::Reader(std::string path) : path_(std::move(path)) {
  silence_errors();
  if (active_image && active_image->path() == path_) {
    open_image(*active_image);
    return;
  }
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path_, ec)) throw InputError(path_ + ": file not found.");
  if (fs::is_directory(path_, ec)) throw InputError(path_ + ": is a folder, not a file.");
  {
    std::ifstream probe(path_, std::ios::binary);
    if (!probe) throw InputError(path_ + ": cannot open the file (permission denied?).");
  }
  file_bytes_ = fs::file_size(path_, ec);
  if (ec) throw InputError(path_ + ": cannot open the file (its size is unknown).");
  const htri_t is = H5Fis_hdf5(path_.c_str());
  if (is <= 0) throw InputError(path_ + ": is not an HDF5 file.");
  Id fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  H5Pset_fclose_degree(fapl.get(), H5F_CLOSE_STRONG);
  file_ = Id(H5Fopen(path_.c_str(), H5F_ACC_RDONLY, fapl.get()), H5Fclose);
  if (!file_.valid()) damaged("HDF5 cannot open it; is it truncated?");
}

void Reader::fail(const std::string& what) const { throw InputError(path_ + ": " + what + "."); }

void Reader::damaged(const std::string& what) const {
  throw DamagedFile(path_ + ": is damaged (" + what + ").");
}

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
    const htri_t found = H5Lexists(file_.get(), prefix.c_str(), H5P_DEFAULT);
    if (found < 0) damaged("cannot look up " + prefix);
    if (found == 0) return false;
    start = end + 1;
  }
  return true;
}

hsize_t Reader::checked_count(hid_t space, std::size_t element_bytes, const std::string& what,
                              std::vector<hsize_t>* dims) const {
  const H5S_class_t kind = H5Sget_simple_extent_type(space);
  if (kind == H5S_NULL) {
    if (dims) dims->clear();
    return 0;
  }
  if (kind == H5S_SCALAR) {
    if (dims) dims->clear();
    if (element_bytes > file_bytes_) damaged(what + " claims a value larger than the file");
    return 1;
  }
  const int rank = H5Sget_simple_extent_ndims(space);
  if (kind != H5S_SIMPLE || rank < 0 || rank > H5S_MAX_RANK)
    damaged(what + " has an unreadable shape");
  std::vector<hsize_t> d(static_cast<std::size_t>(rank));
  if (H5Sget_simple_extent_dims(space, d.data(), nullptr) < 0)
    damaged(what + " has an unreadable shape");
  // Bytes = count x element size, compared with the file's size step by
  // step (no product can overflow): a dataset cannot hold more than the
  // file, and nothing is allocated for a count that a flipped bit made.
  const hsize_t limit = file_bytes_ / std::max<std::size_t>(element_bytes, 1);
  hsize_t n = 1;
  for (hsize_t k : d) {
    if (k != 0 && n > limit / k)
      damaged(what + " claims more values than the file could hold");
    n *= k;
  }
  if (dims) *dims = std::move(d);
  return n;
}

Id Reader::open_scalar_attr(hid_t obj, const std::string& name, const std::string& where) const {
  const htri_t found = H5Aexists(obj, name.c_str());
  if (found < 0) damaged("cannot look up attribute " + name + " of " + where);
  if (found == 0) return Id();
  Id a(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose);
  if (!a.valid()) damaged("cannot open attribute " + name + " of " + where);
  Id space(H5Aget_space(a.get()), H5Sclose);
  if (!space.valid()) damaged("attribute " + name + " of " + where + " has an unreadable shape");
  if (checked_count(space.get(), 1, "attribute " + name + " of " + where) != 1)
    fail("attribute " + name + " of " + where + " must hold a single value");
  return a;
}

std::optional<std::string> Reader::read_text_attr(hid_t attr, const std::string& what) const {
  Id ftype(H5Aget_type(attr), H5Tclose);
  if (!ftype.valid()) damaged(what + " has an unreadable type");
  if (H5Tget_class(ftype.get()) != H5T_STRING) return std::nullopt;
  const htri_t vlen = H5Tis_variable_str(ftype.get());
  if (vlen < 0) damaged(what + " has an unreadable type");
  if (vlen > 0) {
    // Files written before fixed-length text: HDF5 follows the string into
    // the global heap, which has no checksum; a damaged heap there is beyond
    // what this reader can check (docs/reliability.md, "Damaged files").
    Id mtype = utf8_string_type();
    H5Tset_cset(mtype.get(), H5Tget_cset(ftype.get()));
    char* value = nullptr;
    if (H5Aread(attr, mtype.get(), &value) < 0) damaged("cannot read " + what);
    std::string out = value ? value : "";
    Id space(H5Screate(H5S_SCALAR), H5Sclose);
    reclaim_strings(mtype.get(), space.get(), &value);
    return out;
  }
  const std::size_t size = H5Tget_size(ftype.get());
  if (size == 0 || size > file_bytes_) damaged(what + " claims text longer than the file");
  Id mtype = nul_terminated_type(ftype.get(), size);
  std::string buf(size + 1, '\0');
  if (H5Aread(attr, mtype.get(), buf.data()) < 0) damaged("cannot read " + what);
  buf.resize(std::char_traits<char>::length(buf.c_str()));
  return buf;
}

std::optional<std::string> Reader::attr_text(hid_t obj, const std::string& name,
                                             const std::string& where) const {
  Id a = open_scalar_attr(obj, name, where);
  if (!a.valid()) return std::nullopt;
  auto v = read_text_attr(a.get(), "attribute " + name + " of " + where);
  if (!v) fail("attribute " + name + " of " + where + " must be text");
  return v;
}

namespace {

// Whether an attribute's stored type is of `cls` and of a size a native
// number of up to 8 bytes can take (HDF5 allows integers of any size).
bool is_number_type(hid_t attr, H5T_class_t cls) {
  Id t(H5Aget_type(attr), H5Tclose);
  if (!t.valid() || H5Tget_class(t.get()) != cls) return false;
  const std::size_t size = H5Tget_size(t.get());
  return size >= 1 && size <= 8;
}

}  // namespace

std::optional<std::int64_t> Reader::attr_int(hid_t obj, const std::string& name,
                                             const std::string& where) const {
  Id a = open_scalar_attr(obj, name, where);
  if (!a.valid()) return std::nullopt;
  std::int64_t v = 0;
  if (!is_number_type(a.get(), H5T_INTEGER) || H5Aread(a.get(), H5T_NATIVE_INT64, &v) < 0)
    fail("attribute " + name + " of " + where + " must be an integer");
  return v;
}

std::optional<std::uint64_t> Reader::attr_u64(hid_t obj, const std::string& name,
                                              const std::string& where) const {
  Id a = open_scalar_attr(obj, name, where);
  if (!a.valid()) return std::nullopt;
  std::uint64_t v = 0;
  if (!is_number_type(a.get(), H5T_INTEGER) || H5Aread(a.get(), H5T_NATIVE_UINT64, &v) < 0)
    fail("attribute " + name + " of " + where + " must be a non-negative integer");
  return v;
}

std::optional<double> Reader::attr_f64(hid_t obj, const std::string& name,
                                       const std::string& where) const {
  Id a = open_scalar_attr(obj, name, where);
  if (!a.valid()) return std::nullopt;
  double v = 0;
  if ((!is_number_type(a.get(), H5T_FLOAT) && !is_number_type(a.get(), H5T_INTEGER)) ||
      H5Aread(a.get(), H5T_NATIVE_DOUBLE, &v) < 0)
    fail("attribute " + name + " of " + where + " must be a number");
  return v;
}

Id Reader::open_dataset(const std::string& abs_path) const {
  if (!exists(abs_path)) fail("dataset " + abs_path + " is missing");
  Id ds(H5Dopen2(file_.get(), abs_path.c_str(), H5P_DEFAULT), H5Dclose);
  if (!ds.valid()) damaged("cannot open dataset " + abs_path);
  return ds;
}

template <class T>
Array<T> Reader::numeric(const std::string& abs_path, hid_t mem_type) const {
  Id ds = open_dataset(abs_path);
  Id type(H5Dget_type(ds.get()), H5Tclose);
  if (!type.valid()) damaged("dataset " + abs_path + " has an unreadable type");
  const H5T_class_t c = H5Tget_class(type.get());
  if (c != H5T_INTEGER && c != H5T_FLOAT) fail("dataset " + abs_path + " must hold numbers");
  const std::size_t size = H5Tget_size(type.get());
  if (size < 1 || size > 16) damaged("dataset " + abs_path + " has numbers of " + std::to_string(size) + " bytes");
  Id space(H5Dget_space(ds.get()), H5Sclose);
  if (!space.valid()) damaged("dataset " + abs_path + " has an unreadable shape");
  Array<T> out;
  const hsize_t n = checked_count(space.get(), size, "dataset " + abs_path, &out.dims);
  out.data.resize(n);
  if (n > 0 && H5Dread(ds.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data.data()) < 0)
    damaged("dataset " + abs_path + " fails its checksum or cannot be read");
  return out;
}

Array<double> Reader::f64(const std::string& abs_path) const {
  return numeric<double>(abs_path, H5T_NATIVE_DOUBLE);
}

Array<std::int64_t> Reader::i64(const std::string& abs_path) const {
  {
    Id ds = open_dataset(abs_path);
    Id type(H5Dget_type(ds.get()), H5Tclose);
    if (H5Tget_class(type.get()) != H5T_INTEGER)
      fail("dataset " + abs_path + " must hold integers");
  }
  return numeric<std::int64_t>(abs_path, H5T_NATIVE_INT64);
}

std::vector<std::string> Reader::strings(const std::string& abs_path) const {
  Id ds = open_dataset(abs_path);
  Id ftype(H5Dget_type(ds.get()), H5Tclose);
  if (!ftype.valid()) damaged("dataset " + abs_path + " has an unreadable type");
  if (H5Tget_class(ftype.get()) != H5T_STRING) fail("dataset " + abs_path + " must hold text");
  Id space(H5Dget_space(ds.get()), H5Sclose);
  if (!space.valid()) damaged("dataset " + abs_path + " has an unreadable shape");
  const htri_t vlen = H5Tis_variable_str(ftype.get());
  if (vlen < 0) damaged("dataset " + abs_path + " has an unreadable type");
  // A variable-length string takes 16 bytes in the dataset (length and heap
  // address), a fixed-length one its size.
  const std::size_t size = vlen > 0 ? 16 : H5Tget_size(ftype.get());
  if (size == 0) damaged("dataset " + abs_path + " has text of no size");
  std::vector<hsize_t> dims;
  const hsize_t n = checked_count(space.get(), size, "dataset " + abs_path, &dims);
  if (dims.size() != 1) fail("dataset " + abs_path + " must be one-dimensional");
  std::vector<std::string> out;
  out.reserve(n);
  if (n == 0) return out;
  if (vlen > 0) {
    // Files written before fixed-length text (see read_text_attr).
    Id mtype = utf8_string_type();
    H5Tset_cset(mtype.get(), H5Tget_cset(ftype.get()));
    std::vector<char*> ptrs(n, nullptr);
    if (H5Dread(ds.get(), mtype.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()) < 0)
      damaged("dataset " + abs_path + " cannot be read");
    for (char* p : ptrs) out.emplace_back(p ? p : "");
    reclaim_strings(mtype.get(), space.get(), ptrs.data());
  } else {
    Id mtype = nul_terminated_type(ftype.get(), size);
    std::string buf(n * (size + 1), '\0');
    if (H5Dread(ds.get(), mtype.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data()) < 0)
      damaged("dataset " + abs_path + " fails its checksum or cannot be read");
    for (hsize_t i = 0; i < n; ++i) out.emplace_back(buf.c_str() + i * (size + 1));
  }
  return out;
}

std::vector<std::int64_t> Reader::offsets(const std::string& abs_path, std::size_t total,
                                          long long min_step, const std::string& item) const {
  Array<std::int64_t> off = i64(abs_path);
  if (off.dims.size() != 1 || off.dims[0] < 1)
    fail("dataset " + abs_path + " has shape " + describe_dims(off.dims) +
         ", expected (N+1,) with at least one entry");
  const std::vector<std::int64_t>& v = off.data;
  if (v.front() != 0) fail("dataset " + abs_path + " must start at 0, found " + std::to_string(v.front()));
  const auto end = static_cast<std::int64_t>(total);
  // Every entry is checked against the end before the next difference is
  // taken, so no subtraction can overflow and no entry lies outside [0, total].
  for (std::size_t i = 0; i + 1 < v.size(); ++i) {
    if (v[i + 1] > end)
      fail("dataset " + abs_path + " entry " + std::to_string(i + 1) + " is " + std::to_string(v[i + 1]) +
           ", beyond the end " + std::to_string(total));
    if (v[i + 1] < v[i])
      fail("dataset " + abs_path + " entry " + std::to_string(i + 1) + " is " + std::to_string(v[i + 1]) +
           ", below the entry before it " + std::to_string(v[i]));
    if (v[i + 1] - v[i] < min_step)
      fail("dataset " + abs_path + " gives " + item + " " + std::to_string(i) + " " +
           std::to_string(v[i + 1] - v[i]) + " entries, it needs at least " + std::to_string(min_step));
  }
  if (v.back() != end)
    fail("dataset " + abs_path + " must end at " + std::to_string(total) + ", found " +
         std::to_string(v.back()));
  return std::move(off.data);
}

}  // namespace dda::h5
