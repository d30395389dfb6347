// SPDX-License-Identifier: GPL-2.0-or-later
// The detection stage of `diagnose` (post/detect.h): the Gaussian sampling laws against scipy
// (reference/detect_reference.txt, tests/post/make_detect_reference.py), the false-alarm rate
// measured on seeded Gaussian noise, an impulsive record no family explains ('unidentified'),
// and the baseline tests (the measured CWRU records: validation/test_real_records_detect.cpp).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "bearing/diagnose.h"
#include "cli_run.h"
#include "core/error.h"
#include "dsp/acquire.h"
#include "dsp/detect.h"
#include "dsp/envelope.h"
#include "dsp/spectrum.h"
#include "io/json.h"
#include "io/load_signal.h"
#include "synth.h"
#include "test_constants.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

using test::CliRun;

using ohmdem::test::kPi;

bool close_rel(double a, double b, double tol)
{
  return std::fabs(a - b) <= tol * std::max(std::fabs(b), 1e-300);
}

TEST(Detect, GaussianLawsAgreeWithScipy)
{
  std::ifstream in(test::reference("detect_reference.txt"));
  ASSERT_TRUE(in) << "run tests/post/make_detect_reference.py";
  std::string line;
  int cases = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    std::string kind;
    ls >> kind;
    ++cases;
    if (kind == "kurtosis") {
      double n, b2, z, p;
      ls >> n >> b2 >> z >> p;
      if (b2 < 3 * (n - 1) / (n + 1) && z > 0) continue;  // scipy's sign-flipped branch
      EXPECT_NEAR(kurtosis_z(b2, n), z, 1e-9 * std::max(1.0, std::fabs(z))) << line;
      if (p > 1e-290)
        EXPECT_TRUE(close_rel(kurtosis_sf(b2, n), p, 1e-9)) << line << ": " << kurtosis_sf(b2, n);
      else
        EXPECT_LT(kurtosis_sf(b2, n), 1e-290) << line;
    } else if (kind == "normal_isf") {
      double p, z;
      ls >> p >> z;
      EXPECT_NEAR(normal_isf(p), z, 1e-9 * std::max(1.0, std::fabs(z))) << line;
    } else if (kind == "t_sf") {
      double nu, t, p;
      ls >> nu >> t >> p;
      EXPECT_TRUE(close_rel(student_t_isf(p, nu), t, 1e-9)) << line << ": " << student_t_isf(p, nu);
    } else if (kind == "crest") {
      double n, p, u;
      ls >> n >> p >> u;
      EXPECT_TRUE(close_rel(crest_threshold(n, p), u, 1e-9)) << line;
      EXPECT_TRUE(close_rel(crest_sf(u, n), p, 1e-9)) << line;
    } else {
      ADD_FAILURE() << "unknown reference line: " << line;
    }
  }
  EXPECT_GE(cases, 70);
}

TEST(Detect, ThresholdsAreTheQuantilesOfTheirLaws)
{
  for (double n : {20.0, 300.0, 5000.0, 1e6})
    for (double p : {0.05, 1e-3, 1e-6}) {
      EXPECT_TRUE(close_rel(kurtosis_sf(kurtosis_threshold(n, p), n), p, 1e-9)) << n << " " << p;
      EXPECT_TRUE(close_rel(spectral_kurtosis_sf(spectral_kurtosis_threshold(n, p), n), p, 1e-9))
          << n << " " << p;
    }
  // far below the Gaussian kurtosis (a sine: 1.5) the Anscombe-Glynn transform is undefined:
  // a one-sided test of a high kurtosis must not fire there (scipy returns a flipped z)
  EXPECT_DOUBLE_EQ(kurtosis_sf(1.5, 1000), 1.0);
  // SK of m independent circular normal values: mean -2/(m+1) (Dirichlet moments), so the
  // median of the fitted law sits just below 0, and its sd is about 2/sqrt(m) (Antoni 2006)
  const double m = 4096;
  const double q16 = spectral_kurtosis_threshold(m, normal_sf(1));
  const double q84 = spectral_kurtosis_threshold(m, normal_sf(-1));
  EXPECT_NEAR((q16 - q84) / 2, 2 / std::sqrt(m), 0.02 * 2 / std::sqrt(m));
  EXPECT_THROW(normal_isf(0), Error);
  EXPECT_THROW(crest_threshold(100, 1.5), Error);
}

