#pragma once
// Errors the user can act on.
//
// Every problem with the user's input (a scenario key, a file, a command-line
// value) is reported as one InputError whose message is a single sentence that
// names the file, the key or line, and what is wrong.  The `dda` program prints
// it on stderr and exits non-zero; library code never prints or exits itself.
#include <stdexcept>
#include <string>

namespace dda {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& sentence) : std::runtime_error(sentence) {}
};

// A failure of the program itself (a broken invariant), not of the input.
class InternalError : public std::logic_error {
 public:
  explicit InternalError(const std::string& what) : std::logic_error(what) {}
};

}  // namespace dda
