// FracMan .fab fracture files (dl::read_fab).
#include "dda/dl/import3d.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = dda::fuzz::scratch_file(data, size, ".fab");
  dda::fuzz::refuse_only_with_input_errors([&] { dda::dl::read_fab(path); });
  return 0;
}
