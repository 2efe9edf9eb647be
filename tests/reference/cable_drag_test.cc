// Self-checks of the cable drag laws (cable_drag.h), against values of paper Eq. 18-19
// evaluated by hand.

#include "cable_drag.h"

#include <cmath>

#include <gtest/gtest.h>

namespace towsim::reference {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kHandTol = 1e-6;  // the hand values below carry 7 significant digits

TEST(CableDrag, NormalCoefficientHandValues) {
  // Re = 0.5: S = -0.07721 + ln 16 = 2.695379, C = 8 pi / (0.5 S) (1 - 0.87 / S^2)
  //          = 18.648764 * 0.880249 = 16.415553
  EXPECT_NEAR(NormalDragCoefficient(0.5), 16.415553, 1e-5);
  // Re = 10: 1.45 + 8.55 * 10^-0.9 = 1.45 + 8.55 * 0.1258925 = 2.526381
  EXPECT_NEAR(NormalDragCoefficient(10.0), 2.526381, kHandTol);
  // Re = 1e4: 1.1 + 4 / 100 = 1.14; Re = 1e5 and beyond: 1.1 + 4 / 316.2278 = 1.112649
  EXPECT_NEAR(NormalDragCoefficient(1e4), 1.14, kHandTol);
  EXPECT_NEAR(NormalDragCoefficient(1e5), 1.112649, kHandTol);
  EXPECT_EQ(NormalDragCoefficient(2.5e5), NormalDragCoefficient(1e5));
}

TEST(CableDrag, NusseltHandValue) {
  // Re = 1000: 0.55 * 31.62278 + 0.084 * 100 = 17.39253 + 8.4 = 25.79253
  EXPECT_NEAR(TangentialNusselt(1000.0), 25.79253, 1e-5);
}

// a cable along x moving with V = (3, 0, 4): normal part (0, 0, 4), tangential (3, 0, 0)
TEST(CableDrag, SplitsNormalAndTangential) {
  const Fluid fluid;
  const double d = 0.041;
  const Eigen::Vector3d f =
      CableDragPerStretchedLength(fluid, d, Eigen::Vector3d::UnitX(), {3.0, 0.0, 4.0});
  const double re_n = fluid.density * 4.0 * d / fluid.dynamic_viscosity;
  const double re_t = fluid.density * 3.0 * d / fluid.dynamic_viscosity;
  EXPECT_NEAR(f.z(), -0.5 * fluid.density * d * NormalDragCoefficient(re_n) * 16.0, 1e-9);
  EXPECT_NEAR(f.x(), -kPi * fluid.dynamic_viscosity * TangentialNusselt(re_t) * 3.0, 1e-12);
  EXPECT_EQ(f.y(), 0.0);
  EXPECT_LT(f.z(), 0.0);  // opposes the motion
}

}  // namespace
}  // namespace towsim::reference
