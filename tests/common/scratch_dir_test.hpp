#pragma once
// A test fixture with a folder of its own under the system's temporary
// folder, named after the process and the test (so parallel ctest runs do
// not meet), made empty before each test and removed after it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "dda/common/error.hpp"
#include "input_error_of.hpp"

namespace dda::testing {

class ScratchDirTest : public ::testing::Test {
 protected:
  explicit ScratchDirTest(std::string prefix) : prefix_(std::move(prefix)) {}

  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           (prefix_ + "-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  // The folder's file names, sorted.
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  // The message of the InputError f throws (input_error_of.hpp).
  template <class F>
  static std::string error_of(F&& f) {
    return input_error_of(std::forward<F>(f));
  }

  std::filesystem::path dir_;

 private:
  std::string prefix_;
};

}  // namespace dda::testing
