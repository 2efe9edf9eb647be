// Self-checks of the signal-analysis helpers (signal_analysis.h).

#include "signal_analysis.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace towsim::reference {
namespace {

constexpr double kPi = 3.14159265358979323846;

// a sampled sine of known frequency: linear interpolation of the crossings of a sine is
// exact to O(h^3) (the sine has no curvature at its zeros), so 1e-6 relative at 200 samples
// per period is conservative
TEST(SignalAnalysis, FrequencyOfSampledSine) {
  const double f = 1.585;
  const double h = 1.0 / (200.0 * f);
  std::vector<double> t;
  std::vector<double> y;
  for (int i = 0; i <= 2000; ++i) {
    t.push_back(i * h);
    y.push_back(3e-4 * std::sin(2.0 * kPi * f * i * h + 0.3));
  }
  const std::vector<double> c = ZeroCrossings(t, y);
  ASSERT_EQ(c.size(), 20u);  // 10 periods
  EXPECT_NEAR(FrequencyFromCrossings(c), f, 1e-6 * f);
}

TEST(SignalAnalysis, ExactZeroCountsOnce) {
  const std::vector<double> t = {0, 1, 2, 3, 4};
  const std::vector<double> y = {1, 0, -1, 0, 1};
  const std::vector<double> c = ZeroCrossings(t, y);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_DOUBLE_EQ(c[0], 1.0);
  EXPECT_DOUBLE_EQ(c[1], 3.0);
}

TEST(SignalAnalysis, OrderOfPowerLaw) {
  std::vector<double> h;
  std::vector<double> e;
  for (double hi : {0.1, 0.05, 0.025, 0.0125}) {
    h.push_back(hi);
    e.push_back(7.0 * hi * hi * (1.0 + 0.1 * hi));  // order 2 plus a higher-order term
  }
  EXPECT_NEAR(FitConvergenceOrder(h, e), 2.0, 0.01);
}

}  // namespace
}  // namespace towsim::reference
