// The actuator law (actuator.h) against its definition, x_dot = clamp((clamp(u) - x) / T,
// +-max_rate), and the vehicles' actuators against the vehicle file's numbers. Every value is
// a power of two or a small integer, so the arithmetic is exact and so are the comparisons.

#include "core/actuator.h"

#include <gtest/gtest.h>

namespace towsim::core {
namespace {

TEST(Actuator, FirstOrderLagInsideTheRange) {
  Actuator a;
  a.min = -1.0;
  a.max = 4.0;
  a.time_constant = 0.5;
  EXPECT_EQ(a.Rate(3.0, 1.0), 4.0);    // (3 - 1) / 0.5
  EXPECT_EQ(a.Rate(-1.0, 1.0), -4.0);  // (-1 - 1) / 0.5
}

TEST(Actuator, CommandClampedToTheRange) {
  Actuator a;
  a.min = -1.0;
  a.max = 4.0;
  a.time_constant = 0.5;
  EXPECT_EQ(a.Rate(10.0, 0.0), 8.0);    // target 4
  EXPECT_EQ(a.Rate(-10.0, 0.0), -2.0);  // target -1
  double u = 7.0;
  EXPECT_TRUE(a.Clamp(&u));
  EXPECT_EQ(u, 4.0);
  u = 2.0;
  EXPECT_FALSE(a.Clamp(&u));
  EXPECT_EQ(u, 2.0);
}

TEST(Actuator, RateLimited) {
  Actuator a;
  a.min = -1.0;
  a.max = 1.0;
  a.max_rate = 0.25;
  a.time_constant = 0.0625;
  EXPECT_EQ(a.Rate(1.0, 0.0), 0.25);  // (1 - 0) / 0.0625 = 16, limited
  EXPECT_EQ(a.Rate(-1.0, 0.0), -0.25);
  EXPECT_EQ(a.Rate(0.0078125, 0.0), 0.125);  // 0.0078125 / 0.0625 = 0.125 < 0.25
}

TEST(Actuator, ThrustRangeIsAQuarterAstern) {
  VehicleParams p;
  p.has_propeller = true;
  p.max_thrust = 12000.0;
  p.thrust_time_constant = 2.0;
  const Actuator a = ThrustActuator(p);
  EXPECT_EQ(a.min, -3000.0);
  EXPECT_EQ(a.max, 12000.0);
  EXPECT_EQ(a.time_constant, 2.0);
  EXPECT_EQ(a.Rate(20000.0, 0.0), 6000.0);  // no rate limit: (12000 - 0) / 2
  p.has_propeller = false;
  const Actuator none = ThrustActuator(p);
  EXPECT_EQ(none.min, 0.0);
  EXPECT_EQ(none.max, 0.0);
}

TEST(Actuator, FinServoFromTheVehicleFile) {
  ActuatorLimits limits;
  limits.max_deflection = 0.5;
  limits.max_rate = 0.125;
  const Actuator a = FinActuator(limits);
  EXPECT_EQ(a.min, -0.5);
  EXPECT_EQ(a.max, 0.5);
  EXPECT_EQ(a.max_rate, 0.125);
  EXPECT_EQ(a.time_constant, kFinServoTimeConstant);
}

// one row per VehicleActuator: each state driven by its own command through its own law
TEST(Actuator, VehicleActuatorRatesFollowTheTable) {
  VehicleParams p;
  p.has_propeller = true;
  p.max_thrust = 1000.0;
  p.thrust_time_constant = 2.0;
  p.rudder = {0.5, 0.25};
  p.elevator = {0.25, 0.125};
  VehicleCommand cmd;
  cmd.thrust = 400.0;
  cmd.rudder = 1.0;      // beyond the range: clamped to 0.5
  cmd.elevator = -0.25;  // at the limit
  VehicleState s;
  s.actuator[kThrust] = 200.0;
  const std::array<double, kVehicleActuatorCount> rate = ActuatorRates(p, cmd, s);
  EXPECT_EQ(rate[kThrust], 100.0);     // (400 - 200) / 2
  EXPECT_EQ(rate[kRudder], 0.25);      // 0.5 / 0.05 = 10, limited to 0.25
  EXPECT_EQ(rate[kElevator], -0.125);  // -0.25 / 0.05 = -5, limited to -0.125
  p.has_propeller = false;             // no propeller: its state does not move
  EXPECT_EQ(ActuatorRates(p, cmd, s)[kThrust], 0.0);
}

}  // namespace
}  // namespace towsim::core
