#pragma once
// Atomic output: write to a temporary name in the same folder, then rename.
// An interrupted run never leaves a half-written file under the final name,
// and a committed file is on the disk: the temporary is synced before the
// rename and the folder after it, so a power cut cannot leave the final name
// on an empty file (docs/reliability.md). Every output file of the project,
// HDF5 or text, is written this way.
#include <string>

namespace dda {

class AtomicOutput {
 public:
  explicit AtomicOutput(std::string final_path);
  ~AtomicOutput();  // removes the temporary file unless commit() succeeded
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  const std::string& temp_path() const { return temp_path_; }
  const std::string& final_path() const { return final_path_; }
  // Syncs the temporary file, renames it onto the final path and syncs the
  // folder (InputError if any of it fails).
  void commit();

 private:
  std::string final_path_;
  std::string temp_path_;
  bool committed_ = false;
};

void write_text_atomically(const std::string& path, const std::string& text);

}  // namespace dda
