// The autopilot's pure laws: the speed and heading loops on first-order plants
// (settling, saturation, anti-windup recovery, rate limits, heading wrap), the depth loop's
// sign, LOS geometry, waypoint switching and the lawn-mower legs; the setpoint schedule.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "autopilot/autopilot_law.h"
#include "autopilot/guidance.h"
#include "common/laws.h"

namespace towsim::controllers {
namespace {

constexpr double kExact = 1e-12;

// surge: M du/dt = T - D u|u| (D = 4165 / 36, the feedforward's own drag law, plus an
// unmodelled 20 % more), a propeller lag of 1 s; heading: first-order Nomoto model
// T_n dr/dt + r = K rudder (K = 0.55 /s, T_n = 2 s: 20 deg of rudder turns ~11 deg/s, as the
// tow vehicle in the paper's Case 2)
struct Plant {
  double u = 0, thrust = 0, yaw = 0, r = 0;
  void Step(const AutopilotCommand& c, double dt) {
    const double mass = 7500, drag = 1.2 * 4165.0 / 36.0;
    thrust += (c.thrust - thrust) * dt / 1.0;
    u += (thrust - drag * u * std::abs(u)) / mass * dt;
    r += (0.55 * c.rudder - r) / 2.0 * dt;
    yaw = WrapPi(yaw + r * dt);
  }
};

AutopilotMeasurement Measure(const Plant& p) {
  AutopilotMeasurement m;
  m.u = p.u;
  m.yaw = p.yaw;
  m.r = p.r;
  return m;
}

TEST(Autopilot, SpeedAndHeadingSettleOnTheirSetpoints) {
  const AutopilotGains g;
  AutopilotState s;
  Plant plant;
  AutopilotSetpoint sp;
  sp.speed = 6.0;
  sp.heading = Rad(30);
  const double dt = 0.05;
  double max_overshoot = 0;
  for (int k = 0; k < 3000; ++k) {  // 150 s
    const AutopilotCommand c = AutopilotStep(g, s, sp, Measure(plant), dt);
    plant.Step(c, dt);
    max_overshoot = std::max(max_overshoot, Deg(plant.yaw) - 30);
  }
  // the integral removes the 20 % drag mismatch; the heading settles, overshoot moderate
  EXPECT_NEAR(plant.u, 6.0, 1e-3);
  EXPECT_NEAR(Deg(plant.yaw), 30.0, 1e-3);
  EXPECT_LT(max_overshoot, 5.0);
  EXPECT_NEAR(plant.thrust, 1.2 * 4165.0, 1.0);  // the drag at 6 m/s
}

TEST(Autopilot, HeadingErrorTakesTheShortWayAcross180) {
  AutopilotGains g;
  g.heading.rate_limit = 0;  // see the first command whole
  AutopilotState s;
  AutopilotSetpoint sp;
  sp.heading = Rad(-179);
  AutopilotMeasurement m;
  m.yaw = Rad(179);  // 2 deg to starboard, not 358 to port
  const AutopilotCommand c = AutopilotStep(g, s, sp, m, 0.05);
  EXPECT_NEAR(c.rudder, g.heading.kp * Rad(2) + g.heading.ki * Rad(2) * 0.05, 1e-12);
  // the plant crosses 180 deg and settles on -179 deg
  Plant plant;
  plant.yaw = Rad(170);
  plant.u = 6;
  sp.speed = 6;
  AutopilotState s2;
  // 150 s: the integral's slow mode (ki / kp = 0.05 /s) has decayed to < 0.01 deg
  for (int k = 0; k < 3000; ++k) plant.Step(AutopilotStep(g, s2, sp, Measure(plant), 0.05), 0.05);
  EXPECT_NEAR(Deg(WrapPi(plant.yaw - Rad(-179))), 0.0, 1e-2);
}

TEST(Autopilot, RudderSaturatesAndIsRateLimited) {
  const AutopilotGains g;  // 25 deg, 20 deg/s
  AutopilotState s;
  AutopilotSetpoint sp;
  sp.heading = Rad(90);
  AutopilotMeasurement m;
  m.u = 6;
  double last = 0;
  for (int k = 0; k < 40; ++k) {  // 2 s
    const AutopilotCommand c = AutopilotStep(g, s, sp, m, 0.05);
    EXPECT_LE(std::abs(c.rudder - last), Rad(20) * 0.05 + kExact);
    EXPECT_LE(std::abs(c.rudder), Rad(25) + kExact);
    last = c.rudder;
  }
  EXPECT_NEAR(last, Rad(25), kExact);  // reached after 1.25 s
}

TEST(Autopilot, ThrustIsRateLimitedAndSaturated) {
  const AutopilotGains g;  // 2000 N/s, [-3000, 12000] N
  AutopilotState s;
  AutopilotSetpoint sp;
  sp.speed = 9.0;  // far above: the PID asks for more than 12 kN
  AutopilotMeasurement m;
  double last = 0;
  for (int k = 0; k < 200; ++k) {  // 10 s
    const AutopilotCommand c = AutopilotStep(g, s, sp, m, 0.05);
    EXPECT_LE(c.thrust - last, 2000 * 0.05 + 1e-9);
    last = c.thrust;
  }
  EXPECT_NEAR(last, 12000, 1e-9);  // 12 kN reached after 6 s, held
}

TEST(Autopilot, TheThrustRampDoesNotWindUpTheIntegral) {
  // the ramp (2000 N/s) holds the thrust below what the PID asks for: the integral must stay
  // where it was while the error pushes the same way
  const AutopilotGains g;
  AutopilotState s;
  AutopilotSetpoint sp;
  sp.speed = 6.0;
  AutopilotMeasurement m;
  m.u = 5.0;  // kp * 1 = 1500 N above the 4165 N feedforward: the ramp from 0 needs 2.8 s
  for (int k = 0; k < 40; ++k) AutopilotStep(g, s, sp, m, 0.05);  // 2 s on the ramp
  EXPECT_NEAR(s.thrust, 4000, 1e-9);
  EXPECT_EQ(s.speed.integral, 0.0);
  for (int k = 0; k < 20; ++k) AutopilotStep(g, s, sp, m, 0.05);  // off the ramp: integrates
  EXPECT_GT(s.speed.integral, 0.0);
}

TEST(Autopilot, AntiWindupRecoversAtOnceAfterLongSaturation) {
  // 200 s saturated at full thrust with the vehicle held at 0 m/s (aground): the integral
  // must not wind up, so when the speed overshoots the thrust falls immediately
  const AutopilotGains g;
  AutopilotState s;
  AutopilotSetpoint sp;
  sp.speed = 6.0;
  AutopilotMeasurement m;
  for (int k = 0; k < 4000; ++k) AutopilotStep(g, s, sp, m, 0.05);
  EXPECT_LE(g.speed.ki * s.speed.integral, g.speed.out_max + 1e-9);
  m.u = 6.5;  // freed, overshooting: the command leaves saturation within the rate limit
  AutopilotCommand c;
  for (int k = 0; k < 20; ++k) c = AutopilotStep(g, s, sp, m, 0.05);  // 1 s
  EXPECT_LT(c.thrust, 12000 - 1000);
  // without conditional integration (a plain PI) the integral would hold 200 s x 6 m/s
  // x 300 = 360 kN and the thrust would stay at 12 kN for minutes
}

TEST(Autopilot, DepthLoopOffByDefaultAndItsSignWhenOn) {
  AutopilotGains g;
  AutopilotState s;
  AutopilotSetpoint sp;
  sp.depth = 10;
  AutopilotMeasurement m;
  m.z = 12;  // 2 m too deep
  EXPECT_EQ(AutopilotStep(g, s, sp, m, 0.05).elevator, 0.0);
  g.depth_enabled = true;
  g.depth.rate_limit = 0;
  AutopilotState s2;
  // too deep: rise: bow up: positive elevator (depth_sign -1)
  EXPECT_NEAR(AutopilotStep(g, s2, sp, m, 0.05).elevator, g.depth.kp * 2 + g.depth.ki * 2 * 0.05,
              1e-12);
}

TEST(Autopilot, IntegralOnlyInsideItsZone) {
  PidParams p;
  p.kp = 1.0;
  p.ki = 1.0;
  p.out_min = -10;
  p.out_max = 10;
  p.integral_zone = 0.5;
  PidState s;
  PidStep(p, s, 2.0, 0.0, 0.1);  // outside the zone: P only
  EXPECT_EQ(s.integral, 0.0);
  PidStep(p, s, 0.4, 0.0, 0.1);  // inside: integrates
  EXPECT_NEAR(s.integral, 0.04, kExact);
  PidStep(p, s, -0.5, 0.0, 0.1);  // on the edge: outside
  EXPECT_NEAR(s.integral, 0.04, kExact);
}

TEST(Autopilot, RateLimitHelper) {
  EXPECT_EQ(RateLimit(0, 10, 2, 0.5), 1);
  EXPECT_EQ(RateLimit(0, -10, 2, 0.5), -1);
  EXPECT_EQ(RateLimit(0, 0.5, 2, 0.5), 0.5);
  EXPECT_EQ(RateLimit(0, 10, 0, 0.5), 10);  // none
}

TEST(Guidance, LosGeometry) {
  // leg from (0, 0) to (100, 100): path angle 45 deg
  const Waypoint a{0, 0}, b{100, 100};
  // on the leg: steer along it
  LosResult r = LineOfSight(a, b, 50, 50, 40);
  EXPECT_NEAR(r.path_angle, Rad(45), kExact);
  EXPECT_NEAR(r.along, 50 * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(r.cross, 0, 1e-9);
  EXPECT_NEAR(r.heading, Rad(45), kExact);
  EXPECT_NEAR(r.leg_length, 100 * std::sqrt(2.0), 1e-9);
  // 40 m to starboard of the leg (south-east of it): e = +40, steer 45 deg back to port
  const double k = 40 / std::sqrt(2.0);
  r = LineOfSight(a, b, 50 - k, 50 + k, 40);
  EXPECT_NEAR(r.cross, 40, 1e-9);
  EXPECT_NEAR(r.heading, Rad(0), 1e-12);  // 45 - atan(40/40) = 0
  // to port: steer to starboard
  r = LineOfSight(a, b, 50 + k, 50 - k, 40);
  EXPECT_NEAR(r.cross, -40, 1e-9);
  EXPECT_NEAR(r.heading, Rad(90), 1e-12);
  // a leg heading south-west: path angle -135 deg, heading wrapped into (-180, 180]
  r = LineOfSight(b, a, 50 + 2 * k, 50, 1e9);  // lookahead -> infinity: the path angle
  EXPECT_NEAR(r.heading, Rad(-135), 1e-7);     // to within e / lookahead = 4e-8 rad
  // a leg due south with the vehicle just to starboard (west): the heading crosses 180 deg
  r = LineOfSight({0, 0}, {-100, 0}, -50, -1, 10);
  EXPECT_NEAR(r.path_angle, kPi, kExact);
  EXPECT_NEAR(r.cross, 1, 1e-9);
  EXPECT_NEAR(r.heading, WrapPi(kPi - std::atan(0.1)), 1e-12);
}

TEST(Guidance, LawnMowerLegs) {
  LawnMowerParams p;
  p.origin = {10, 20};
  p.heading = 0;  // north
  p.leg_length = 300;
  p.spacing = 80;
  p.legs = 3;
  p.turn = 1;  // steps east (starboard of north)
  const std::vector<Waypoint> w = LawnMower(p);
  const std::vector<Waypoint> expected = {{10, 20},  {310, 20}, {310, 100},
                                          {10, 100}, {10, 180}, {310, 180}};
  ASSERT_EQ(w.size(), expected.size());
  for (size_t i = 0; i < w.size(); ++i) {
    EXPECT_NEAR(w[i].x, expected[i].x, 1e-9) << i;
    EXPECT_NEAR(w[i].y, expected[i].y, 1e-9) << i;
  }
  p.turn = -1;          // port: steps west
  p.heading = Rad(90);  // legs east: port is north
  p.legs = 2;
  const std::vector<Waypoint> v = LawnMower(p);
  ASSERT_EQ(v.size(), 4u);
  EXPECT_NEAR(v[1].x, 10, 1e-9);
  EXPECT_NEAR(v[1].y, 320, 1e-9);
  EXPECT_NEAR(v[2].x, 90, 1e-9);  // 80 m north
  EXPECT_NEAR(v[2].y, 320, 1e-9);
  EXPECT_NEAR(v[3].x, 90, 1e-9);
  EXPECT_NEAR(v[3].y, 20, 1e-9);
}

TEST(Guidance, WaypointSwitchingByRadiusOrPassing) {
  WaypointTracker k;
  k.waypoints = {{100, 0}, {100, 100}};
  k.acceptance_radius = 10;
  k.lookahead = 20;
  // start at the origin: steer to (100, 0), due north
  EXPECT_NEAR(TrackWaypoints(k, 0.0, 0, 0, 0), 0.0, kExact);
  EXPECT_EQ(k.target, 0u);
  EXPECT_NEAR(TrackWaypoints(k, 1.0, 85, 0, 0), 0.0, kExact);  // 15 m off: not yet
  EXPECT_EQ(k.target, 0u);
  // within 10 m: the next leg, (100, 0) -> (100, 100): due east
  const double h = TrackWaypoints(k, 2.0, 92, 0, 0);
  EXPECT_EQ(k.target, 1u);
  EXPECT_NEAR(k.reached_at[0], 2.0, kExact);
  EXPECT_NEAR(k.miss[0], 8.0, 1e-9);
  // at (92, 0) the vehicle is 8 m south of the eastbound leg, to its starboard: e = +8,
  // steer north of east
  EXPECT_NEAR(h, Rad(90) - std::atan(8.0 / 20.0), 1e-12);
  // passing the end of the leg 30 m wide of the waypoint: taken as reached (no orbiting)
  EXPECT_FALSE(k.done());
  TrackWaypoints(k, 3.0, 130, 101, Rad(90));
  EXPECT_TRUE(k.done());
  EXPECT_NEAR(k.reached_at[1], 3.0, kExact);
  EXPECT_NEAR(k.miss[1], std::hypot(30.0, 1.0), 1e-9);
  // done: hold the last leg's direction
  EXPECT_NEAR(TrackWaypoints(k, 4.0, 200, 200, 0.3), Rad(90), kExact);
}

}  // namespace
}  // namespace towsim::controllers
