#pragma once
// Includes <hdf5.h>: a library using this header links hdf5::hdf5 itself
// (PRIVATE), so HDF5 stays out of the public interface of dda_common.
// Helpers over the HDF5 C API for the project's own files (lines, blocks,
// results, checkpoints): handles that close themselves, and a writer and a
// reader that turn every HDF5 failure into one InputError sentence naming
// the file (HDF5's own error stack printing is switched off).
//
// Damaged files (docs/reliability.md, "Damaged files"): the writer makes
// every byte that matters checksummed (HDF5 1.10 metadata, Fletcher-32 on
// every dataset, fixed-length text only), and the reader is the one place
// that checks a size, a count or a string length against the file before
// anything is allocated or indexed.
#include <hdf5.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dda/common/error.hpp"

namespace dda::h5 {

// The InputError of a damaged file ("PATH: is damaged (...)."), its own type
// so that a caller that takes other errors as "not one of ours" (e.g.
// h5_format_of) still reports the damage.
class DamagedFile : public InputError {
 public:
  using InputError::InputError;
};

// Switches off HDF5's automatic error printing (idempotent).
void silence_errors();

// An owned hid_t, closed with the function it was made with.
class Id {
 public:
  using Closer = herr_t (*)(hid_t);
  Id() = default;
  Id(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  ~Id() { reset(); }
  Id(Id&& o) noexcept : id_(o.id_), closer_(o.closer_) { o.id_ = H5I_INVALID_HID; }
  Id& operator=(Id&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = o.id_;
      closer_ = o.closer_;
      o.id_ = H5I_INVALID_HID;
    }
    return *this;
  }
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  // Closes now; returns false if HDF5 reported a failure.
  bool close() {
    if (id_ < 0) return true;
    const herr_t r = closer_(id_);
    id_ = H5I_INVALID_HID;
    return r >= 0;
  }
  void reset() { close(); }

 private:
  hid_t id_ = H5I_INVALID_HID;
  Closer closer_ = nullptr;
};

// A UTF-8 variable-length string type (caller owns it). Only for reading
// files written before fixed-length text; nothing is written with it.
Id utf8_string_type();

// Creates a new HDF5 file at `real_path`; every message names `shown_path`
// (the final name the user asked for, not the temporary one).
class Writer {
 public:
  Writer(std::string shown_path, const std::string& real_path);
  hid_t file() const { return file_.get(); }
  // Creates a group below the root (e.g. "lines") and returns it.
  Id group(const std::string& name);

  // Datasets: `dims` has one entry (1-D) or more (rows x columns x ...); zero
  // sizes give zero-size datasets. Each carries `units` and `description`
  // attributes, and every non-empty one is chunked with the Fletcher-32
  // checksum filter.
  void f64(hid_t loc, const std::string& name, const std::vector<double>& data,
           std::vector<hsize_t> dims, const std::string& units, const std::string& description);
  void i32(hid_t loc, const std::string& name, const std::vector<std::int32_t>& data,
           const std::string& units, const std::string& description);
  void i32(hid_t loc, const std::string& name, const std::vector<std::int32_t>& data,
           std::vector<hsize_t> dims, const std::string& units, const std::string& description);
  void i64(hid_t loc, const std::string& name, const std::vector<std::int64_t>& data,
           const std::string& units, const std::string& description);
  void strings(hid_t loc, const std::string& name, const std::vector<std::string>& data,
               const std::string& units, const std::string& description);

  // Scalar attributes on any object (file, group or dataset); text is a
  // fixed-length UTF-8 string.
  void attr_text(hid_t obj, const std::string& name, const std::string& value);
  void attr_i32(hid_t obj, const std::string& name, std::int32_t value);
  void attr_u64(hid_t obj, const std::string& name, std::uint64_t value);
  void attr_f64(hid_t obj, const std::string& name, double value);

  // Flushes and closes the file; throws if HDF5 could not finish it.
  void close();

