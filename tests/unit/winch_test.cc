// The drum's kinematics (winch.h, AdvanceWinch) against its limits and their definitions: the
// speed and acceleration limits hold at every step, a length target and the drum's ends are
// reached exactly and at rest, the time to travel is the time-optimal (bang-coast-bang) one
// to within a step or two, and the brake slips by the excess it must relieve. The references
// are the limits themselves and the analytic minimum-time profile.

#include "core/winch.h"

#include <cmath>

#include <gtest/gtest.h>

namespace towsim::core {
namespace {

constexpr double kH = 0.05;  // [s]
// the limits hold up to the rounding of V + clamp(...) (a few ulps of the speed)
constexpr double kLimitTol = 1e-12;
// the discrete profile brakes along u^2 + a h u = 2 a d (winch.h), a little earlier than the
// continuous one: it may arrive up to two steps after the continuous time-optimal profile
constexpr double kArrivalSlack = 2.0 * kH;

WinchParams Params() {
  // min_length, max_length [m], max_speed [m/s], max_acceleration [m/s^2]
  WinchParams p{50.0, 250.0, 1.0, 0.2};
  return p;
}

// minimum time from rest to rest over a distance d (trapezoidal or triangular speed profile)
double MinimumTime(const WinchParams& p, double d) {
  const double v = p.max_speed, a = p.max_acceleration;
  if (d >= v * v / a) return d / v + v / a;
  return 2.0 * std::sqrt(d / a);
}

struct DriveRecord {
  double arrival = -1.0;  // first time at the target at rest
  double max_speed = 0.0, max_accel = 0.0;
  bool overshoot = false;
};

// drives the drum from `length` under `command` for `duration`, recording the limits
DriveRecord Drive(const WinchParams& p, const WinchCommand& command, double length, double target,
          double duration, double* final_length = nullptr) {
  DriveRecord run;
  double L = length, V = 0.0;
  const double sign = target > length ? 1.0 : -1.0;
  for (int k = 1; k * kH <= duration; ++k) {
    const WinchStep s = AdvanceWinch(p, command, L, V, 0.0, 0.0, 0.0, kH);
    run.max_speed = std::max(run.max_speed, std::abs(s.speed));
    run.max_accel = std::max(run.max_accel, std::abs(s.speed - V) / kH);
    if (sign * (s.length - target) > 0.0) run.overshoot = true;
    L = s.length;
    V = s.speed;
    if (run.arrival < 0.0 && L == target && V == 0.0) run.arrival = k * kH;
  }
  if (final_length) *final_length = L;
  return run;
}

TEST(Winch, LengthTargetReachedExactlyAndTimeOptimally) {
  const WinchParams p = Params();
  for (const double target : {150.0, 100.7, 152.3, 230.0, 60.0}) {
    double final_length = 0.0;
    const DriveRecord run =
        Drive(p, {WinchCommand::Mode::kLength, target}, 150.0, target, 400.0, &final_length);
    SCOPED_TRACE(target);
    EXPECT_EQ(final_length, target);  // stops exactly and stays
    EXPECT_FALSE(run.overshoot);
    EXPECT_LE(run.max_speed, p.max_speed * (1.0 + kLimitTol));
    EXPECT_LE(run.max_accel, p.max_acceleration * (1.0 + kLimitTol));
    if (target == 150.0) continue;
    const double t_min = MinimumTime(p, std::abs(target - 150.0));
    EXPECT_GE(run.arrival, t_min - kH);
    EXPECT_LE(run.arrival, t_min + kArrivalSlack);
  }
}

TEST(Winch, SpeedCommandStopsExactlyAtTheDrumsEnds) {
  const WinchParams p = Params();
  // paying out at full speed into max_length, reeling in at full speed into min_length
  double end = 0.0;
  DriveRecord run = Drive(p, {WinchCommand::Mode::kSpeed, 5.0}, 150.0, p.max_length, 300.0, &end);
  EXPECT_EQ(end, p.max_length);
  EXPECT_FALSE(run.overshoot);
  EXPECT_LE(run.max_speed, p.max_speed * (1.0 + kLimitTol));  // 5 m/s clamped to 1 m/s
  EXPECT_LE(run.max_accel, p.max_acceleration * (1.0 + kLimitTol));
  run = Drive(p, {WinchCommand::Mode::kSpeed, -0.5}, 150.0, p.min_length, 300.0, &end);
  EXPECT_EQ(end, p.min_length);
  EXPECT_FALSE(run.overshoot);
  EXPECT_LE(run.max_speed, 0.5 * (1.0 + kLimitTol));
  EXPECT_LE(run.max_accel, p.max_acceleration * (1.0 + kLimitTol));
}

TEST(Winch, SpeedCommandReachedAtTheAccelerationLimit) {
  const WinchParams p = Params();
  double L = 150.0, V = 0.0;
  int steps = 0;
  while (V < 0.6) {
    const WinchStep s = AdvanceWinch(p, {WinchCommand::Mode::kSpeed, 0.6}, L, V, 0.0, 0.0, 0.0, kH);
    EXPECT_NEAR(s.speed - V, std::min(p.max_acceleration * kH, 0.6 - V), 1e-15);
    // constant acceleration over the step: the trapezoidal length update
    EXPECT_DOUBLE_EQ(s.length, L + 0.5 * kH * (V + s.speed));
    L = s.length;
    V = s.speed;
    ++steps;
  }
  // 0.6 m/s at 0.2 m/s^2: 3 s, 60 steps of 0.01 m/s
  EXPECT_EQ(steps, 60);
  EXPECT_EQ(V, 0.6);
}

TEST(Winch, BrakeSlipIntegratesTheExcessTension) {
  WinchParams p = Params();
  p.brake_tension = 10000.0;
  const double compliance = 10.0 / 9.24e5;  // l_0 / (E A): 10 m of the shipped cable
  // holding: below the brake tension nothing moves
  WinchStep s = AdvanceWinch(p, {}, 150.0, 0.0, 0.0, 9999.0, compliance, kH);
  EXPECT_EQ(s.speed, 0.0);
  EXPECT_FALSE(s.slipping);
  // 2000 N above it: s = 2000 l_0 / (E A h), past max_speed and max_acceleration, on top of
  // the drive's speed (here at rest), which the slip leaves alone
  s = AdvanceWinch(p, {}, 150.0, 0.0, 0.0, 12000.0, compliance, kH);
  EXPECT_TRUE(s.slipping);
  EXPECT_DOUBLE_EQ(s.slip_speed, 2000.0 * compliance / kH);
  EXPECT_EQ(s.speed, s.slip_speed);
  EXPECT_DOUBLE_EQ(s.length, 150.0 + kH * s.speed);
  EXPECT_EQ(s.drive_speed, 0.0);
  // the excess again: the slip grows by as much; 1000 N below: it falls by half of that
  const double s1 = s.slip_speed;
  s = AdvanceWinch(p, {}, s.length, 0.0, s1, 12000.0, compliance, kH);
  EXPECT_DOUBLE_EQ(s.slip_speed, 2.0 * s1);
  s = AdvanceWinch(p, {}, s.length, 0.0, s1, 9000.0, compliance, kH);
  EXPECT_DOUBLE_EQ(s.slip_speed, 0.5 * s1);
  // far below: the drum grips (no negative slip)
  s = AdvanceWinch(p, {}, s.length, 0.0, s1, 0.0, compliance, kH);
  EXPECT_EQ(s.slip_speed, 0.0);
  EXPECT_FALSE(s.slipping);
  // the drum's end holds even a slipping brake
  s = AdvanceWinch(p, {}, p.max_length, 0.0, 1.0, 1e9, compliance, kH);
  EXPECT_EQ(s.length, p.max_length);
}

TEST(Winch, CommandsClampedIntoTheirRanges) {
  const WinchParams p = Params();
  WinchCommand c{WinchCommand::Mode::kSpeed, -3.0};
  EXPECT_TRUE(ClampWinchCommand(p, &c));
  EXPECT_EQ(c.value, -1.0);
  c = {WinchCommand::Mode::kLength, 300.0};
  EXPECT_TRUE(ClampWinchCommand(p, &c));
  EXPECT_EQ(c.value, 250.0);
  c = {WinchCommand::Mode::kLength, 120.0};
  EXPECT_FALSE(ClampWinchCommand(p, &c));
  EXPECT_EQ(c.value, 120.0);
  const Actuator speed = WinchSpeedRange(p);
  EXPECT_EQ(speed.min, -1.0);
  EXPECT_EQ(speed.max, 1.0);
  EXPECT_EQ(speed.max_rate, 0.2);
}

}  // namespace
}  // namespace towsim::core
