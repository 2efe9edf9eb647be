// The drum's kinematics (winch.h, AdvanceWinch) against its limits and their definitions: the
// speed and acceleration limits hold at every step, a length target and the drum's ends are
// reached exactly and at rest, the time to travel is the time-optimal (bang-coast-bang) one
// to within a step or two, the brake's slip adds to the drive, and the slip's secant iteration
// finds the slip that holds the brake's tension. The references are the limits themselves, the
// analytic minimum-time profile and the root of a known tension law.

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
    const WinchStep s = AdvanceWinch(p, command, L, V, 0.0, kH);
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
    const WinchStep s = AdvanceWinch(p, {WinchCommand::Mode::kSpeed, 0.6}, L, V, 0.0, kH);
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

TEST(Winch, BrakeSlipAddsToTheDrive) {
  const WinchParams p = Params();
  // the slip of the step on top of the drive's speed (at rest here), past max_speed and
  // max_acceleration, which the drive's part keeps
  WinchStep s = AdvanceWinch(p, {}, 150.0, 0.0, 1.5, kH);
  EXPECT_TRUE(s.slipping);
  EXPECT_EQ(s.slip_speed, 1.5);
  EXPECT_EQ(s.speed, 1.5);
  EXPECT_EQ(s.drive_speed, 0.0);
  EXPECT_DOUBLE_EQ(s.length, 150.0 + kH * 1.5);
  s = AdvanceWinch(p, {}, 150.0, 0.0, 0.0, kH);
  EXPECT_FALSE(s.slipping);
  EXPECT_EQ(s.length, 150.0);
  // the drum's end holds even a slipping brake
  s = AdvanceWinch(p, {}, p.max_length, 0.0, 1.0, kH);
  EXPECT_EQ(s.length, p.max_length);
  EXPECT_EQ(s.slip_speed, 0.0);
}

// the secant iteration on a tension that falls linearly with the slip, T(s) = T_0 - k h s (the
// reference: its root s* = (T_0 - T_b) / (k h)), and on a nonlinear one
TEST(Winch, BrakeSlipIterationSolvesTheTensionBand) {
  constexpr double kBrake = 2000.0;  // T_b [N]
  constexpr double kMaxSlip = 40.0;  // [m/s]
  // a first slope 3x too stiff (the drum element alone), the cable's true one 3x softer
  constexpr double kStiffnessH = 9.24e4 * kH;  // E A h / l_0, l_0 = 10 m [N s/m]
  const double true_slope = kStiffnessH / 3.0;
  auto tension = [&](double s) { return 2500.0 - true_slope * s; };
  BrakeSlipIteration it(kBrake, kMaxSlip, -kStiffnessH);
  double slip = 0.0, next = 0.0;
  int attempts = 1;
  while (it.Next(slip, tension(slip), &next)) {
    slip = next;
    ++attempts;
  }
  // the first correction undershoots by 3x, the secant is exact on a line: 3 attempts
  EXPECT_EQ(attempts, 3);
  EXPECT_NEAR(slip, 500.0 / true_slope, 1e-12 * kMaxSlip);
  EXPECT_LE(std::abs(tension(slip) - kBrake), kBrakeTensionRelTol * kBrake);
  // a stiffening response T = T_0 - c s - d s^3: within the band in at most 5 attempts
  auto curved = [&](double s) { return 2500.0 - 0.5 * true_slope * s - 50.0 * s * s * s; };
  BrakeSlipIteration it2(kBrake, kMaxSlip, -kStiffnessH);
  slip = 0.0;
  attempts = 1;
  while (it2.Next(slip, curved(slip), &next)) {
    slip = next;
    ++attempts;
  }
  EXPECT_LE(attempts, 5);
  EXPECT_LE(std::abs(curved(slip) - kBrake), kBrakeTensionRelTol * kBrake);
  // below the brake's tension without slip: the drum grips at once
  BrakeSlipIteration grip(kBrake, kMaxSlip, -kStiffnessH);
  EXPECT_FALSE(grip.Next(0.0, 1999.0, &next));
  EXPECT_EQ(grip.attempts(), 1);
  // a slip that leaves the tension below the brake's: less slip by the first slope, none if
  // that would be negative (the next attempt at s = 0, where it grips)
  BrakeSlipIteration less(kBrake, kMaxSlip, -kStiffnessH);
  ASSERT_TRUE(less.Next(1.0, 1000.0, &next));
  EXPECT_DOUBLE_EQ(next, 1.0 - 1000.0 / kStiffnessH);
  BrakeSlipIteration none(kBrake, kMaxSlip, -kStiffnessH);
  ASSERT_TRUE(none.Next(0.1, 0.0, &next));
  EXPECT_EQ(next, 0.0);
  EXPECT_FALSE(none.Next(0.0, 1500.0, &next));
  // more than the bound allows: the slip stops at it
  BrakeSlipIteration bound(kBrake, kMaxSlip, -kStiffnessH);
  ASSERT_TRUE(bound.Next(0.0, 1e9, &next));
  EXPECT_EQ(next, kMaxSlip);
  EXPECT_FALSE(bound.Next(kMaxSlip, 1e9, &next));
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
