// core/cubic_spline.h: the natural cubic spline. Oracles: a spline worked by hand, exactness
// for straight lines, the analytic sine and its derivatives, one-sided finite differences.
#include "core/cubic_spline.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/constants.h"

namespace towsim::core {
namespace {

TEST(CubicSpline, MatchesASplineWorkedByHand) {
  // (0, 0), (1, 1), (2, 0): 2 (1 + 1) M_1 = 6 ((0 - 1) - (1 - 0)) -> M_1 = -3; on [0, 1]
  // y = 1.5 t - 0.5 t^3: y(0.5) = 0.6875, y'(0.5) = 1.125, y''(0.5) = -1.5, y'(1) = 0
  const CubicSpline s({0.0, 1.0, 2.0}, {0.0, 1.0, 0.0});
  constexpr double kTol = 1e-15;
  EXPECT_NEAR(s.second_derivatives()[1], -3.0, kTol);
  const CubicSpline::Value v = s.Evaluate(0.5);
  EXPECT_NEAR(v.y, 0.6875, kTol);
  EXPECT_NEAR(v.dy, 1.125, kTol);
  EXPECT_NEAR(v.d2y, -1.5, kTol);
  EXPECT_NEAR(s.Evaluate(1.0).dy, 0.0, kTol);
  // symmetric about t = 1
  EXPECT_NEAR(s.Evaluate(1.5).y, 0.6875, kTol);
  EXPECT_NEAR(s.Evaluate(1.5).dy, -1.125, kTol);
}

TEST(CubicSpline, ReproducesAStraightLineOnUnevenKnots) {
  // y = 2 - 0.7 t: M = 0 solves the system exactly
  const std::vector<double> t = {-1.0, 0.2, 0.25, 1.9, 4.0, 4.1, 7.5};
  std::vector<double> y;
  for (double x : t) y.push_back(2.0 - 0.7 * x);
  const CubicSpline s(t, y);
  constexpr double kTol = 1e-13;
  for (double x = -1.0; x <= 7.5; x += 0.01) {
    const CubicSpline::Value v = s.Evaluate(x);
    EXPECT_NEAR(v.y, 2.0 - 0.7 * x, kTol) << x;
    EXPECT_NEAR(v.dy, -0.7, kTol) << x;
    EXPECT_NEAR(v.d2y, 0.0, kTol) << x;
  }
  // two samples: the line
  const CubicSpline two({0.0, 2.0}, {1.0, 5.0});
  EXPECT_NEAR(two.Evaluate(0.5).y, 2.0, kTol);
  EXPECT_NEAR(two.Evaluate(0.5).dy, 2.0, kTol);
  EXPECT_EQ(two.Evaluate(0.5).d2y, 0.0);
}

// y = A sin(w t + f) sampled at dt = T/40 over 3 periods, starting off a zero of y'' (so the
// natural end condition is wrong there, as it is for real data)
struct SineCase {
  double amplitude = 1.7;
  double period = 10.0;
  double phase = 0.4;
  double omega() const { return 2.0 * kPi / period; }
  double Y(double t) const { return amplitude * std::sin(omega() * t + phase); }
  double Dy(double t) const { return amplitude * omega() * std::cos(omega() * t + phase); }
  double D2y(double t) const {
    return -amplitude * omega() * omega() * std::sin(omega() * t + phase);
  }
};

TEST(CubicSpline, FollowsASineAndItsDerivativesAwayFromTheEnds) {
  const SineCase c;
  const double dt = c.period / 40.0;
  std::vector<double> t, y;
  for (int i = 0; i <= 120; ++i) {
    t.push_back(0.3 + i * dt);
    y.push_back(c.Y(t.back()));
  }
  const CubicSpline s(t, y);
  // at the knots: the samples exactly
  for (size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(s.Evaluate(t[i]).y, y[i], 1e-14);
  // interior, 12 knots (0.3 T) from either end: the end error has decayed by 0.27^12 ~ 1e-7.
  // Expected errors for w dt = 2 pi / 40 = 0.157: position ~ (5/384) (w dt)^4 = 8e-6,
  // velocity ~ (w dt)^3 / 24 = 2e-4, acceleration ~ (w dt)^2 / 12 = 2e-3 (relative)
  constexpr double kPositionRelTol = 1e-4;
  constexpr double kRateRelTol = 1e-2;
  double worst_y = 0.0, worst_dy = 0.0, worst_d2y = 0.0;
  for (double x = t[12]; x <= t[108]; x += dt / 7.0) {
    const CubicSpline::Value v = s.Evaluate(x);
    worst_y = std::max(worst_y, std::abs(v.y - c.Y(x)) / c.amplitude);
    worst_dy = std::max(worst_dy, std::abs(v.dy - c.Dy(x)) / (c.amplitude * c.omega()));
    worst_d2y =
        std::max(worst_d2y, std::abs(v.d2y - c.D2y(x)) / (c.amplitude * c.omega() * c.omega()));
  }
  EXPECT_LT(worst_y, kPositionRelTol);
  EXPECT_LT(worst_dy, kRateRelTol);
  EXPECT_LT(worst_d2y, kRateRelTol);
  // and the accuracy is not trivially loose: the error is of the expected order
  EXPECT_GT(worst_d2y, 1e-5);
}

TEST(CubicSpline, IsTwiceContinuouslyDifferentiableAtTheKnots) {
  // rough data (a fixed pseudo-random sequence): a C1-only interpolant would jump by O(1) in
  // y'' at the knots; the spline must not
  std::vector<double> t, y;
  double x = 0.0;
  unsigned state = 12345u;
  for (int i = 0; i < 12; ++i) {
    state = state * 1103515245u + 12345u;
    const double r = ((state >> 16) & 0x7fff) / 32767.0;  // [0, 1]
    t.push_back(x);
    y.push_back(2.0 * r - 1.0);
    x += 0.5 + r;  // uneven spacing
  }
  const CubicSpline s(t, y);
  // one-sided differences at t_k, step d: y' from the left (3 y0 - 4 y_-1 + y_-2) / (2 d),
  // y'' from the left (y0 - 2 y_-1 + y_-2) / d^2, and mirrored from the right. Errors: O(d^2
  // y''') and O(d y''') with y''' = O(10) here, plus round-off eps / d^2 = 2e-8
  const double d = 1e-4;
  constexpr double kRateTol = 1e-6;
  constexpr double kCurvatureTol = 5e-3;
  for (size_t k = 1; k + 1 < t.size(); ++k) {
    const double tk = t[k];
    const auto f = [&](double at) { return s.Evaluate(at).y; };
    const double dy_left = (3.0 * f(tk) - 4.0 * f(tk - d) + f(tk - 2.0 * d)) / (2.0 * d);
    const double dy_right = (-3.0 * f(tk) + 4.0 * f(tk + d) - f(tk + 2.0 * d)) / (2.0 * d);
    const double d2y_left = (f(tk) - 2.0 * f(tk - d) + f(tk - 2.0 * d)) / (d * d);
    const double d2y_right = (f(tk) - 2.0 * f(tk + d) + f(tk + 2.0 * d)) / (d * d);
    const CubicSpline::Value v = s.Evaluate(tk);
    EXPECT_NEAR(dy_left, v.dy, kRateTol) << "knot " << k;
    EXPECT_NEAR(dy_right, v.dy, kRateTol) << "knot " << k;
    EXPECT_NEAR(d2y_left, v.d2y, kCurvatureTol) << "knot " << k;
    EXPECT_NEAR(d2y_right, v.d2y, kCurvatureTol) << "knot " << k;
    // the data are rough enough for the test to mean something
    if (k == 5) {
      EXPECT_GT(std::abs(v.d2y), 0.5);
    }
  }
  // natural ends
  EXPECT_EQ(s.Evaluate(t.front()).d2y, 0.0);
  EXPECT_EQ(s.Evaluate(t.back()).d2y, 0.0);
}

}  // namespace
}  // namespace towsim::core
