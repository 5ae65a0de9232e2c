// 2D fracture traces as CSV (dl::read_traces_csv), as `traces: {file:}` of a
// scenario names them.
#include "dda/dl/import.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = dda::fuzz::scratch_file(data, size, ".csv");
  dda::fuzz::refuse_only_with_input_errors([&] { dda::dl::read_traces_csv(path); });
  return 0;
}
