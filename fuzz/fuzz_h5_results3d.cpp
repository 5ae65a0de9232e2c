// 3D results files with their checkpoint (df3::read_results3_h5 with the
// state, as `dda df --resume` reads them).
#include "dda/df/io/results3d.hpp"
#include "fuzz_h5_image.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  dda::fuzz::read_h5_image(data, size, [](const std::string& path) { dda::df3::read_results3_h5(path); });
  return 0;
}