// Smallest k with P(X >= k) <= alpha for X ~ Binomial(n, p): observing k or more false alarms
// would refute the stated rate p at level alpha.
int binomial_upper(int n, double p, double alpha)
{
  double tail = 1;
  for (int k = 0; k <= n; ++k) {
    if (tail <= alpha) return k;
    tail -= std::exp(std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0) +
                     k * std::log(p) + (n - k) * std::log1p(-p));
  }
  return n + 1;
}
// Largest k with P(X <= k) <= alpha.
int binomial_lower(int n, double p, double alpha)
{
  double cdf = 0;
  for (int k = 0; k <= n; ++k) {
    cdf += std::exp(std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0) +
                    k * std::log(p) + (n - k) * std::log1p(-p));
    if (cdf > alpha) return k - 1;
  }
  return n;
}

// test::Gaussian(s) walks the splitmix64 sequence from s: streams of nearby seeds overlap, so
// independent records take seeds a million draws apart (records here use < 500 000 draws).
std::uint64_t stream(int i)
{
  return 1 + static_cast<std::uint64_t>(i) * 1000003u;
}

// One seeded Gaussian record: white, or AR(1) x_t = phi x_t-1 + e_t (colored: fewer independent
// samples than values).
std::vector<double> gaussian_record(std::size_t n, double phi, std::uint64_t seed)
{
  test::Gaussian g(seed);
  std::vector<double> x(n);
  double prev = g() / std::sqrt(1 - phi * phi);
  for (auto &v : x) v = prev = phi * prev + g();
  double mean = 0;
  for (double v : x) mean += v / static_cast<double>(n);
  for (auto &v : x) v -= mean;
  return x;
}

TEST(Detect, FalseAlarmRateOnGaussianNoise)
{
  // The detection stage as diagnose runs it (band: the kurtogram's best, Bonferroni over its
  // cells) on seeded Gaussian records of 4096 samples. A test fires at level P when its p-value
  // is below P. The observed count must lie under the 1e-4 upper quantile of Binomial(R, P)
  // (the stated rate holds); for the kurtosis and the crest factor of white noise, whose laws
  // are not bounds but approximations/exact, also over the 1e-4 lower quantile (the stated
  // rate is not grossly conservative).
  const double levels[] = {0.05, 0.01, 1e-3};
  std::printf("\n[ false alarm ] Gaussian records of 4096 samples, kurtogram band (4 levels)\n");
  for (double phi : {0.0, 0.9}) {
    const int R = phi == 0 ? 1000 : 500;
    int count[4][3] = {};  // kurtosis, crest, band_sk, any x level
    for (int r = 0; r < R; ++r) {
      const auto x = gaussian_record(4096, phi, stream(1000 + r));
      const Kurtogram kg = kurtogram(x, 1e4, 4, 0);
      DetectOptions o;
      o.false_alarm = 1e-3;
      o.band = {kg.best.lo, kg.best.hi};
      o.bands_searched = kg.cells.size();
      const Detection d = detect(x, 1e4, o);
      ASSERT_TRUE(d.gaussian_applicable) << d.gaussian_note;
      ASSERT_EQ(d.tests.size(), 3u);
      for (int l = 0; l < 3; ++l) {
        bool any = false;
        for (int t = 0; t < 3; ++t) {
          ASSERT_TRUE(d.tests[t].applicable) << d.tests[t].name << ": " << d.tests[t].note;
          const bool f = d.tests[t].p_value < levels[l];
          if (levels[l] == o.false_alarm) {
            EXPECT_EQ(f, d.tests[t].fired) << d.tests[t].name;
          }
          count[t][l] += f;
          any = any || f;
        }
        count[3][l] += any;
      }
    }
    const char *names[] = {"kurtosis", "crest", "band_sk", "any (<= 3P)"};
    for (int t = 0; t < 4; ++t) {
      std::printf("[ false alarm ] %-6s %-12s", phi == 0 ? "white" : "AR0.9", names[t]);
      for (int l = 0; l < 3; ++l) {
        const double p = t == 3 ? std::min(1.0, 3 * levels[l]) : levels[l];
        std::printf("  P=%-6g %4d/%d (expected %6.1f, bound %d)", levels[l], count[t][l], R, R * p,
                    binomial_upper(R, p, 1e-4));
        EXPECT_LT(count[t][l], binomial_upper(R, p, 1e-4)) << names[t] << " P " << levels[l];
        if (phi == 0 && t < 2 && R * p >= 10) {
          EXPECT_GT(count[t][l], binomial_lower(R, p, 1e-4)) << names[t] << " P " << levels[l];
        }
      }
      std::printf("\n");
    }
  }
}

