// SPDX-License-Identifier: GPL-2.0-or-later
// FFTW behind a small interface (PIMPL: including this header does not pull in fftw3.h).
// Plans are made once per size and kind with FFTW_ESTIMATE (deterministic) and reused through
// FFTW's new-array execute functions; of the plans longer than 65536 points only the last one
// is kept (their twiddle tables are as large as a signal). Not thread-safe (the tool is
// single-threaded).
#ifndef OHMDEM_POST_FFT_H
#define OHMDEM_POST_FFT_H

#include <complex>
#include <cstddef>
#include <vector>

namespace ohmdem::post {

using Complex = std::complex<double>;

// Real-to-complex forward transform of in[0..n): out gets n/2 + 1 bins, unnormalised
// (X_k = sum x_j e^{-2 pi i jk/n}).
void rfft(const double *in, std::size_t n, std::vector<Complex> &out);
// Complex-to-real backward transform of a half spectrum in[0..n/2] (destroyed), unnormalised:
// out[0..n) = sum over the full Hermitian spectrum (n x the inverse).
void irfft(std::vector<Complex> &in, std::size_t n, double *out);
// Complex transform in place, unnormalised. sign -1: forward, +1: backward (inverse x n).
void cfft(std::vector<Complex> &data, int sign);

// Number of distinct plans held (for tests of the plan cache).
std::size_t fft_plan_count();

}  // namespace ohmdem::post

#endif
