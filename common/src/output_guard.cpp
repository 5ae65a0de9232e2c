#include "dda/common/output_guard.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "dda/common/error.hpp"

namespace dda {
namespace fs = std::filesystem;

namespace {

// The path with symlinks and `..` resolved as far as it exists; the path as
// given if even that fails (it is then compared as spelled).
fs::path real_path(const std::string& p) {
  std::error_code ec;
  fs::path r = fs::weakly_canonical(fs::absolute(p, ec), ec);
  if (ec) r = fs::path(p).lexically_normal();
  return r.has_filename() ? r : r.parent_path();  // "out/" is the folder out
}

// Whether two names reach one file. The inode test catches what no path
// comparison can: a second hard link to the input.
bool same_file(const std::string& a, const std::string& b) {
  struct stat sa {}, sb {};
  if (::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0)
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  return real_path(a) == real_path(b);
}

bool inside(const std::string& file, const std::string& folder) {
  const fs::path f = real_path(file), d = real_path(folder);
  const auto [fi, di] = std::mismatch(f.begin(), f.end(), d.begin(), d.end());
  return di == d.end() && fi != f.end();
}

}  // namespace

void refuse_overwriting_inputs(const std::vector<std::string>& inputs, const std::vector<std::string>& outputs,
                               const std::vector<std::string>& output_folders) {
  for (const std::string& in : inputs) {
    if (in.empty()) continue;
    for (const std::string& out : outputs)
      if (!out.empty() && same_file(out, in))
        throw InputError(out + ": will not write the output over the input " + in +
                         (out == in ? "" : " (they are the same file)") + "; choose another output name.");
    for (const std::string& dir : output_folders)
      if (!dir.empty() && inside(in, dir))
        throw InputError(dir + ": will not write into this output folder, it holds the input " + in +
                         "; choose another output folder.");
  }
}

}  // namespace dda
