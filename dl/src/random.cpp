#include "dda/dl/random.hpp"

#include <cmath>

#include "dda/common/geometry.hpp"

namespace dda::dl {

std::uint64_t mix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

std::uint64_t derive_seed(std::uint64_t seed, std::string_view tag, std::uint64_t index) {
  std::uint64_t h = 0xCBF29CE484222325ULL;  // FNV-1a offset basis
  for (const char c : tag) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001B3ULL;  // FNV prime
  }
  return mix64(mix64(mix64(seed) ^ h) ^ index);
}

double Stream::uniform01() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

double Stream::uniform_open01() { return (static_cast<double>(engine_() >> 11) + 0.5) * 0x1.0p-53; }

double Stream::symmetric() { return 2.0 * uniform01() - 1.0; }

double Stream::normal() {
  const double u1 = uniform_open01();
  const double u2 = uniform01();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
}

}  // namespace dda::dl
