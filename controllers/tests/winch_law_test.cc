// towfish_depth's winch law (controllers/towfish_depth/winch_law.h) on a plant with the
// property the law relies on: the towfish's steady depth grows with the paid-out length,
// z_ss = z0 + s (L - L0), and the depth follows it with a first-order lag (the cable settling).

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "towfish_depth/winch_law.h"

namespace towsim::controllers {
namespace {

struct PlantRun {
  double final_depth = 0.0, final_length = 0.0;
  double max_speed = 0.0, max_acceleration = 0.0;
};

// the plant: dL/dt = v (the commanded speed, as the drum does within its limits);
// z' = (z0 + slope (L - L0) - z) / lag
PlantRun Simulate(const WinchDepthParams& p, double target, double seconds, double slope = 0.3,
             double lag = 8.0) {
  WinchDepthState s;
  const double dt = 0.05, z0 = 30.0, l0 = 150.0;
  double z = z0, length = l0, last_v = 0.0;
  PlantRun r;
  for (double t = 0.0; t < seconds; t += dt) {
    const double v = WinchDepthStep(p, s, target, z, 0.0, dt);
    r.max_speed = std::max(r.max_speed, std::abs(v));
    r.max_acceleration = std::max(r.max_acceleration, std::abs(v - last_v) / dt);
    last_v = v;
    length += v * dt;
    z += (z0 + slope * (length - l0) - z) * dt / lag;
  }
  r.final_depth = z;
  r.final_length = length;
  return r;
}

TEST(WinchDepthLaw, PaysOutToGoDeeperAndSettlesInTheDeadband) {
  WinchDepthParams p;
  const PlantRun r = Simulate(p, 45.0, 600.0);
  // 15 m deeper at dz/dL = 0.3 needs 50 m more cable; the law stops within its deadband, and
  // after 600 s (75 lags) the depth is the steady one of the length reached
  constexpr double kSettledTol = 1e-3;  // [m]
  EXPECT_NEAR(r.final_depth, 45.0, p.deadband);
  EXPECT_NEAR(r.final_length, 150.0 + (r.final_depth - 30.0) / 0.3, kSettledTol / 0.3);
  // within the limits given (the acceleration to its rounding in the finite difference)
  EXPECT_LE(r.max_speed, p.max_speed + 1e-12);
  EXPECT_LE(r.max_acceleration, p.max_acceleration * (1.0 + 1e-9));
}

TEST(WinchDepthLaw, ReelsInToComeUp) {
  WinchDepthParams p;
  const PlantRun r = Simulate(p, 20.0, 600.0);
  EXPECT_NEAR(r.final_depth, 20.0, p.deadband);
  EXPECT_LT(r.final_length, 150.0);
}

TEST(WinchDepthLaw, SpeedAndAccelerationLimitsHoldOnALargeStep) {
  WinchDepthParams p;
  p.max_speed = 0.5;
  p.max_acceleration = 0.05;
  const PlantRun r = Simulate(p, 90.0, 60.0);  // a 60 m step: saturated all along
  EXPECT_NEAR(r.max_speed, 0.5, 1e-12);
  EXPECT_LE(r.max_acceleration, 0.05 * (1.0 + 1e-9));
}

TEST(WinchDepthLaw, StandsStillInsideTheDeadband) {
  WinchDepthParams p;
  WinchDepthState s;
  for (int k = 0; k < 100; ++k) EXPECT_EQ(WinchDepthStep(p, s, 30.3, 30.0, 0.0, 0.05), 0.0);
}

TEST(WinchDepthLaw, OffloadsTheElevatorsSteadyDemand) {
  // at the commanded depth with the elevators pushing down 0.1 rad: the drum pays out, at
  // k (elevator_depth d - deadband) once the filter has settled (10 filter constants)
  WinchDepthParams p;
  WinchDepthState s;
  double v = 0.0;
  for (int k = 0; k < 2000; ++k) v = WinchDepthStep(p, s, 30.0, 30.0, 0.1, 0.05);
  EXPECT_NEAR(v, p.gain * (p.elevator_depth * 0.1 - p.deadband), 1e-9);
  // pulling up: it reels in
  WinchDepthState up;
  for (int k = 0; k < 2000; ++k) v = WinchDepthStep(p, up, 30.0, 30.0, -0.1, 0.05);
  EXPECT_LT(v, 0.0);
}

}  // namespace
}  // namespace towsim::controllers
