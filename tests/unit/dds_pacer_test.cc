// sim_node/app/node/dds_pacer: the lateness statistics (the pacing itself is measured by the
// benchmark, never gated on wall time here).

#include "app/node/dds_pacer.h"

#include <gtest/gtest.h>

namespace towsim::app {
namespace {

constexpr double kBin = 1e-6;  // [s], the histogram's resolution

TEST(LatenessStatsTest, Quantiles) {
  LatenessStats s;
  EXPECT_EQ(s.Quantile(0.5), 0.0);
  for (int i = 1; i <= 100; ++i) s.Add(i * 1e-5);  // 10 us .. 1 ms
  EXPECT_EQ(s.count(), 100);
  EXPECT_NEAR(s.Quantile(0.50), 50e-5, kBin);
  EXPECT_NEAR(s.Quantile(0.99), 99e-5, kBin);
  EXPECT_NEAR(s.Quantile(1.0), 100e-5, kBin);
  EXPECT_DOUBLE_EQ(s.max(), 100e-5);
  EXPECT_DOUBLE_EQ(s.last(), 100e-5);
}

TEST(LatenessStatsTest, EarlyCountsAsZeroAndLargeIsKept) {
  LatenessStats s;
  s.Add(-1e-3);
  s.Add(0.5);  // beyond the histogram: the maximum stays exact
  EXPECT_EQ(s.Quantile(0.5), 0.0);
  EXPECT_DOUBLE_EQ(s.Quantile(1.0), 0.5);
  EXPECT_DOUBLE_EQ(s.max(), 0.5);
  s.Clear();
  EXPECT_EQ(s.count(), 0);
}

}  // namespace
}  // namespace towsim::app
