// The manoeuvre runner's pure logic: the zig-zag state machine and its trials sheet
// against hand-computed sequences, the turning circle's decision and sheet against a circle
// of known geometry, Kasa's circle fit.

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "common/laws.h"
#include "maneuver_runner/payout.h"
#include "maneuver_runner/turning_circle.h"
#include "maneuver_runner/zigzag.h"

namespace towsim::controllers {
namespace {

constexpr double kExact = 1e-12;  // pure arithmetic on the given samples

ZigZagParams TenTen() {
  ZigZagParams p;
  p.thrust = 4000;
  p.rudder = Rad(10);
  p.switch_angle = Rad(10);
  p.start = 10;
  p.reversals = 3;
  return p;
}

TEST(ZigZag, SwitchingSequenceAndOvershootsOfAHandComputedTrack) {
  const ZigZagParams p = TenTen();
  ZigZagState s;
  // (t, heading deg, expected rudder deg) with psi_0 = 30 deg at execute (t = 10)
  struct Row {
    double t, psi, rudder;
  };
  const std::vector<Row> rows = {
      {9.0, 30, 0},                                           // before execute: thrust only
      {10.0, 30, 10},                                         // execute: +10 deg
      {11.0, 35, 10},   {12.0, 39.9, 10}, {13.0, 40.5, -10},  // change 10.5 >= 10: 1st reversal
      {14.0, 43, -10},  {15.0, 44, -10},  // peak: change 14, 1st overshoot 4 deg at t = 15
      {16.0, 41, -10},  {17.0, 25, -10},  {18.0, 19.5, 10},  // change -10.5 <= -10: 2nd reversal
      {19.0, 17.5, 10},                   // peak: change -12.5, 2nd overshoot 2.5 deg at t = 19
      {20.0, 20, 10},   {21.0, 40, -10},  // change exactly 10 >= 10: 3rd reversal
      {21.5, 41, -10},                    // peak: change 11, 3rd overshoot 1 deg at t = 21.5
  };
  for (const Row& r : rows) {
    const ManeuverCommand c = ZigZagStep(p, s, r.t, Rad(r.psi));
    EXPECT_EQ(c.thrust, 4000);
    EXPECT_NEAR(c.rudder, Rad(r.rudder), kExact) << "t = " << r.t;
  }
  // the heading swings back to a change of -10 deg: after 3 reversals, the end
  ZigZagStep(p, s, 22.0, Rad(30));
  EXPECT_FALSE(s.finished);
  const ManeuverCommand end = ZigZagStep(p, s, 23.0, Rad(19.9));  // change -10.1: 4th switch
  EXPECT_TRUE(s.finished);
  EXPECT_EQ(end.rudder, 0.0);
  EXPECT_EQ(ZigZagStep(p, s, 30.0, Rad(50)).rudder, 0.0);  // stays 0

  const ZigZagResults r = ZigZagSheet(s);
  EXPECT_TRUE(r.finished);
  EXPECT_NEAR(r.t_execute, 10.0, kExact);
  EXPECT_NEAR(r.initial_turning_time, 3.0, kExact);  // 13 - 10
  ASSERT_EQ(r.overshoots.size(), 3u);
  EXPECT_NEAR(Deg(r.overshoots[0]), 4.0, 1e-9);       // 44 - 30 - 10
  EXPECT_NEAR(Deg(r.overshoots[1]), 2.5, 1e-9);       // 30 - 17.5 - 10
  EXPECT_NEAR(Deg(r.overshoots[2]), 1.0, 1e-9);       // 41 - 30 - 10
  EXPECT_NEAR(r.times_to_check_yaw[0], 2.0, kExact);  // 15 - 13
  EXPECT_NEAR(r.times_to_check_yaw[1], 1.0, kExact);  // 19 - 18
  EXPECT_NEAR(r.times_to_check_yaw[2], 0.5, kExact);  // 21.5 - 21
  ASSERT_EQ(r.periods.size(), 1u);
  EXPECT_NEAR(r.periods[0], 8.0, kExact);  // reversal 1 (13 s) -> 3 (21 s)
}

TEST(ZigZag, HeadingChangeIsUnwrappedAcross180) {
  ZigZagParams p = TenTen();
  p.start = 0;
  ZigZagState s;
  EXPECT_NEAR(ZigZagStep(p, s, 0.0, Rad(175)).rudder, Rad(10), kExact);
  EXPECT_NEAR(ZigZagStep(p, s, 1.0, Rad(179)).rudder, Rad(10), kExact);
  // 175 -> -176 deg is +9 deg of change, not -351: no switch yet
  EXPECT_NEAR(ZigZagStep(p, s, 2.0, Rad(-176)).rudder, Rad(10), kExact);
  EXPECT_NEAR(Deg(s.change), 9.0, 1e-9);
  // -174.5 deg: change 10.5: reversal
  EXPECT_NEAR(ZigZagStep(p, s, 3.0, Rad(-174.5)).rudder, Rad(-10), kExact);
  // back across 180 to 164 deg: change -11: the next reversal
  ZigZagStep(p, s, 4.0, Rad(179));
  EXPECT_NEAR(ZigZagStep(p, s, 5.0, Rad(164)).rudder, Rad(10), kExact);
  const ZigZagResults r = ZigZagSheet(s);
  ASSERT_EQ(r.overshoots.size(), 1u);
  EXPECT_NEAR(Deg(r.overshoots[0]), 0.5, 1e-9);  // peak change 10.5 at the reversal itself
}

TEST(ZigZag, PortFirstMirrorsTheSequence) {
  ZigZagParams p = TenTen();
  p.port_first = true;
  p.start = 0;
  ZigZagState s;
  EXPECT_NEAR(ZigZagStep(p, s, 0.0, 0.0).rudder, Rad(-10), kExact);
  EXPECT_NEAR(ZigZagStep(p, s, 1.0, Rad(9)).rudder, Rad(-10), kExact);  // wrong way: no switch
  EXPECT_NEAR(ZigZagStep(p, s, 2.0, Rad(-10)).rudder, Rad(10), kExact);
}

// a vehicle on a circle of radius R at speed U from t = 0, heading 30 deg at execute,
// turning to starboard: centre to starboard of the start
std::vector<TrackSample> CircleTrack(double radius, double speed, double psi0, double turns,
                                     double dt) {
  std::vector<TrackSample> track;
  const double r = speed / radius;                                           // yaw rate
  const double cx = -radius * std::sin(psi0), cy = radius * std::cos(psi0);  // centre
  for (double t = 0; t * r <= turns * 2 * kPi + 1e-12; t += dt) {
    const double psi = psi0 + r * t;
    TrackSample s;
    s.t = 100 + t;
    s.x = cx + radius * std::sin(psi);
    s.y = cy - radius * std::cos(psi);
    s.yaw = WrapPi(psi);
    s.speed = speed;
    s.yaw_rate = r;
    track.push_back(s);
  }
  return track;
}

TEST(TurningCircle, SheetOfAnExactCircle) {
  const double radius = 25, speed = 5, psi0 = Rad(30);
  const std::vector<TrackSample> track = CircleTrack(radius, speed, psi0, 2.0, 0.05);
  const TurningCircleResults r = TurningCircleSheet(track);
  // on a circle from the start: advance = transfer = R at 90 deg, tactical diameter 2R; the
  // interpolation along chords of 0.01 rad is off by at most R (0.01)^2 / 8 = 3e-4 m
  constexpr double kChord = 1e-3;  // [m]
  ASSERT_TRUE(r.has_90 && r.has_180 && r.has_steady);
  EXPECT_NEAR(r.advance, radius, kChord);
  EXPECT_NEAR(r.transfer, radius, kChord);
  EXPECT_NEAR(r.tactical_diameter, 2 * radius, kChord);
  EXPECT_NEAR(r.time_90, 0.5 * kPi * radius / speed, 1e-3);
  EXPECT_NEAR(r.time_180, kPi * radius / speed, 1e-3);
  EXPECT_NEAR(r.steady_diameter, 2 * radius, 1e-9);  // the fit is exact on exact points
  EXPECT_NEAR(r.kinematic_diameter, 2 * radius, 1e-9);
  EXPECT_NEAR(r.total_turn, 4 * kPi, 0.01);
}

TEST(TurningCircle, PortTurnGivesNegativeTransferAndNoSteadyCircleWhenShort) {
  std::vector<TrackSample> track = CircleTrack(40, 4, 0.0, 1.2, 0.1);
  for (TrackSample& s : track) s.y = -s.y, s.yaw = -s.yaw, s.yaw_rate = -s.yaw_rate;  // mirror
  const TurningCircleResults r = TurningCircleSheet(track);
  EXPECT_NEAR(r.advance, 40, 1e-2);
  EXPECT_NEAR(r.transfer, -40, 1e-2);
  EXPECT_NEAR(r.tactical_diameter, -80, 1e-2);
  EXPECT_FALSE(r.has_steady);  // 432 deg < 360 + 180
}

TEST(TurningCircle, RudderHeldFromStartUntilTheTurn) {
  TurningCircleParams p;
  p.thrust = 3000;
  p.rudder = Rad(-20);
  p.start = 5;
  p.until_turn = Rad(90);
  TurningCircleState s;
  EXPECT_EQ(TurningCircleStep(p, s, 4.0, 0.0).rudder, 0.0);
  EXPECT_EQ(TurningCircleStep(p, s, 5.0, Rad(170)).rudder, Rad(-20));
  EXPECT_EQ(TurningCircleStep(p, s, 6.0, Rad(-150)).rudder, Rad(-20));  // +40 across 180
  EXPECT_EQ(TurningCircleStep(p, s, 7.0, Rad(-99.9)).rudder, 0.0);      // +90.1: done
  EXPECT_EQ(TurningCircleStep(p, s, 8.0, Rad(0)).thrust, 3000);
}

TEST(TurningCircle, FitCircleOfNoisyArcAndDegenerateInput) {
  std::vector<double> x, y;
  for (int i = 0; i < 50; ++i) {
    const double a = 0.05 * i;                        // an arc of 140 deg
    const double wobble = 0.01 * ((i % 2) ? 1 : -1);  // +-1 cm
    x.push_back(3 + (10 + wobble) * std::cos(a));
    y.push_back(-7 + (10 + wobble) * std::sin(a));
  }
  double cx, cy, radius;
  ASSERT_TRUE(FitCircle(x, y, &cx, &cy, &radius));
  EXPECT_NEAR(cx, 3, 0.02);
  EXPECT_NEAR(cy, -7, 0.02);
  EXPECT_NEAR(radius, 10, 0.02);
  EXPECT_FALSE(FitCircle({0, 1, 2}, {0, 1, 2}, &cx, &cy, &radius));  // collinear
  EXPECT_FALSE(FitCircle({0, 1}, {0, 1}, &cx, &cy, &radius));
}

}  // namespace
}  // namespace towsim::controllers

