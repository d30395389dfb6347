// SPDX-License-Identifier: GPL-2.0-or-later
// Diagnosis of synthetic 6208 resistance signals over a sweep of signal-to-noise ratios: the
// lowest SNR at which every kind is still named (printed, and at most -10 dB).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <string>

#include "bearing/diagnose.h"
#include "synth.h"
#include "test_constants.h"

namespace ohmdem::post {
namespace {

TEST(Diagnose, NoiseSweepReportsTheSnrLimit)
{
  // SNR = AC power of the clean rectangle train / white-noise power, over the full 500 kHz
  // band of a 1 MHz record of 0.2 s
  const double snrs[] = {20, 10, 0, -10, -15, -20, -25, -30, -35, -40};
  std::printf("\n[ SNR sweep  ] 6208, 500 rad/s, 1 deg defect, 1 MHz, 0.2 s, 2 seeds per cell\n");
  std::printf("[ SNR sweep  ] %8s %-22s %-22s %-22s\n", "SNR(dB)", "inner", "outer", "ball");
  double limit[3] = {1e9, 1e9, 1e9};  // lowest SNR down to which every run was right
  bool broken[3] = {false, false, false};
  const char *kinds[] = {"inner", "outer", "ball"};
  const BearingGeometry paper = bearing_preset("machado2014");
  DiagnoseOptions options;
  options.geometry = paper;
  options.fr = 500 / (2 * ohmdem::test::kPi);
  for (double snr : snrs) {
    std::printf("[ SNR sweep  ] %8.0f", snr);
    for (int k = 0; k < 3; ++k) {
      int right = 0;
      double score = 0;
      std::string got;
      for (std::uint64_t seed : {11, 12}) {
        test::DefectSpec spec;
        spec.kind = kinds[k];
        spec.snr_db = snr;
        spec.seed = seed;
        const Diagnosis d =
            diagnose(test::defect_signal(paper, spec).signal, options);
        right += d.defect == kinds[k];
        score += d.score / 2;
        if (d.defect != kinds[k]) got = d.defect;
      }
      char cell[64];
      std::snprintf(cell, sizeof cell, "%d/2 score %.2f%s%s", right, score,
                    got.empty() ? "" : " got ", got.c_str());
      std::printf(" %-22s", cell);
      if (right == 2 && !broken[k]) limit[k] = snr;
      if (right < 2) broken[k] = true;
    }
    std::printf("\n");
  }
  std::printf("[ SNR sweep  ] works down to: inner %.0f dB, outer %.0f dB, ball %.0f dB\n",
              limit[0], limit[1], limit[2]);
  for (int k = 0; k < 3; ++k) EXPECT_LE(limit[k], -10) << kinds[k];
}

}  // namespace
}  // namespace ohmdem::post
