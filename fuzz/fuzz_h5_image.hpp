#pragma once
// HDF5 readers fed from memory: the input is the file's bytes, opened by
// the reader through h5::FileImage (HDF5's core driver), so a run touches no
// file and every input is the whole file as the reader would see it.
#include "dda/common/h5_util.hpp"
#include "fuzz_support.hpp"

namespace dda::fuzz {

// Runs `read(path)` with the bytes as the file at `path`.
template <class Read>
void read_h5_image(const std::uint8_t* data, std::size_t size, Read&& read) {
  static const std::string path = "fuzz.h5";
  const h5::FileImage image(path, data, size);
  refuse_only_with_input_errors([&] { read(path); });
}

}  // namespace dda::fuzz
