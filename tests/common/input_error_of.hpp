#pragma once
// The message of the InputError a call throws: what the common tests
// compare with the sentence a user would read.
#include <gtest/gtest.h>

#include <string>

#include "dda/common/error.hpp"

namespace dda::testing {

// Runs f, expects an InputError and returns its message ("" and a failure
// if none is thrown).
template <class F>
std::string input_error_of(F&& f) {
  try {
    f();
  } catch (const dda::InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return "";
}

}  // namespace dda::testing
