// SPDX-License-Identifier: GPL-2.0-or-later
#include "dsp/fft.h"

#include <fftw3.h>

#include <iterator>
#include <map>
#include <memory>
#include <tuple>

#include "core/error.h"

namespace ohmdem::post {

namespace {

struct PlanDeleter {
  void operator()(fftw_plan_s *p) const { fftw_destroy_plan(p); }
};
using Plan = std::unique_ptr<fftw_plan_s, PlanDeleter>;

struct FftwBuffer {
  explicit FftwBuffer(std::size_t bytes) : p(fftw_malloc(bytes)) {}
  ~FftwBuffer() { fftw_free(p); }
  FftwBuffer(const FftwBuffer &) = delete;
  FftwBuffer &operator=(const FftwBuffer &) = delete;
  void *p;
};

enum class Kind { R2C, C2R, C2C_FORWARD, C2C_BACKWARD };

// A plan is made on FFTW-aligned scratch arrays; they can be freed afterwards because plans are
// only run through the new-array functions, on arrays of the same alignment (else via a copy).
class PlanCache {
 public:
  static constexpr std::size_t kLargePlan = std::size_t(1) << 16;

  fftw_plan get(Kind kind, std::size_t n, int &alignment)
  {
    auto key = std::make_tuple(kind, n);
    auto it = plans_.find(key);
    if (it == plans_.end()) {
      const int in = static_cast<int>(n);
      if (static_cast<std::size_t>(in) != n) throw Error("transform size too large for FFTW");
      fftw_plan p = nullptr;
      if (kind == Kind::R2C) {
        FftwBuffer a(sizeof(double) * n), b(sizeof(fftw_complex) * (n / 2 + 1));
        p = fftw_plan_dft_r2c_1d(in, static_cast<double *>(a.p), static_cast<fftw_complex *>(b.p),
                                 FFTW_ESTIMATE);
        alignment = fftw_alignment_of(static_cast<double *>(a.p));
      } else if (kind == Kind::C2R) {
        FftwBuffer a(sizeof(fftw_complex) * (n / 2 + 1)), b(sizeof(double) * n);
        p = fftw_plan_dft_c2r_1d(in, static_cast<fftw_complex *>(a.p), static_cast<double *>(b.p),
                                 FFTW_ESTIMATE);
        alignment = fftw_alignment_of(static_cast<double *>(b.p));
      } else {
        FftwBuffer a(sizeof(fftw_complex) * n);
        auto *c = static_cast<fftw_complex *>(a.p);
        p = fftw_plan_dft_1d(in, c, c, kind == Kind::C2C_FORWARD ? FFTW_FORWARD : FFTW_BACKWARD,
                             FFTW_ESTIMATE);
        alignment = fftw_alignment_of(reinterpret_cast<double *>(c));
      }
      if (!p) throw Error("FFTW could not plan a transform of size " + std::to_string(n));
      // a plan holds twiddle tables of about its size (a transform of 1e7 points: ~70 MB):
      // plans of long transforms are not accumulated, only the last one is kept
      if (n > kLargePlan)
        for (auto old = plans_.begin(); old != plans_.end();)
          old = std::get<1>(old->first) > kLargePlan ? plans_.erase(old) : std::next(old);
      it = plans_.emplace(key, Entry{Plan(p), alignment}).first;
    }
    alignment = it->second.alignment;
    return it->second.plan.get();
  }
  std::size_t size() const { return plans_.size(); }

 private:
  struct Entry {
    Plan plan;
    int alignment;
  };
  std::map<std::tuple<Kind, std::size_t>, Entry> plans_;
};

PlanCache &cache()
{
  static PlanCache c;
  return c;
}

}  // namespace

void rfft(const double *in, std::size_t n, std::vector<Complex> &out)
{
  if (n == 0) throw Error("internal: FFT of an empty array");
  out.resize(n / 2 + 1);
  int alignment = 0;
  fftw_plan p = cache().get(Kind::R2C, n, alignment);
  auto *o = reinterpret_cast<fftw_complex *>(out.data());
  // the r2c plan preserves its input (FFTW's default for out-of-place r2c)
  auto *i = const_cast<double *>(in);
  if (fftw_alignment_of(i) == alignment &&
      fftw_alignment_of(reinterpret_cast<double *>(o)) == alignment) {
    fftw_execute_dft_r2c(p, i, o);
    return;
  }
  FftwBuffer a(sizeof(double) * n), b(sizeof(fftw_complex) * (n / 2 + 1));
  std::copy(in, in + n, static_cast<double *>(a.p));
  fftw_execute_dft_r2c(p, static_cast<double *>(a.p), static_cast<fftw_complex *>(b.p));
  const auto *bc = static_cast<const Complex *>(b.p);
  std::copy(bc, bc + out.size(), out.begin());
}

void irfft(std::vector<Complex> &in, std::size_t n, double *out)
{
  if (n == 0 || in.size() != n / 2 + 1) throw Error("internal: bad inverse real FFT sizes");
  int alignment = 0;
  fftw_plan p = cache().get(Kind::C2R, n, alignment);
  auto *i = reinterpret_cast<fftw_complex *>(in.data());
  if (fftw_alignment_of(reinterpret_cast<double *>(i)) == alignment &&
      fftw_alignment_of(out) == alignment) {
    fftw_execute_dft_c2r(p, i, out);
    return;
  }
  FftwBuffer a(sizeof(fftw_complex) * in.size()), b(sizeof(double) * n);
  std::copy(in.begin(), in.end(), static_cast<Complex *>(a.p));
  fftw_execute_dft_c2r(p, static_cast<fftw_complex *>(a.p), static_cast<double *>(b.p));
  std::copy(static_cast<double *>(b.p), static_cast<double *>(b.p) + n, out);
}

void cfft(std::vector<Complex> &data, int sign)
{
  const std::size_t n = data.size();
  if (n == 0) throw Error("internal: FFT of an empty array");
  int alignment = 0;
  fftw_plan p = cache().get(sign < 0 ? Kind::C2C_FORWARD : Kind::C2C_BACKWARD, n, alignment);
  auto *d = reinterpret_cast<fftw_complex *>(data.data());
  if (fftw_alignment_of(reinterpret_cast<double *>(d)) == alignment) {
    fftw_execute_dft(p, d, d);
    return;
  }
  FftwBuffer a(sizeof(fftw_complex) * n);
  auto *ac = static_cast<Complex *>(a.p);
  std::copy(data.begin(), data.end(), ac);
  fftw_execute_dft(p, static_cast<fftw_complex *>(a.p), static_cast<fftw_complex *>(a.p));
  std::copy(ac, ac + n, data.begin());
}

std::size_t fft_plan_count()
{
  return cache().size();
}

}  // namespace ohmdem::post
