// SPDX-License-Identifier: GPL-2.0-or-later
// Spectral windows (periodic / "DFT-even" cosine sums, as scipy.signal.get_window), their
// amplitude (coherent gain) and noise (ENBW) corrections, and the exact transform of each
// window, used to interpolate spectral peaks.
#ifndef OHMDEM_POST_WINDOW_H
#define OHMDEM_POST_WINDOW_H

#include <cstddef>
#include <string>
#include <vector>

namespace ohmdem::post {

enum class WindowKind { Rectangular, Hann, Hamming, Blackman, BlackmanHarris, Flattop };

WindowKind parse_window(const std::string &name);  // throws Error listing the names
const char *window_name(WindowKind w);
const char *window_names();  // "rect|hann|hamming|blackman|blackmanharris|flattop"

// w[j] = sum_m (-1)^m a_m cos(2 pi m j / n), j = 0..n-1
std::vector<double> make_window(WindowKind w, std::size_t n);

// |W(u)| / W(0): magnitude of the window's DFT at an offset of u bins of an nfft-point
// transform (closed form for cosine sums; nfft >= n when zero padded). 1 at u = 0.
double window_kernel(WindowKind w, std::size_t n, std::size_t nfft, double u);
// The same kernel with W(0) computed once (a peak's refinement evaluates it ~120 times).
class WindowKernel {
 public:
  WindowKernel(WindowKind w, std::size_t n, std::size_t nfft);
  double operator()(double u) const;

 private:
  WindowKind w_;
  std::size_t n_, nfft_;
  double norm0_;  // |W(0)|
};

// Half-width of the main lobe in bins of the unpadded transform (1 rect, 2 hann/hamming, ...).
double main_lobe_half_width(WindowKind w);

}  // namespace ohmdem::post

#endif
