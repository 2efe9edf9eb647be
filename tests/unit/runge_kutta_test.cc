#include "core/runge_kutta.h"

#include <cmath>

#include <Eigen/Core>
#include <gtest/gtest.h>

namespace towsim::core {
namespace {

using Vec1 = Eigen::Matrix<double, 1, 1>;
using Vec2 = Eigen::Vector2d;

// y' = y, y(0) = 1: one step is the Taylor polynomial of e^h to degree 4,
// 1 + h + h^2/2 + h^3/6 + h^4/24 = 211/128 for h = 1/2
TEST(RungeKutta4, OneStepIsTheQuarticTaylorPolynomial) {
  constexpr double kRoundOff = 1e-15;  // h / 6 is not a binary fraction
  const Vec1 y1 = RungeKutta4(Vec1(1.0), 0.5, [](const Vec1& y, double) { return Vec1(y); });
  EXPECT_NEAR(y1(0), 211.0 / 128.0, kRoundOff);
}

// y' = 4 t^3 (the stage time t0 + c h): RK4 reduces to Simpson's rule, exact for cubics, so
// y(1) = 1 in one step from t0 = 0
TEST(RungeKutta4, StageTimesIntegrateACubicExactly) {
  constexpr double kRoundOff = 1e-15;
  const double t0 = 0.0, h = 1.0;
  const Vec1 y1 = RungeKutta4(Vec1(0.0), h, [&](const Vec1&, double c) {
    const double t = t0 + c * h;
    return Vec1(4.0 * t * t * t);
  });
  EXPECT_NEAR(y1(0), 1.0, kRoundOff);
}

// x'' = -x, x(0) = 1, v(0) = 0: x = cos t, v = -sin t. The global error at T = 1 is O(h^4):
// halving h divides it by 2^4 = 16
TEST(RungeKutta4, FourthOrderOnTheHarmonicOscillator) {
  auto error = [](int steps) {
    const double h = 1.0 / steps;
    Vec2 x(1.0, 0.0);
    for (int i = 0; i < steps; ++i)
      x = RungeKutta4(x, h, [](const Vec2& y, double) { return Vec2(y(1), -y(0)); });
    return (x - Vec2(std::cos(1.0), -std::sin(1.0))).norm();
  };
  const double e10 = error(10), e20 = error(20), e40 = error(40);
  EXPECT_LT(e10, 1e-6);
  // asymptotic ratio 16; the next term of the error, O(h^5), moves it by a few percent
  constexpr double kRatioTol = 0.5;
  EXPECT_NEAR(e10 / e20, 16.0, kRatioTol);
  EXPECT_NEAR(e20 / e40, 16.0, kRatioTol);
}

}  // namespace
}  // namespace towsim::core
