// DDA for Windows geometry files, .geo (dl::import_geo, `dda dl model.geo`).
#include "dda/dl/generate.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = dda::fuzz::scratch_file(data, size, ".geo");
  dda::fuzz::refuse_only_with_input_errors([&] { dda::dl::import_geo(path); });
  return 0;
}
