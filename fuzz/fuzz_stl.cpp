// STL surfaces, text and binary (read_stl), then the closed-surface check
// every scenario applies to a domain or excavation surface.
#include "dda/common/triangle_mesh.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = dda::fuzz::scratch_file(data, size, ".stl");
  dda::fuzz::refuse_only_with_input_errors([&] {
    const dda::TriangleMesh mesh = dda::read_stl(path);
    dda::check_closed_surface(mesh, path);
  });
  return 0;
}
