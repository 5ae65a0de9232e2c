// Discrete Fourier transform of any length (fft.hpp).
#include "dda/analysis/fft.hpp"

#include <cmath>
#include <cstdint>
#include <utility>

#include "dda/common/geometry.hpp"

namespace dda::analysis {

namespace {

bool is_power_of_two(std::size_t n) { return n != 0 && (n & (n - 1)) == 0; }

// In-place forward radix-2 transform; n = x.size() is a power of two.
void radix2(std::vector<Complex>& x) {
  const std::size_t n = x.size();
  if (n < 2) return;
  for (std::size_t i = 1, j = 0; i < n; ++i) {  // bit-reversal permutation
    std::size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(x[i], x[j]);
  }
  // exp(-2 pi i j / n) for j < n/2, each from its own angle.
  std::vector<Complex> twiddle(n / 2);
  for (std::size_t j = 0; j < n / 2; ++j)
    twiddle[j] = std::polar(1.0, -2.0 * kPi * static_cast<double>(j) / static_cast<double>(n));
  for (std::size_t len = 2; len <= n; len <<= 1) {
    const std::size_t half = len / 2, stride = n / len;
    for (std::size_t start = 0; start < n; start += len)
      for (std::size_t j = 0; j < half; ++j) {
        const Complex u = x[start + j];
        const Complex v = x[start + j + half] * twiddle[j * stride];
        x[start + j] = u + v;
        x[start + j + half] = u - v;
      }
  }
}

// Forward transform of any length by Bluestein's chirp-z convolution.
void bluestein(std::vector<Complex>& x) {
  const std::size_t n = x.size();
  std::size_t m = 1;
  while (m < 2 * n - 1) m <<= 1;
  // chirp_j = exp(-i pi j^2 / n); j^2 is reduced modulo 2n first (the chirp's
  // period), exactly in integers, so large j lose no accuracy.
  std::vector<Complex> chirp(n);
  const std::uint64_t period = 2 * static_cast<std::uint64_t>(n);
  for (std::size_t j = 0; j < n; ++j) {
    const std::uint64_t jj = static_cast<std::uint64_t>(j);
    chirp[j] = std::polar(1.0, -kPi * static_cast<double>((jj * jj) % period) / static_cast<double>(n));
  }
  std::vector<Complex> a(m, Complex(0.0, 0.0)), b(m, Complex(0.0, 0.0));
  for (std::size_t j = 0; j < n; ++j) a[j] = x[j] * chirp[j];
  b[0] = std::conj(chirp[0]);
  for (std::size_t j = 1; j < n; ++j) b[j] = b[m - j] = std::conj(chirp[j]);
  radix2(a);
  radix2(b);
  for (std::size_t j = 0; j < m; ++j) a[j] = std::conj(a[j] * b[j]);  // inverse by conjugation
  radix2(a);
  const double scale = 1.0 / static_cast<double>(m);
  for (std::size_t k = 0; k < n; ++k) x[k] = chirp[k] * std::conj(a[k]) * scale;
}

}  // namespace

std::vector<Complex> fft(std::vector<Complex> x, bool inverse) {
  const std::size_t n = x.size();
  if (n < 2) return x;
  // The inverse is the conjugate of the forward transform of the conjugate, over n.
  if (inverse)
    for (Complex& v : x) v = std::conj(v);
  if (is_power_of_two(n))
    radix2(x);
  else
    bluestein(x);
  if (inverse) {
    const double scale = 1.0 / static_cast<double>(n);
    for (Complex& v : x) v = std::conj(v) * scale;
  }
  return x;
}

std::vector<Complex> real_fft(const std::vector<double>& x) {
  std::vector<Complex> c(x.begin(), x.end());
  c = fft(std::move(c));
  c.resize(x.size() / 2 + 1);
  return c;
}

}  // namespace dda::analysis
