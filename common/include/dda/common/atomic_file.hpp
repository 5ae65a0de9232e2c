#pragma once
// Atomic output: write to a temporary name in the same folder, then rename.
// An interrupted run never leaves a half-written file under the final name.
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
  // Renames the temporary file onto the final path (InputError if it fails).
  void commit();

 private:
  std::string final_path_;
  std::string temp_path_;
  bool committed_ = false;
};

void write_text_atomically(const std::string& path, const std::string& text);

}  // namespace dda
