// app/sweep/sweep_values: ranges, evenly spaced points, seeded draws. The draws are checked against
// the C++ standard's fixed value of std::mt19937_64 and against their distributions' moments.

#include "app/sweep/sweep_values.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <gtest/gtest.h>

namespace towsim::app {
namespace {

TEST(SweepValues, RangesIncludeTheirEndAndDoNotAccumulate) {
  EXPECT_EQ(RangeValues(10, 40, 10), (std::vector<double>{10, 20, 30, 40}));
  EXPECT_EQ(RangeValues(10, 45, 10), (std::vector<double>{10, 20, 30, 40}));
  EXPECT_EQ(RangeValues(1, 0, -0.5), (std::vector<double>{1, 0.5, 0}));
  // 0.1 steps: from + i step, so the 10th is 1.0 to rounding and counts as the end
  const std::vector<double> tenths = RangeValues(0, 1, 0.1);
  ASSERT_EQ(tenths.size(), 11u);
  EXPECT_EQ(FormatSweepNumber(tenths[3]), "0.3");
  EXPECT_EQ(LinspaceValues(0.6, 0.9, 4).back(), 0.9);
  EXPECT_EQ(FormatSweepNumber(LinspaceValues(0.6, 0.9, 4)[1]), "0.7");
}

TEST(SweepValues, UniformDrawsAreTheStandardsMersenneTwister) {
  // [rand.predef]: the 10000th output of a default-constructed mt19937_64 (seed 5489) is
  // 9981545732273789042; the draw is (x >> 11) 2^-53
  const std::vector<double> u = UniformDraws(0.0, 1.0, 10000, 5489);
  EXPECT_EQ(u[9999], static_cast<double>(9981545732273789042ull >> 11) / 9007199254740992.0);
  EXPECT_EQ(UniformDraws(2, 3, 5, 11), UniformDraws(2, 3, 5, 11));  // reproducible
  EXPECT_NE(UniformDraws(2, 3, 5, 11), UniformDraws(2, 3, 5, 12));
}

TEST(SweepValues, DrawsHaveTheirDistributionsMoments) {
  // n = 20000: the sample mean's standard error is sigma / sqrt(n); allow 4 of them
  constexpr int kN = 20000;
  constexpr double kSigmas = 4.0;
  const std::vector<double> z = NormalDraws(3.0, 2.0, kN, 1);
  double sum = 0.0, sum2 = 0.0;
  for (double x : z) sum += x, sum2 += x * x;
  const double mean = sum / kN;
  const double var = sum2 / kN - mean * mean;
  EXPECT_NEAR(mean, 3.0, kSigmas * 2.0 / std::sqrt(kN));
  // the sample variance's standard error is sigma^2 sqrt(2 / n)
  EXPECT_NEAR(var, 4.0, kSigmas * 4.0 * std::sqrt(2.0 / kN));

  const std::vector<double> u = UniformDraws(-1.0, 1.0, kN, 2);
  double usum = 0.0;
  for (double x : u) {
    usum += x;
    EXPECT_GE(x, -1.0);
    EXPECT_LT(x, 1.0);
  }
  EXPECT_NEAR(usum / kN, 0.0, kSigmas * (2.0 / std::sqrt(12.0)) / std::sqrt(kN));

  // integers: every value of [1, 6] appears, none outside, each about n / 6 times
  const std::vector<long long> dice = IntegerDraws(1, 6, kN, 3);
  std::vector<int> counts(7, 0);
  for (long long d : dice) {
    ASSERT_GE(d, 1);
    ASSERT_LE(d, 6);
    ++counts[d];
  }
  const double expected = kN / 6.0, sd = std::sqrt(kN * (1.0 / 6.0) * (5.0 / 6.0));
  for (int face = 1; face <= 6; ++face) EXPECT_NEAR(counts[face], expected, kSigmas * sd);
}

}  // namespace
}  // namespace towsim::app