TEST(Detect, NoiseAloneIsNone)
{
  // diagnose on white noise (the 6208 at 500 rad/s, 1 MHz): nothing identified, nothing
  // detected
  DiagnoseOptions o;
  o.geometry = bearing_preset("machado2014");
  o.fr = 500 / (2 * kPi);
  for (int seed : {21, 22, 23}) {
    Signal s;
    s.rate = 1e6;
    s.x = gaussian_record(100000, 0, stream(seed));
    const Diagnosis d = diagnose(s, o);
    EXPECT_EQ(d.defect, "none") << seed;
    EXPECT_FALSE(d.detected) << seed;
    EXPECT_FALSE(d.detection.fired) << seed;
  }
}

// Resonance bursts (20 kHz, 50 us decay) at random instants in white noise, 1 MHz: as
// impulsive as a bearing fault, but with no repetition frequency for a family to match.
std::vector<double> random_bursts(std::size_t n, int *count = nullptr)
{
  const double rate = 1e6;
  auto x = gaussian_record(n, 0, stream(7));
  test::Gaussian g(stream(8));
  std::size_t t = 500;
  int bursts = 0;
  while (t + 400 < n) {
    for (std::size_t j = 0; j < 400; ++j) {
      const double tau = static_cast<double>(j) / rate;
      x[t + j] += 6 * std::exp(-tau / 50e-6) * std::sin(2 * kPi * 20e3 * tau);
    }
    ++bursts;
    t += 800 + static_cast<std::size_t>(3000 * std::fabs(g()));  // random spacing
  }
  if (count) *count = bursts;
  return x;
}

