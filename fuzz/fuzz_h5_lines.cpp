// 2D lines files (read_lines_h5), and the format probe `dda info` runs on
// any HDF5 file (h5_format_of).
#include "dda/common/model_io.hpp"
#include "fuzz_h5_image.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  dda::fuzz::read_h5_image(data, size, [](const std::string& path) {
    dda::h5_format_of(path);
    dda::read_lines_h5(path);
  });
  return 0;
}
