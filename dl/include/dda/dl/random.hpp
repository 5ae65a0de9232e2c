#pragma once
// Seeded random streams that give the same numbers on every platform.
//
// std::uniform_real_distribution and std::normal_distribution are not
// specified bit for bit and differ between standard libraries, so DL draws
// from the raw 64-bit output of std::mt19937_64 (which is fully specified)
// with explicit transforms:
//  * uniform01(): the top 53 bits of one draw times 2^-53, in [0, 1);
//  * symmetric(): 2 * uniform01() - 1, uniform on [-1, 1);
//  * normal(): Box-Muller from two draws, cosine branch only (one normal per
//    two draws). It uses std::log/std::sqrt/std::cos, which glibc rounds
//    correctly or within one ulp; the sequence is identical on one platform
//    and may differ in the last bits across C libraries.
//
// Every generator (a statistical set, the bed thicknesses, a layered set in
// one bed) gets its own stream derived from the scenario seed, a tag and an
// index (derive_seed), so adding a set does not change the lines of another.
#include <cstdint>
#include <random>
#include <string_view>

namespace dda::dl {

// SplitMix64 finaliser: a bijective 64-bit mixer.
std::uint64_t mix64(std::uint64_t x);
// Seed of the stream for (seed, tag, index): mix64 chained over the seed, the
// FNV-1a hash of the tag and the index.
std::uint64_t derive_seed(std::uint64_t seed, std::string_view tag, std::uint64_t index = 0);

class Stream {
 public:
  explicit Stream(std::uint64_t seed) : engine_(seed) {}
  Stream(std::uint64_t seed, std::string_view tag, std::uint64_t index = 0)
      : engine_(derive_seed(seed, tag, index)) {}

  std::uint64_t next() { return engine_(); }
  double uniform01();       // [0, 1)
  double uniform_open01();  // (0, 1), for logarithms
  double symmetric();       // [-1, 1)
  double normal();          // standard normal
  // mean * (1 + randomness * X), X uniform on [-1, 1): the DDA "degree of
  // randomness" bounds the relative deviation from the mean.
  double around(double mean, double randomness) { return mean * (1.0 + randomness * symmetric()); }

 private:
  std::mt19937_64 engine_;
};

}  // namespace dda::dl
