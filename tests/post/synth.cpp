// SPDX-License-Identifier: GPL-2.0-or-later
#include "synth.h"

#include <cmath>

#include "test_constants.h"

namespace ohmdem::post::test {

namespace {
using ohmdem::test::kPi;
}

Gaussian::Gaussian(std::uint64_t seed) : state_(seed * 0x9E3779B97F4A7C15ull + 1) {}

double Gaussian::next_uniform()
{
  // splitmix64: fully specified, identical everywhere
  std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return (static_cast<double>(z >> 11) + 0.5) * (1.0 / 9007199254740992.0);
}

double Gaussian::operator()()
{
  const double u1 = next_uniform(), u2 = next_uniform();
  return std::sqrt(-2 * std::log(u1)) * std::cos(2 * kPi * u2);
}

DefectSignal defect_signal(const BearingGeometry &g, const DefectSpec &spec)
{
  const double fr = spec.omega_inner / (2 * kPi);
  const DefectFrequencies k = defect_frequencies(g, fr);
  const double size = spec.size_deg * kPi / 180;
  DefectSignal out;
  double f = 0, width = 0;
  if (spec.kind == "inner") {
    f = k.bpfi;
    width = size / (2 * kPi * (k.fr - k.ftf));
  } else if (spec.kind == "outer") {
    f = k.bpfo;
    width = size / (2 * kPi * k.ftf);
  } else if (spec.kind == "ball") {
    f = 2 * k.bsf;
    width = size / (2 * kPi * k.bsf);
  } else if (spec.kind == "cage") {
    f = k.ftf;
    width = 4 * size / (2 * kPi * k.ftf);
  }
  f *= 1 - spec.slip;
  out.frequency = f;
  out.width_s = width;
  const auto n = static_cast<std::size_t>(std::llround(spec.duration * spec.rate));
  std::vector<double> clean(n, 0.0);
  if (f > 0) {
    const double phase0 = 0.37 / f;  // first pulse not at t = 0
    for (std::size_t i = 0; i < n; ++i) {
      const double t = static_cast<double>(i) / spec.rate;
      const double u = std::fmod(t + 1 / f - phase0, 1 / f);
      if (u < width) {
        double a = spec.step * spec.level;
        if (spec.kind == "ball")
          a *= 1 - spec.modulation / 2 + spec.modulation / 2 * std::cos(2 * kPi * k.ftf * t);
        clean[i] = a;
      }
    }
  }
  double mean = 0, var = 0;
  for (double v : clean) mean += v;
  mean /= static_cast<double>(n);
  for (double v : clean) var += (v - mean) * (v - mean);
  var /= static_cast<double>(n);
  if (var == 0) var = std::pow(spec.step * spec.level, 2) * 0.03;  // healthy: noise scale only
  out.noise_sigma = spec.snr_db < 1e8 ? std::sqrt(var / std::pow(10, spec.snr_db / 10)) : 0;
  Gaussian noise(spec.seed);
  out.signal.x.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    out.signal.x[i] = spec.level + clean[i] + (out.noise_sigma > 0 ? out.noise_sigma * noise() : 0);
  out.signal.rate = spec.rate;
  out.signal.name = "R";
  return out;
}

std::vector<double> sine(std::size_t n, double rate, double f, double amplitude, double phase)
{
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i)
    x[i] = amplitude * std::sin(2 * kPi * f * static_cast<double>(i) / rate + phase);
  return x;
}

}  // namespace ohmdem::post::test
