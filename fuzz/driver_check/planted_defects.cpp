// A fuzz target with defects planted on purpose, for check.sh: it shows
// that the standalone driver (../standalone_driver.cpp) reports each kind of
// finding, saves the input that caused it, and makes its mutants the same
// way every time. Each defect is chosen by what the input is.
#include <unistd.h>

#include <csignal>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "../fuzz_support.hpp"

namespace {

int planted(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  if (text == "refused") throw dda::InputError("r.txt: planted refusal.");  // the right answer: no finding
  if (text == "escape") throw std::out_of_range("planted escape");
  if (text == "segv") std::raise(SIGSEGV);
  if (text == "abort") std::abort();
  if (text == "hang")
    for (;;) pause();  // until the driver's time limit
  if (text == "alloc") {
    std::vector<char> huge(std::size_t{3} << 30, 'x');  // beyond --memory-mb 1024
    return huge[size];
  }
  // Reached only by mutation: a seed "abcdef" whose third byte becomes 0x80
  // (one of the driver's interesting bytes, or a random one).
  if (size == 6 && text.compare(0, 2, "ab") == 0 && data[2] == 0x80) throw std::logic_error("planted byte");
  return 0;
}

}  // namespace

// As every real target does: an InputError is the reader's right answer.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  dda::fuzz::refuse_only_with_input_errors([&] { planted(data, size); });
  return 0;
}
