#pragma once
// The mutations of the standalone fuzz driver (standalone_driver.cpp): the
// byte-level changes libFuzzer makes most often, drawn from a small PRNG of
// our own so that a run is the same on every compiler and standard library
// (std::uniform_int_distribution is not: its algorithm is the library's).
//
// Mutation i of a run with seed S depends on S and i only (Rng::for_iteration),
// so any one of them can be made again alone (--seed S --iteration i).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace dda::fuzz {

using Bytes = std::vector<std::uint8_t>;

// SplitMix64 (Steele, Lea, Flood 2014): one 64-bit state, a full period,
// and good enough mixing to choose positions and operators.
class Rng {
 public:
  explicit Rng(std::uint64_t state) : state_(state) {}

  // The generator of mutation `iteration` of the run with `seed`.
  static Rng for_iteration(std::uint64_t seed, std::uint64_t iteration) {
    Rng mixer(seed ^ (iteration * 0xD1B54A32D192ED03ull));
    return Rng(mixer.next());
  }

  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  // A number in [0, n) (n > 0). The modulo bias, below 2^-40 for the sizes
  // here, does not matter for choosing where to mutate.
  std::size_t below(std::size_t n) { return static_cast<std::size_t>(next() % n); }

  // A run length: short runs are the most useful, long ones still happen.
  std::size_t run_length(std::size_t most) {
    const std::size_t limit = std::min<std::size_t>(most, below(4) == 0 ? 256 : 16);
    return limit == 0 ? 0 : 1 + below(limit);
  }

 private:
  std::uint64_t state_;
};

// Bytes that sit at the edges of signed and unsigned types, and the
// characters that delimit text formats.
inline constexpr std::array<std::uint8_t, 10> kInterestingBytes = {0x00, 0xff, 0x7f, 0x80, 0x01, 0xfe,
                                                                   '\n', ' ', ',', '-'};

// Numbers at the limits of what text readers convert: beyond int, long and
// double, denormal, not finite, negative zero.
inline constexpr std::array<std::string_view, 12> kExtremeNumbers = {
    "0", "-1", "-0", "2147483648", "-9223372036854775809", "18446744073709551616",
    "1e308", "1e309", "4.9e-324", "nan", "inf", "6e68"};

// One mutation of `b`, kept within `max_size` bytes; `other` is a second
// input (a seed) for the splices. Returns nothing: an operator that cannot
// apply (an empty input to flip) leaves `b` as it was.
inline void mutate_once(Bytes& b, const Bytes& other, std::size_t max_size, Rng& rng) {
  const auto insert_at = [&](std::size_t pos, auto first, auto last) {
    const std::size_t room = max_size > b.size() ? max_size - b.size() : 0;
    const std::size_t n = std::min<std::size_t>(room, static_cast<std::size_t>(last - first));
    b.insert(b.begin() + static_cast<std::ptrdiff_t>(pos), first, first + static_cast<std::ptrdiff_t>(n));
  };
  switch (rng.below(10)) {
    case 0:  // flip one bit
      if (!b.empty()) b[rng.below(b.size())] ^= static_cast<std::uint8_t>(1u << rng.below(8));
      break;
    case 1:  // one byte to an interesting value
      if (!b.empty()) b[rng.below(b.size())] = kInterestingBytes[rng.below(kInterestingBytes.size())];
      break;
    case 2:  // one byte to any value
      if (!b.empty()) b[rng.below(b.size())] = static_cast<std::uint8_t>(rng.next());
      break;
    case 3: {  // insert a run: one byte repeated, or random bytes
      const std::size_t pos = rng.below(b.size() + 1);
      Bytes run(rng.run_length(max_size));
      const bool repeated = rng.below(2) == 0;
      const auto fill = static_cast<std::uint8_t>(rng.next());
      for (auto& c : run) c = repeated ? fill : static_cast<std::uint8_t>(rng.next());
      insert_at(pos, run.begin(), run.end());
      break;
    }
    case 4: {  // erase a run
      if (b.empty()) break;
      const std::size_t pos = rng.below(b.size());
      const std::size_t n = rng.run_length(b.size() - pos);
      b.erase(b.begin() + static_cast<std::ptrdiff_t>(pos), b.begin() + static_cast<std::ptrdiff_t>(pos + n));
      break;
    }
    case 5:  // truncate
      b.resize(rng.below(b.size() + 1));
      break;
    case 6: {  // duplicate a chunk somewhere else
      if (b.empty()) break;
      const std::size_t from = rng.below(b.size());
      const std::size_t n = rng.run_length(b.size() - from);
      const Bytes chunk(b.begin() + static_cast<std::ptrdiff_t>(from),
                        b.begin() + static_cast<std::ptrdiff_t>(from + n));
      insert_at(rng.below(b.size() + 1), chunk.begin(), chunk.end());
      break;
    }
    case 7: {  // splice: this input's head, the other's tail
      const std::size_t head = rng.below(b.size() + 1);
      const std::size_t tail_from = rng.below(other.size() + 1);
      b.resize(head);
      insert_at(b.size(), other.begin() + static_cast<std::ptrdiff_t>(tail_from), other.end());
      break;
    }
    case 8: {  // a chunk of the other input inserted
      if (other.empty()) break;
      const std::size_t from = rng.below(other.size());
      const std::size_t n = rng.run_length(other.size() - from);
      insert_at(rng.below(b.size() + 1), other.begin() + static_cast<std::ptrdiff_t>(from),
                other.begin() + static_cast<std::ptrdiff_t>(from + n));
      break;
    }
    default: {  // an extreme number in place of a run of digits (or inserted)
      const std::string_view number = kExtremeNumbers[rng.below(kExtremeNumbers.size())];
      std::size_t pos = rng.below(b.size() + 1);
      const auto is_digit = [](std::uint8_t c) { return c >= '0' && c <= '9'; };
      const auto digit = std::find_if(b.begin() + static_cast<std::ptrdiff_t>(pos), b.end(), is_digit);
      std::size_t end = pos;
      if (digit != b.end()) {
        pos = static_cast<std::size_t>(digit - b.begin());
        end = pos;
        while (end < b.size() && (is_digit(b[end]) || b[end] == '.' || b[end] == 'e')) ++end;
      }
      b.erase(b.begin() + static_cast<std::ptrdiff_t>(pos), b.begin() + static_cast<std::ptrdiff_t>(end));
      insert_at(pos, number.begin(), number.end());
      break;
    }
  }
}

// A mutant of `base`: one to four mutations stacked, as libFuzzer does.
inline Bytes mutant(const Bytes& base, const Bytes& other, std::size_t max_size, Rng& rng) {
  Bytes b = base;
  const std::size_t count = 1 + rng.below(4);
  for (std::size_t k = 0; k < count; ++k) mutate_once(b, other, max_size, rng);
  return b;
}

}  // namespace dda::fuzz