 private:
  [[noreturn]] void fail(const std::string& what) const;
  void write_numeric(hid_t loc, const std::string& name, hid_t file_type, hid_t mem_type,
                     const void* data, const std::vector<hsize_t>& dims, const std::string& units,
                     const std::string& description);
  void attr_scalar(hid_t obj, const std::string& name, hid_t file_type, hid_t mem_type,
                   const void* value);

  std::string shown_;
  Id file_;
};

template <class T>
struct Array {
  std::vector<T> data;
  std::vector<hsize_t> dims;  // as stored
};

// Bytes in memory that every Reader of `path` opens instead of the file of
// that name while this lives (HDF5's core driver with a file image), so the
// fuzz targets (fuzz/) feed the readers without the file system. One at a
// time and not thread-safe: for fuzzing and tests only.
class FileImage {
 public:
  FileImage(std::string path, const void* data, std::size_t size);
  ~FileImage();
  FileImage(const FileImage&) = delete;
  FileImage& operator=(const FileImage&) = delete;

  const std::string& path() const { return path_; }
  const void* data() const { return data_; }
  std::size_t size() const { return size_; }

 private:
  std::string path_;
  const void* data_;
  std::size_t size_;
};

// Opens an existing file read-only after checking that it exists and is HDF5
// (or the FileImage of that path).
class Reader {
 public:
  explicit Reader(std::string path);
  const std::string& path() const { return path_; }
  hid_t file() const { return file_.get(); }

  // Whether a link of that name exists at the root ("lines") or below it
  // ("/lines/set").
  bool exists(const std::string& abs_path) const;

  // The size of the file in bytes: no dataset, attribute or string of it can
  // hold more, so every claim of one to be larger is damage.
  std::uint64_t file_bytes() const { return file_bytes_; }

  std::optional<std::string> attr_text(hid_t obj, const std::string& name,
                                       const std::string& where) const;
  std::optional<std::int64_t> attr_int(hid_t obj, const std::string& name,
                                       const std::string& where) const;
  std::optional<std::uint64_t> attr_u64(hid_t obj, const std::string& name,
                                        const std::string& where) const;
  std::optional<double> attr_f64(hid_t obj, const std::string& name,
                                 const std::string& where) const;

  // Numeric datasets by absolute path, converted to the requested type.
  Array<double> f64(const std::string& abs_path) const;
  Array<std::int64_t> i64(const std::string& abs_path) const;
  std::vector<std::string> strings(const std::string& abs_path) const;

  // CSR offsets (item i owns [offsets[i], offsets[i+1])): a 1-D integer
  // dataset of at least one entry, starting at 0, ending at `total`, each
  // entry at least `min_step` above the one before. Whoever indexes with
  // them may then trust every one to lie in [0, total]. `item` names what an
  // entry is ("polygon", "face") for the message.
  std::vector<std::int64_t> offsets(const std::string& abs_path, std::size_t total,
                                    long long min_step, const std::string& item) const;

  // "PATH: WHAT." (a value the file holds is wrong).
  [[noreturn]] void fail(const std::string& what) const;
  // "PATH: is damaged (WHAT)." (HDF5 could not read it, a checksum failed,
  // or a size is beyond what the file could hold).
  [[noreturn]] void damaged(const std::string& what) const;

 private:
  Id open_dataset(const std::string& abs_path) const;
  template <class T>
  Array<T> numeric(const std::string& abs_path, hid_t mem_type) const;
  Id open_scalar_attr(hid_t obj, const std::string& name, const std::string& where) const;
  // Elements of `space` times `element_bytes`, refused as damage beyond the
  // file's size; `what` names the object for the message.
  hsize_t checked_count(hid_t space, std::size_t element_bytes, const std::string& what,
                        std::vector<hsize_t>* dims = nullptr) const;
  std::optional<std::string> read_text_attr(hid_t attr, const std::string& what) const;
  void open_image(const FileImage& image);

  std::string path_;
  std::uint64_t file_bytes_ = 0;
  Id file_;
};

}  // namespace dda::h5
