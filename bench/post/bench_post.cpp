// SPDX-License-Identifier: GPL-2.0-or-later
// Times the post-processing library on one long signal: the amplitude spectrum (mean removed,
// Hann window, FFTW r2c) and the envelope spectrum (Hilbert envelope of the whole band through
// FFTW, then its amplitude spectrum). Prints one JSON object; run_bench.py compares it with
// numpy/scipy doing the same operations in the same run.
//   bench_post [samples=10000000] [repeats=3] [signal file: raw float64, optional]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "dsp/envelope.h"
#include "dsp/spectrum.h"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// A resistance-like test signal: 1.39 ohm, +8.3 % rectangles at 624.8 Hz lasting 58 us, a
// deterministic pseudo-noise (the same generator as run_bench.py's fallback is not needed:
// run_bench.py passes its own signal file).
std::vector<double> make_signal(std::size_t n)
{
  std::vector<double> x(n);
  std::uint64_t s = 12345;
  for (std::size_t i = 0; i < n; ++i) {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    const double noise = (static_cast<double>(s >> 11) / 9007199254740992.0 - 0.5) * 0.01;
    const double t = static_cast<double>(i) * 1e-6;
    x[i] = 1.39 + (std::fmod(t, 1 / 624.8) < 58e-6 ? 0.115 : 0.0) + noise;
  }
  return x;
}

}  // namespace

int main(int argc, char **argv)
{
  using namespace ohmdem::post;
  const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 10000000;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 3;
  std::vector<double> x;
  if (argc > 3) {
    std::ifstream in(argv[3], std::ios::binary);
    x.resize(n);
    in.read(reinterpret_cast<char *>(x.data()), static_cast<std::streamsize>(n * sizeof(double)));
    if (!in) {
      std::fprintf(stderr, "ERROR: cannot read %zu float64 values from %s\n", n, argv[3]);
      return 1;
    }
  } else {
    x = make_signal(n);
  }
  const double fs = 1e6;
  SpectrumOptions o;  // hann, mean removed, amplitude, whole signal
  double best_spec = 1e300, best_env = 1e300, check_spec = 0, check_env = 0;
  for (int r = 0; r < repeats + 1; ++r) {  // the first round plans FFTW and warms up
    auto t0 = Clock::now();
    const Spectrum s = spectrum(x, fs, o);
    const double ts = seconds_since(t0);
    t0 = Clock::now();
    const std::vector<double> env = envelope(x, fs, {0, 0});
    const Spectrum e = spectrum(env, fs, o);
    const double te = seconds_since(t0);
    if (r > 0) {
      best_spec = std::min(best_spec, ts);
      best_env = std::min(best_env, te);
    }
    check_spec = s.value[s.bins() / 3];
    check_env = e.value[e.bins() / 7];
  }
  std::printf(
      "{\"samples\": %zu, \"repeats\": %d, \"spectrum_s\": %.6f, \"envelope_s\": %.6f, "
      "\"check_spectrum\": %.12g, \"check_envelope\": %.12g}\n",
      n, repeats, best_spec, best_env, check_spec, check_env);
  return 0;
}