namespace towsim::controllers {
namespace {

// the payout manoeuvre (maneuver_runner/payout.h): its schedule on time alone, its commands,
// its sheet
TEST(PayoutManoeuvre, ScheduleAndWinchCommandsByPhase) {
  PayoutParams p;  // 150 -> 250 m at 1 m/s from 100 s, hold 100 s
  const PayoutTimes t = PayoutSchedule(p);
  EXPECT_EQ(t.payout, 100.0);
  EXPECT_EQ(t.hold, 200.0);
  EXPECT_EQ(t.reel_in, 300.0);
  EXPECT_EQ(t.done, 400.0);
  PayoutState s;
  const PayoutCommand approach = PayoutStep(p, s, 50.0, 3.0, 0.05);
  EXPECT_FALSE(approach.winch_length_mode);
  EXPECT_EQ(approach.winch_value, 0.0);
  const PayoutCommand out = PayoutStep(p, s, 100.0 - 1e-10, 3.0, 0.05);  // the script's rule
  EXPECT_FALSE(out.winch_length_mode);
  EXPECT_EQ(out.winch_value, 1.0);
  const PayoutCommand hold = PayoutStep(p, s, 250.0, 3.0, 0.05);
  EXPECT_TRUE(hold.winch_length_mode);
  EXPECT_EQ(hold.winch_value, 250.0);
  EXPECT_EQ(PayoutStep(p, s, 350.0, 3.0, 0.05).winch_value, -1.0);
  const PayoutCommand done = PayoutStep(p, s, 420.0, 3.0, 0.05);
  EXPECT_TRUE(done.winch_length_mode);
  EXPECT_EQ(done.winch_value, 150.0);
  // reeling in first (to < from): the signs turn
  PayoutParams in = p;
  in.to_length = 120.0;
  EXPECT_EQ(PayoutStep(in, s, 110.0, 3.0, 0.05).winch_value, -1.0);
}

TEST(PayoutManoeuvre, ThrustHoldsTheTowingSpeedWithinItsLimit) {
  PayoutParams p;
  PayoutState s;
  // too slow: thrust up to the limit; too fast for long: down to 0
  double thrust = 0.0;
  for (int k = 0; k < 200; ++k) thrust = PayoutStep(p, s, k * 0.05, 1.0, 0.05).vehicle.thrust;
  EXPECT_EQ(thrust, p.max_thrust);
  for (int k = 0; k < 2000; ++k) thrust = PayoutStep(p, s, k * 0.05, 5.0, 0.05).vehicle.thrust;
  EXPECT_EQ(thrust, 0.0);
}

TEST(PayoutManoeuvre, SheetSamplesAndPhaseEnds) {
  PayoutParams p;
  PayoutSheet sheet(p, 10.0);
  for (int k = 0; k <= 4500; ++k) {  // every 0.1 s to 450 s
    const double t = 0.1 * k;
    sheet.Add({t, 150.0 + std::min(100.0, std::max(0.0, t - 100.0)), 40.0 + 0.1 * t, 3.5, 3.0});
  }
  const PayoutResults& r = sheet.results();
  ASSERT_EQ(r.samples.size(), 46u);  // 0, 10, ..., 450 s
  EXPECT_NEAR(r.samples[1].t, 10.0, 1e-9);
  ASSERT_TRUE(r.approach.valid && r.payout.valid && r.hold.valid && r.reel_in.valid);
  EXPECT_NEAR(r.approach.at.t, 99.9, 1e-9);
  EXPECT_NEAR(r.payout.at.t, 199.9, 1e-9);
  EXPECT_NEAR(r.hold.at.t, 299.9, 1e-9);
  EXPECT_NEAR(r.reel_in.at.t, 399.9, 1e-9);
  EXPECT_NEAR(r.final.at.t, 450.0, 1e-9);
  EXPECT_NEAR(r.max_length, 250.0, 1e-12);
  EXPECT_NEAR(r.max_depth, 85.0, 1e-9);
}

}  // namespace
}  // namespace towsim::controllers
