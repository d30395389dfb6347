// SPDX-License-Identifier: GPL-2.0-or-later
// The record of acquire: the chain's lines (the noise line names the setting that gave it, the
// command line its flag) and the "time value" table in both forms.
#include <gtest/gtest.h>

#include "report/acquire_report.h"

namespace ohmdem::post {
namespace {

Acquisition sampled()
{
  Acquisition q;
  q.signal.x = {1, 2, 3, 4};
  q.signal.rate = 1000;
  q.signal.name = "V";
  q.decimation = 1;
  return q;
}

TEST(AcquireReport, NoiseLineNamesItsSetting)
{
  AcquireSettings s;
  s.noise_rms = 0.1;
  Acquisition q = sampled();
  q.noise_sigma = 0.1;
  AcquisitionContext c;
  c.input_rate = 1000;
  const std::string chain = acquisition_chain(s, q, c);
  EXPECT_NE(chain.find("# noise: white Gaussian added to the samples, rms 0.1 "
                       "({acquire.noise_rms}), mt19937_64 + Box-Muller, seed 1\n"),
            std::string::npos)
      << chain;
  EXPECT_NE(chain.find("# sampling: the input's samples\n"), std::string::npos);
  EXPECT_NE(chain.find("# samples: 4\n"), std::string::npos);
  c.rate_given = true;  // the same samples, asked for: every k-th with k = 1
  EXPECT_NE(acquisition_chain(s, q, c).find("# sampling: every k-th sample of the input, k = 1\n"),
            std::string::npos);
}

TEST(AcquireReport, TableInBothForms)
{
  const Signal y = sampled().signal;
  EXPECT_EQ(acquisition_table(y, "V", nullptr, "", false),
            "# time V\n0 1\n0.001 2\n0.002 3\n0.003 4\n");
  EXPECT_EQ(acquisition_table(y, "V", nullptr, "", true),
            "time,V\n0,1\n0.001,2\n0.002,3\n0.003,4\n");
  // a second axis: a third column
  Signal z = y;
  for (double &v : z.x) v = -v;
  EXPECT_EQ(acquisition_table(y, "V", &z, "V2", false),
            "# time V V2\n0 1 -1\n0.001 2 -2\n0.002 3 -3\n0.003 4 -4\n");
  EXPECT_EQ(acquisition_table(y, "V", &z, "V2", true),
            "time,V,V2\n0,1,-1\n0.001,2,-2\n0.002,3,-3\n0.003,4,-4\n");
  EXPECT_EQ(acquisition_head("1.0", {{"source", "x.txt"}, {"column", "R"}}),
            "# ohmdem-post 1.0 acquire: what an instrument records\n"
            "# source: x.txt\n# input column: R\n");
}

}  // namespace
}  // namespace ohmdem::post
