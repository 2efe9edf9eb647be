// The controllers' pure control laws: angles, the PID (step response, saturation,
// anti-windup, rate limit), the Case 2 U-turn decision and the towfish depth law.

#include <cmath>

#include <gtest/gtest.h>

#include "common/laws.h"
#include "maneuver_runner/uturn.h"
#include "towfish_depth/depth_law.h"

namespace towsim::controllers {
namespace {

TEST(Angles, WrapPiFoldsIntoMinusPiPi) {
  EXPECT_NEAR(WrapPi(Rad(190)), Rad(-170), 1e-12);
  EXPECT_NEAR(WrapPi(Rad(-190)), Rad(170), 1e-12);
  EXPECT_NEAR(WrapPi(kPi), kPi, 1e-12);
  EXPECT_NEAR(WrapPi(-kPi), kPi, 1e-12);
  EXPECT_NEAR(WrapPi(Rad(720 + 10)), Rad(10), 1e-12);
}

TEST(Angles, EulerFromQuaternionZyx) {
  // yaw 170 deg about z, then pitch 10 deg, roll 5 deg
  const double y = Rad(170), p = Rad(10), r = Rad(5);
  const double cy = std::cos(y / 2), sy = std::sin(y / 2), cp = std::cos(p / 2),
               sp = std::sin(p / 2), cr = std::cos(r / 2), sr = std::sin(r / 2);
  const double qw = cr * cp * cy + sr * sp * sy, qx = sr * cp * cy - cr * sp * sy,
               qy = cr * sp * cy + sr * cp * sy, qz = cr * cp * sy - sr * sp * cy;
  const Euler e = EulerFromQuaternion(qx, qy, qz, qw);
  EXPECT_NEAR(e.yaw, y, 1e-12);
  EXPECT_NEAR(e.pitch, p, 1e-12);
  EXPECT_NEAR(e.roll, r, 1e-12);
  // yaw past 180 deg comes back negative
  const Euler back = EulerFromQuaternion(0, 0, std::sin(Rad(190) / 2), std::cos(Rad(190) / 2));
  EXPECT_NEAR(back.yaw, Rad(-170), 1e-12);
}

TEST(Angles, BodyToWorldPitchedBodyDescends) {
  // bow down 30 deg (pitch -30 deg): forward speed 2 m/s sinks at 1 m/s (z down in NED)
  const double h = Rad(-30) / 2;
  const Vec3 v = BodyToWorld(0, std::sin(h), 0, std::cos(h), {2, 0, 0});
  EXPECT_NEAR(v.x, std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(v.z, 1.0, 1e-12);
}

// a first-order plant x' = (u - x) / tau driven by a PID towards 1
double Simulate(const PidParams& p, double seconds, double* max_u = nullptr) {
  PidState s;
  double x = 0.0, xdot = 0.0;
  const double dt = 0.01, tau = 0.5;
  for (double t = 0; t < seconds; t += dt) {
    const double u = PidStep(p, s, 1.0 - x, xdot, dt);
    if (max_u != nullptr) *max_u = std::max(*max_u, std::abs(u));
    xdot = (u - x) / tau;
    x += xdot * dt;
  }
  return x;
}

TEST(Pid, StepResponseSettlesWithoutSteadyError) {
  PidParams p;
  p.kp = 2.0;
  p.ki = 2.0;
  p.kd = 0.05;
  p.out_min = -5;
  p.out_max = 5;
  EXPECT_NEAR(Simulate(p, 20.0), 1.0, 1e-4);
  p.ki = 0.0;  // P alone leaves the classic error 1 / (1 + kp)
  EXPECT_NEAR(Simulate(p, 20.0), 2.0 / 3.0, 1e-3);
}

TEST(Pid, OutputSaturates) {
  PidParams p;
  p.kp = 100.0;
  p.out_min = -0.5;
  p.out_max = 0.5;
  PidState s;
  EXPECT_DOUBLE_EQ(PidStep(p, s, 10.0, 0.0, 0.1), 0.5);
  EXPECT_DOUBLE_EQ(PidStep(p, s, -10.0, 0.0, 0.1), -0.5);
}

TEST(Pid, AntiWindupStopsIntegratingInSaturation) {
  PidParams p;
  p.kp = 1.0;
  p.ki = 1.0;
  p.out_min = -1.0;
  p.out_max = 1.0;
  PidState s;
  for (int i = 0; i < 1000; ++i) PidStep(p, s, 5.0, 0.0, 0.1);  // 100 s saturated high
  EXPECT_LE(s.integral, 1.0 / p.ki + 1e-12);
  // once the error reverses the output leaves saturation at once, not after unwinding 500
  const double u = PidStep(p, s, -1.5, 0.0, 0.1);
  EXPECT_LT(u, 1.0);
}

TEST(Pid, RateLimitBoundsTheChangePerStep) {
  PidParams p;
  p.kp = 10.0;
  p.out_min = -1.0;
  p.out_max = 1.0;
  p.rate_limit = 0.2;  // per second
  PidState s;
  EXPECT_NEAR(PidStep(p, s, 1.0, 0.0, 0.5), 0.1, 1e-12);
  EXPECT_NEAR(PidStep(p, s, 1.0, 0.0, 0.5), 0.2, 1e-12);
  EXPECT_NEAR(PidStep(p, s, -1.0, 0.0, 0.5), 0.1, 1e-12);
}

TEST(Pid, DerivativeActsOnTheMeasurement) {
  PidParams p;
  p.kd = 1.0;
  p.out_min = -10;
  p.out_max = 10;
  PidState s;
  // a setpoint jump (error jumps) gives no derivative kick; a rising measurement brakes
  EXPECT_DOUBLE_EQ(PidStep(p, s, 5.0, 0.0, 0.1), 0.0);
  EXPECT_DOUBLE_EQ(PidStep(p, s, 5.0, 2.0, 0.1), -2.0);
}

TEST(UTurn, ThrustAlwaysRudderFromStartUntilYaw) {
  UTurnParams p;
  p.thrust = 4165;
  p.rudder = Rad(20);
  p.start = 55;
  p.until_yaw = Rad(170);
  UTurnState s;
  ManeuverCommand c = UTurnStep(p, s, 0.0, 0.0);
  EXPECT_EQ(c.thrust, 4165);
  EXPECT_EQ(c.rudder, 0.0);
  EXPECT_EQ(UTurnStep(p, s, 54.95, 0.0).rudder, 0.0);
  EXPECT_DOUBLE_EQ(UTurnStep(p, s, 55.0 - 1e-12, 0.0).rudder, Rad(20));  // t >= 55 to 1e-9
  EXPECT_DOUBLE_EQ(UTurnStep(p, s, 60.0, Rad(100)).rudder, Rad(20));
  EXPECT_DOUBLE_EQ(UTurnStep(p, s, 70.0, Rad(169.9)).rudder, Rad(20));
  c = UTurnStep(p, s, 70.5, Rad(170.0));
  EXPECT_EQ(c.rudder, 0.0);
  EXPECT_EQ(c.thrust, 4165);
  EXPECT_TRUE(s.turned);
}

TEST(UTurn, YawWrappingPast180DoesNotRestartTheTurn) {
  UTurnParams p;
  p.rudder = Rad(20);
  p.until_yaw = Rad(170);
  UTurnState s;
  EXPECT_EQ(UTurnStep(p, s, 71.0, Rad(171)).rudder, 0.0);
  EXPECT_EQ(UTurnStep(p, s, 75.0, Rad(-172)).rudder, 0.0);  // yaw wrapped
  EXPECT_EQ(UTurnStep(p, s, 200.0, Rad(0)).rudder, 0.0);
}

TEST(UTurn, PortTurnEndsBelowTheYaw) {
  UTurnParams p;
  p.rudder = Rad(-20);
  p.until_yaw = Rad(-170);
  UTurnState s;
  EXPECT_EQ(UTurnStep(p, s, 60.0, Rad(-100)).rudder, Rad(-20));
  EXPECT_EQ(UTurnStep(p, s, 70.0, Rad(-170.5)).rudder, 0.0);
}

TEST(UTurn, ZeroRudderIsCase1) {
  UTurnParams p;
  p.rudder = 0.0;
  UTurnState s;
  for (double t : {0.0, 55.0, 100.0}) EXPECT_EQ(UTurnStep(p, s, t, 0.3).rudder, 0.0);
}

TEST(DepthLaw, SignFollowsTheErrorAndHoldMeansZero) {
  DepthParams p;
  p.depth = 25;
  PidState s;
  // a towfish rises on positive elevator (bow up)
  EXPECT_GT(DepthStep(p, s, 30.0, 0.0, 0.0, 0.05), 0.0);  // too deep: positive elevator
  PidState s2;
  EXPECT_LT(DepthStep(p, s2, 20.0, 0.0, 0.0, 0.05), 0.0);  // too shallow: negative
  p.sign = 1.0;  // a body that dives on positive elevator
  PidState s4;
  EXPECT_LT(DepthStep(p, s4, 30.0, 0.0, 0.0, 0.05), 0.0);
  p.hold = true;
  PidState s3;
  EXPECT_EQ(DepthStep(p, s3, 30.0, 1.0, 0.0, 0.05), 0.0);
}

TEST(DepthLaw, SaturatesAtTheTravelAndIsRateLimited) {
  DepthParams p;
  p.depth = 25;
  p.max_elevator = Rad(25);
  p.rate_limit = Rad(20);
  PidState s;
  double e = 0.0;
  for (int k = 0; k < 40; ++k) {
    const double next = DepthStep(p, s, 200.0, 0.0, 0.0, 0.05);  // 175 m too deep
    EXPECT_LE(next - e, Rad(20) * 0.05 + 1e-12);
    e = next;
  }
  EXPECT_NEAR(e, Rad(25), 1e-12);  // 25 deg at 20 deg/s: reached after 1.25 s
  EXPECT_LE(s.integral * p.ki, p.max_elevator + 1e-12);  // no windup
}

TEST(DepthLaw, RisingFishIsDampedByTheDepthRate) {
  DepthParams p;
  p.depth = 25;
  p.rate_limit = 0;  // none
  PidState a, b;
  // on depth, but rising fast (z decreasing): bow down (negative); sinking: bow up
  EXPECT_LT(DepthStep(p, a, 25.0, -1.0, 0.0, 0.05), 0.0);
  EXPECT_GT(DepthStep(p, b, 25.0, 1.0, 0.0, 0.05), 0.0);
}

TEST(DepthLaw, DisengagedWhileTheFishHangsSteeply) {
  DepthParams p;
  p.depth = 25;
  p.max_pitch = Rad(30);
  PidState s;
  for (int k = 0; k < 10; ++k) DepthStep(p, s, 200.0, 0.0, 0.0, 0.05);
  EXPECT_NE(s.output, 0.0);  // the PID's internal "deeper" demand
  EXPECT_EQ(DepthStep(p, s, 200.0, 0.0, Rad(60), 0.05), 0.0);  // nose up 60 deg: off
  EXPECT_EQ(s.integral, 0.0);                                  // and reset
  EXPECT_EQ(DepthStep(p, s, 200.0, 0.0, Rad(-45), 0.05), 0.0);
  // re-engaged: from 0, at the rate limit
  EXPECT_NEAR(DepthStep(p, s, 200.0, 0.0, Rad(10), 0.05), p.rate_limit * 0.05, 1e-12);
}

// a crude heave model: the elevator's lift moves the depth rate towards -k * elevator with a
// lag; a steady upward pull of the cable needs an integral to hold the depth
TEST(DepthLaw, HoldsDepthAgainstASteadyPull) {
  DepthParams p;
  p.depth = 25;
  PidState s;
  double z = 25, zdot = 0;
  const double dt = 0.05;
  for (int k = 0; k < 6000; ++k) {
    const double el = DepthStep(p, s, z, zdot, 0.0, dt);
    const double target = -3.0 * el - 0.3;  // 0.3 m/s of steady rise from the cable
    zdot += (target - zdot) * dt / 1.0;
    z += zdot * dt;
  }
  EXPECT_NEAR(z, 25.0, 0.05);
}

}  // namespace
}  // namespace towsim::controllers
