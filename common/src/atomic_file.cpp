#include "dda/common/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <system_error>

#include "dda/common/error.hpp"

namespace dda {
namespace fs = std::filesystem;

namespace {

// A name nobody else will pick: process id, a per-process counter and a few
// random bits (two processes with recycled pids, or two threads, must not
// collide).
std::string unique_suffix() {
  static std::atomic<unsigned long> counter{0};
  thread_local std::mt19937_64 rng{std::random_device{}()};
  std::ostringstream s;
  s << ".tmp-" << ::getpid() << '-' << counter++ << '-' << std::hex << (rng() & 0xffffffULL);
  return s.str();
}

// Removes the trailing full stop of a system message, if any, so that our
// sentence ends with exactly one.
std::string reason_of(const std::error_code& ec) {
  std::string r = ec.message();
  while (!r.empty() && (r.back() == '.' || r.back() == '\n')) r.pop_back();
  return r;
}

std::string reason_of(int err) { return reason_of(std::error_code(err, std::generic_category())); }

// Forces what was written to `path` (a file, or a folder's list of names)
// onto the disk; the errno of the first failure, or 0.
int sync_to_disk(const std::string& path, bool folder) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | (folder ? O_DIRECTORY : 0));
  if (fd < 0) return errno;
  int err = ::fsync(fd) == 0 ? 0 : errno;
  if (::close(fd) != 0 && err == 0) err = errno;
  return err;
}

}  // namespace

AtomicOutput::AtomicOutput(std::string final_path) : final_path_(std::move(final_path)) {
  if (final_path_.empty()) throw InputError("An output file name is empty.");
  const fs::path target(final_path_);
  fs::path folder = target.parent_path();
  const std::string name = target.filename().string();
  if (name.empty() || name == "." || name == "..")
    throw InputError(final_path_ + ": cannot write: the path names a folder, not a file.");
  std::error_code ec;
  if (folder.empty()) folder = ".";
  if (!fs::is_directory(folder, ec))
    throw InputError(final_path_ + ": cannot write: the folder " + folder.string() +
                     " does not exist.");
  if (fs::is_directory(target, ec))
    throw InputError(final_path_ + ": cannot write: a folder of that name exists.");
  temp_path_ = (target.parent_path() / ("." + name + unique_suffix())).string();
}

AtomicOutput::~AtomicOutput() {
  if (committed_) return;
  std::error_code ec;
  fs::remove(temp_path_, ec);  // nothing to report from a destructor
}

void AtomicOutput::commit() {
  if (committed_) return;
  std::error_code ec;
  if (!fs::exists(temp_path_, ec))
    throw InputError(final_path_ + ": cannot write: the temporary file " + temp_path_ +
                     " was never written.");
  // The data first: without it a crash soon after the rename can leave the
  // final name on an empty or partial file (ext4 and others write the rename
  // before the data). A full disk also shows up here, on filesystems that
  // allocate late, as ENOSPC from fsync.
  if (const int err = sync_to_disk(temp_path_, false))
    throw InputError(final_path_ + ": cannot write: " + reason_of(err) + ".");
  fs::rename(temp_path_, final_path_, ec);
  if (ec) throw InputError(final_path_ + ": cannot write: " + reason_of(ec) + ".");
  committed_ = true;
  // Then the folder, so that the new name itself survives a crash. Some
  // filesystems cannot sync a folder (EINVAL): nothing more can be done there.
  fs::path folder = fs::path(final_path_).parent_path();
  if (folder.empty()) folder = ".";
  if (const int err = sync_to_disk(folder.string(), true); err != 0 && err != EINVAL)
    throw InputError(final_path_ + ": written, but the folder " + folder.string() +
                     " could not be synced to disk: " + reason_of(err) + ".");
}

void write_text_atomically(const std::string& path, const std::string& text) {
  AtomicOutput out(path);
  {
    std::ofstream f(out.temp_path(), std::ios::binary | std::ios::trunc);
    if (!f)
      throw InputError(path + ": cannot write: " + std::strerror(errno) + ".");
    f.write(text.data(), static_cast<std::streamsize>(text.size()));
    f.flush();
    if (!f) throw InputError(path + ": cannot write: " + std::strerror(errno) + ".");
    f.close();
    if (f.fail()) throw InputError(path + ": cannot write: closing the file failed.");
  }
  out.commit();
}

}  // namespace dda
