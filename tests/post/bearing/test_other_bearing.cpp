// SPDX-License-Identifier: GPL-2.0-or-later
// diagnose with the other bearing on the shaft: a pulse train at a defect frequency
// of the CWRU drive-end 6205 read on the fan-end 6203's channel is the other bearing's defect.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "bearing/diagnose.h"
#include "synth.h"
#include "test_constants.h"

namespace ohmdem::post {
namespace {

test::DefectSignal drive_end_train(const std::string &kind, double snr_db)
{
  test::DefectSpec spec;
  spec.kind = kind;
  spec.omega_inner = 188;  // 1796 rpm, the CWRU records' speed
  spec.rate = 48000;
  spec.duration = 1.0;
  spec.snr_db = snr_db;
  return test::defect_signal(bearing_preset("6205-2RS_JEM"), spec);
}

DiagnoseOptions options(const char *bearing, const char *other)
{
  DiagnoseOptions o;
  o.geometry = bearing_preset(bearing);
  if (other) o.other = bearing_preset(other);
  o.fr = 188 / (2 * ohmdem::test::kPi);
  o.estimate_size = false;
  return o;
}

TEST(OtherBearing, TheOtherBearingsPulseTrainIsNamedAsItsDefect)
{
  for (const char *kind : {"inner", "outer"})
    for (double snr : {1e9, 10.0}) {
      const test::DefectSignal sig = drive_end_train(kind, snr);
      // the fan end's own families do not explain a train at the 6205's BPFI (5.415 fr) or BPFO
      // (3.585 fr), 9 % and 17 % from the 6203's: no family of its own is named
      const Diagnosis alone = diagnose(sig.signal, options("6203-2RS_JEM", nullptr));
      EXPECT_NE(alone.defect, kind) << kind << " snr " << snr;
      const Diagnosis d = diagnose(sig.signal, options("6203-2RS_JEM", "6205-2RS_JEM"));
      EXPECT_EQ(d.defect, "other-bearing") << kind << " snr " << snr << ": " << alone.defect;
      EXPECT_EQ(d.candidate, kind);
      EXPECT_EQ(d.reason.rfind("impulses at 6205-2RS_JEM's BP", 0), 0u) << d.reason;
      EXPECT_NEAR(d.frequency_hz, sig.frequency, 0.002 * sig.frequency) << kind;
      ASSERT_EQ(d.other_families.size(), 4u);
      // on the faulty bearing's own channel, naming the other bearing changes nothing
      const Diagnosis own = diagnose(sig.signal, options("6205-2RS_JEM", "6203-2RS_JEM"));
      const Diagnosis own_alone = diagnose(sig.signal, options("6205-2RS_JEM", nullptr));
      EXPECT_EQ(own.defect, kind);
      EXPECT_EQ(own_alone.defect, kind);
      EXPECT_EQ(own.score, own_alone.score);
    }
}

TEST(OtherBearing, AHealthyRecordStaysNone)
{
  // white Gaussian noise: neither bearing's comb stands out, nothing is attributed
  Signal s;
  s.rate = 48000;
  std::mt19937_64 gen(7);
  std::normal_distribution<double> n(0, 1);
  for (int i = 0; i < 48000; ++i) s.x.push_back(n(gen));
  const Diagnosis d = diagnose(s, options("6203-2RS_JEM", "6205-2RS_JEM"));
  EXPECT_EQ(d.defect, "none") << d.reason;
  for (const FamilyScore &f : d.other_families) EXPECT_LT(f.score, 0.3) << f.defect;
}

}  // namespace
}  // namespace ohmdem::post