TEST(Detect, ImpulsesNoFamilyExplainsAreUnidentified)
{
  const double rate = 1e6;
  int bursts = 0;
  const auto x = random_bursts(200000, &bursts);
  Signal s;
  s.rate = rate;
  s.x = x;
  DiagnoseOptions o;
  o.geometry = bearing_preset("machado2014");
  o.fr = 500 / (2 * kPi);
  const Diagnosis d = diagnose(s, o);
  std::printf(
      "[ unidentified] %d bursts: defect %s, best family score %.2f, kurtosis %.2f "
      "(threshold %.2f)\n",
      bursts, d.defect.c_str(), d.score, d.detection.tests[0].value,
      d.detection.tests[0].threshold);
  EXPECT_EQ(d.defect, "unidentified");
  EXPECT_TRUE(d.detected);
  EXPECT_TRUE(d.detection.tests[0].fired);  // kurtosis

  // An outer-race burst train (amplitude 1.4 sigma) whose period wanders by 8 % (slip) from
  // burst to burst: below the identification SNR (the BPFO comb scores < 0.3), still found by
  // the envelope band's spectral kurtosis. (With a strictly periodic train identification is
  // the more sensitive stage: at 1 sigma BPFO scores 0.55 while no statistic fires.)
  auto y = gaussian_record(200000, 0, stream(41));
  test::Gaussian jitter(stream(42));
  const double period = 1 / defect_frequencies(o.geometry, o.fr).bpfo;
  for (double t0 = 1e-3; t0 * rate + 400 < 200000; t0 += period * (1 + 0.08 * jitter())) {
    const auto i0 = static_cast<std::size_t>(t0 * rate);
    for (std::size_t j = 0; j < 400; ++j) {
      const double tau = static_cast<double>(j) / rate;
      y[i0 + j] += 1.4 * std::exp(-tau / 50e-6) * std::sin(2 * kPi * 20e3 * tau);
    }
  }
  s.x = y;
  const Diagnosis e = diagnose(s, o);
  std::printf(
      "[ unidentified] slipping BPFO bursts: defect %s, outer score %.2f, band SK %.2f "
      "(threshold %.2f)\n",
      e.defect.c_str(), e.families[1].score, e.detection.tests[2].value,
      e.detection.tests[2].threshold);
  EXPECT_EQ(e.defect, "unidentified");
  EXPECT_LT(e.families[1].score, 0.3);
  EXPECT_TRUE(e.detection.tests[2].fired);  // band_sk
}

TEST(Detect, DeterministicRecordsAreJudgedAgainstTheBaseline)
{
  // A noiseless resistance record (the simulator's kind: a level and a shaft-synchronous
  // ripple) has no noise floor: the Gaussian tests do not apply. Against itself it is healthy;
  // a rectangle train of a small defect on it is detected by the baseline tests.
  const BearingGeometry g = bearing_preset("machado2014");
  test::DefectSpec healthy;
  healthy.kind = "none";
  auto h = test::defect_signal(g, healthy);
  const auto ripple = test::sine(h.signal.size(), h.signal.rate, 500 / (2 * kPi), 1e-4, 0.3);
  for (std::size_t i = 0; i < ripple.size(); ++i) h.signal.x[i] += ripple[i];
  DiagnoseOptions o;
  o.geometry = g;
  o.fr = 500 / (2 * kPi);
  const Diagnosis alone = diagnose(h.signal, o);
  EXPECT_FALSE(alone.detection.gaussian_applicable);
  EXPECT_EQ(alone.defect, "none");

  o.baseline = &h.signal;
  const Diagnosis self = diagnose(h.signal, o);
  EXPECT_EQ(self.defect, "none");
  EXPECT_FALSE(self.detection.fired);

  test::DefectSpec small;
  small.kind = "outer";
  small.size_deg = 0.05;
  small.step = 0.002;  // a 0.2 % rise for 4 us, every BPFO period
  auto f = test::defect_signal(g, small);
  for (std::size_t i = 0; i < ripple.size(); ++i) f.signal.x[i] += ripple[i];
  const Diagnosis vs = diagnose(f.signal, o);
  EXPECT_TRUE(vs.detection.fired);
  EXPECT_TRUE(vs.detected);
  std::printf("[ baseline   ] noiseless: alone %s; itself %s; small outer defect %s\n",
              alone.defect.c_str(), self.defect.c_str(), vs.defect.c_str());
}

