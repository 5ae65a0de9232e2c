#pragma once
// Helpers shared by the DL tests.
#include <gtest/gtest.h>

#include <string>

#include "dda/common/error.hpp"
#include "dda/common/yaml_reader.hpp"
#include "dda/dl/generate.hpp"

namespace dda::dl::test {

inline DlResult run(const std::string& yaml, const std::string& label = "test.yaml") {
  return generate_from_scenario(YamlNode::load_string(yaml, label));
}

// The InputError message of running `yaml`, or "" if it ran.
inline std::string error_of(const std::string& yaml, const std::string& label = "test.yaml") {
  try {
    run(yaml, label);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Built by appending: GCC 12 warns falsely (-Warray-bounds) about
// std::string(literal) + "/" + name once gtest's headers are precompiled.
inline std::string data_path(const std::string& name) {
  std::string path = DDA_TEST_DATA_DIR;
  path += '/';
  path += name;
  return path;
}

}  // namespace dda::dl::test
