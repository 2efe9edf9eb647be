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

namespace towsim::reference {
namespace {

// the FFT against the direct sum of its definition
TEST(SignalAnalysis, FftMatchesTheDirectSum) {
  constexpr double kPi = 3.14159265358979323846;
  std::vector<std::complex<double>> x(64);
  for (size_t n = 0; n < x.size(); ++n) x[n] = {std::sin(0.3 * n * n), std::cos(1.7 * n)};
  std::vector<std::complex<double>> direct(x.size());
  for (size_t k = 0; k < x.size(); ++k)
    for (size_t n = 0; n < x.size(); ++n)
      direct[k] += x[n] * std::polar(1.0, -2.0 * kPi * k * n / x.size());
  Fft(&x);
  for (size_t k = 0; k < x.size(); ++k) EXPECT_LT(std::abs(x[k] - direct[k]), 1e-11) << k;
}

// Welch's estimate of a sine a cos(w0 t) holds its variance a^2/2 (Parseval) at w0, and the
// autocorrelation of that sine is cos(w0 tau)
TEST(SignalAnalysis, WelchAndAutocorrelationOfASine) {
  const double dt = 0.1, w0 = 2.0 * 3.14159265358979323846 / 6.4;  // on a bin of 256 samples
  std::vector<double> x(8192);
  for (size_t n = 0; n < x.size(); ++n) x[n] = 0.7 * std::cos(w0 * n * dt);
  const Spectrum s = WelchSpectrum(x, dt, 256);
  double m0 = 0.0;
  for (size_t k = 0; k < s.density.size(); ++k) m0 += s.density[k] * (s.omega[1] - s.omega[0]);
  EXPECT_NEAR(m0, 0.5 * 0.7 * 0.7, 1e-3);  // Hann leakage stays within the record's bins
  EXPECT_EQ(s.segments, 63);
  const std::vector<double> rho = Autocorrelation(x, 200);
  EXPECT_DOUBLE_EQ(rho[0], 1.0);
  // the sample autocorrelation of a finite record is biased by (N - k) / N; the product's
  // oscillating half, sum cos(w0 (2n + k) dt) / N, is bounded by 1 / (N sin(w0 dt)) = 1.25e-3
  constexpr double kEndEffectTol = 1.5e-3;
  for (int k : {16, 32, 64, 100}) {
    EXPECT_NEAR(rho[k], std::cos(w0 * k * dt) * (x.size() - k) / x.size(), kEndEffectTol) << k;
  }
}

}  // namespace
}  // namespace towsim::reference