TEST(Detect, LinesTheBaselineHasTooIdentifyNothing)
{
  // A radially loaded healthy bearing has a ball-pass (BPFO) comb of its own: its stiffness
  // varies as the balls pass through the load zone. Against a baseline with that comb, the
  // same record is healthy, and an outer defect is identified by what it adds to the comb.
  const BearingGeometry g = bearing_preset("machado2014");
  const double fr = 500 / (2 * kPi);
  const DefectFrequencies k = defect_frequencies(g, fr);
  auto with_comb = [&](std::uint64_t seed, double comb_amplitude) {
    test::DefectSpec spec;
    spec.kind = "none";
    spec.duration = 0.1;
    spec.rate = 1e5;
    auto h = test::defect_signal(g, spec);
    test::Gaussian noise(seed);
    for (int harmonic = 1; harmonic <= 5; ++harmonic) {
      const auto c = test::sine(h.signal.size(), h.signal.rate, harmonic * k.bpfo,
                                comb_amplitude / harmonic, 0.1 * harmonic);
      for (std::size_t i = 0; i < c.size(); ++i) h.signal.x[i] += c[i];
    }
    for (double &v : h.signal.x) v += 2e-6 * noise();
    return h.signal;
  };
  const Signal base = with_comb(11, 1e-4), healthy = with_comb(12, 1e-4),
               defective = with_comb(13, 1e-3);
  DiagnoseOptions o;
  o.geometry = g;
  o.fr = fr;
  o.estimate_size = false;
  // without a baseline: the comb alone, a smooth modulation (sines, kurtosis < 3), is no
  // pulse train: not taken as a defect, the family named as the candidate
  const Diagnosis alone = diagnose(healthy, o);
  EXPECT_NE(alone.defect, "outer");
  EXPECT_EQ(alone.candidate, "outer");
  o.baseline = &base;
  const Diagnosis h = diagnose(healthy, o);
  EXPECT_EQ(h.defect, "none");
  EXPECT_LT(h.families[1].baseline_excess, 3.0);  // the same lines: about 0 dB over the baseline
  const Diagnosis d = diagnose(defective, o);
  EXPECT_EQ(d.defect, "outer");
  EXPECT_NEAR(d.families[1].baseline_excess, 20.0, 3.0);  // lines 10x (20 dB) the baseline's
  std::printf(
      "[ baseline   ] BPFO comb in the baseline: healthy %s (%.1f dB over it), "
      "10x comb %s (%.1f dB over it)\n",
      h.defect.c_str(), h.families[1].baseline_excess, d.defect.c_str(),
      d.families[1].baseline_excess);
}

TEST(Detect, ATooShortBaselineLeavesItsTestsNotApplicable)
{
  // 16 baseline windows of at least 256 samples are needed to know the healthy scatter; a slow
  // instrument over a short record gives fewer: the baseline tests say so instead of failing.
  test::Gaussian g(5);
  std::vector<double> x(2000), base(3000);
  for (double &v : x) v = g();
  for (double &v : base) v = g();
  DetectOptions o;
  const Detection d = detect(x, 1000.0, o, &base);
  int baseline_tests = 0;
  for (const auto &t : d.tests) {
    if (t.reference != "baseline") continue;
    ++baseline_tests;
    EXPECT_FALSE(t.applicable) << t.name;
    EXPECT_FALSE(t.fired) << t.name;
    EXPECT_NE(t.note.find("too short"), std::string::npos) << t.note;
  }
  EXPECT_EQ(baseline_tests, 4);
}

TEST(Detect, BaselineWindowsGiveTheStatedFalseAlarmRate)
{
  // A record against a healthy baseline of the same Gaussian process: the baseline tests fire
  // at the stated rate (t prediction bound) and the stage stays quiet.
  const int R = 200;
  int fired = 0;
  for (int r = 0; r < R; ++r) {
    const auto b = gaussian_record(16384, 0.5, stream(5000 + 2 * r));
    const auto x = gaussian_record(8192, 0.5, stream(5001 + 2 * r));
    DetectOptions o;
    o.false_alarm = 0.01;
    o.band = {1000, 3000};
    const Detection d = detect(x, 1e4, o, &b);
    ASSERT_EQ(d.tests.size(), 7u);
    for (std::size_t t = 3; t < 7; ++t) fired += d.tests[t].fired;
  }
  // 4 tests x 200 records at 1 %: 8 expected
  std::printf("[ baseline   ] Gaussian vs Gaussian baseline, P = 0.01: %d of %d tests fired\n",
              fired, 4 * R);
  EXPECT_LT(fired, binomial_upper(4 * R, 0.01, 1e-4));
}

