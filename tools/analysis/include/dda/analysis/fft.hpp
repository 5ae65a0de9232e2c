#pragma once
// Discrete Fourier transform of any length, O(N log N):
//   X_k = sum_{n=0}^{N-1} x_n exp(-2 pi i k n / N),   k = 0 .. N-1
// (no scaling; the inverse carries the 1/N).
//
// Powers of two use an iterative radix-2 transform. Other lengths use
// Bluestein's chirp-z identity, k n = (k^2 + n^2 - (k - n)^2) / 2, which turns
// the transform into a convolution done with power-of-two transforms of
// length M >= 2N - 1. Bluestein rather than zero-padding the signal to a
// power of two because padding changes the transform itself (the bins move
// to k / (M dt) and the amplitudes of a padded record are those of a longer,
// partly silent one); the spectra tools want the exact DFT of the N samples
// they were given, so that a sine with an integer number of cycles falls on
// one bin and Parseval's theorem holds for the record as it is.
//
// Twiddle factors and chirps are computed directly from their angles (the
// chirp's n^2 reduced modulo 2N in integers), not by recurrence, so the
// round-off stays near 1e-15 relative for lengths up to millions.
#include <complex>
#include <vector>

namespace dda::analysis {

using Complex = std::complex<double>;

// Forward transform (as above); the inverse with `inverse` (sign +, and 1/N).
std::vector<Complex> fft(std::vector<Complex> x, bool inverse = false);

// The first floor(N/2) + 1 terms X_0 .. X_{N/2} of the transform of real
// samples (the rest are their complex conjugates).
std::vector<Complex> real_fft(const std::vector<double>& x);

}  // namespace dda::analysis
