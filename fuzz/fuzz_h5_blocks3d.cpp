// 3D blocks files (read_polyhedra_h5).
#include "dda/common/model_io3d.hpp"
#include "fuzz_h5_image.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  dda::fuzz::read_h5_image(data, size, [](const std::string& path) { dda::read_polyhedra_h5(path); });
  return 0;
}