std::string write_samples(const std::string &name, const std::vector<double> &x)
{
  std::ostringstream os;
  os.precision(10);
  for (double v : x) os << v << '\n';
  return test::write_temp(name, os.str());
}

TEST(Detect, CommandLineReportsDetection)
{
  const std::string bursts = write_samples("detect_bursts.txt", random_bursts(100000));
  const std::string noise =
      write_samples("detect_noise.txt", gaussian_record(100000, 0, stream(31)));
  const std::string base = write_samples("detect_base.txt", gaussian_record(100000, 0, stream(32)));
  const std::string opts = " --rate 1e6 --bearing machado2014 --omega 500 --no-size";

  CliRun r = test::run("diagnose " + bursts + opts + " --format json");
  ASSERT_EQ(r.status, 0) << r.out;
  Json j = Json::parse(r.out, "diagnose output");
  EXPECT_EQ(j.find("defect")->string(), "unidentified");
  EXPECT_TRUE(j.find("detected")->boolean());
  EXPECT_TRUE(j.find("frequency_hz")->is_null());
  const Json *det = j.find("detection");
  ASSERT_TRUE(det);
  EXPECT_TRUE(det->find("fired")->boolean());
  EXPECT_TRUE(det->find("gaussian_applicable")->boolean());
  const Json *tests = det->find("tests");
  ASSERT_TRUE(tests && tests->size() == 3);
  EXPECT_EQ((*tests)[0].find("name")->string(), "kurtosis");
  EXPECT_TRUE((*tests)[0].find("fired")->boolean());

  r = test::run("diagnose " + noise + opts + " --baseline " + base + " --format json");
  ASSERT_EQ(r.status, 0) << r.out;
  j = Json::parse(r.out, "diagnose output");
  EXPECT_EQ(j.find("defect")->string(), "none");
  EXPECT_FALSE(j.find("detected")->boolean());
  EXPECT_EQ(j.find("detection")->find("tests")->size(), 7u);

  r = test::run("diagnose " + bursts + opts + " --baseline " + base + " --format csv");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("\ndefect,score,frequency_Hz,kinematic_Hz,size_deg,pulse_width_s,"
                       "inner_score,outer_score,ball_score,cage_score,band_kurtosis,"
                       "band_kurtosis_threshold,band_kurtosis_significant,detected,fired,kurtosis,"
                       "kurtosis_threshold,crest,crest_threshold,band_sk,band_sk_threshold,"
                       "baseline_rms,baseline_rms_threshold,"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\nunidentified,"), std::string::npos) << r.out;
  // with a baseline the Gaussian tests are for information: the baseline ones fire
  EXPECT_NE(r.out.find(",yes,baseline_"), std::string::npos) << r.out;

  r = test::run("diagnose " + bursts + opts);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("defect:        unidentified"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("detected:      yes (fired: kurtosis"), std::string::npos) << r.out;
}

TEST(Detect, BadInput)
{
  const auto x = gaussian_record(4096, 0, stream(1));
  DetectOptions o;
  o.false_alarm = 0;
  EXPECT_THROW(detect(x, 1e4, o), Error);
  o.false_alarm = 1e-3;
  const std::vector<double> flat(8192, 0.0);
  EXPECT_THROW(detect(x, 1e4, o, &flat), Error);  // a constant baseline has no scatter
  Signal s;
  s.rate = 1e6;
  s.x = gaussian_record(100000, 0, stream(3));
  Signal b = s;
  b.rate = 5e5;
  DiagnoseOptions d;
  d.geometry = bearing_preset("machado2014");
  d.fr = 80;
  d.baseline = &b;
  EXPECT_THROW(diagnose(s, d), Error);  // rates differ
}

}  // namespace
}  // namespace ohmdem::post
