// core/vessel_course.h: the course's closed forms against their definitions. The references:
// the entries' targets (speed, heading), the limits (max_acceleration, max_yaw_acceleration),
// the circle of radius U / r of a steady turn, and central differences of the course's own
// position and heading (the velocity and the turn rate it reports must be their derivatives).

#include "core/vessel_course.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/constants.h"

namespace towsim::core {
namespace {

constexpr double kDeg = kPi / 180.0;
// the course's closed forms are exact: targets to rounding
constexpr double kExact = 1e-9;
// central differences with dt = 1e-3 s of quantities varying over seconds: O(dt^2) ~ 1e-6
constexpr double kFdDt = 1e-3;
constexpr double kFdTol = 1e-5;

Vessel Ship(double speed, double heading_deg) {
  Vessel v;
  v.name = "ship";
  v.position = Eigen::Vector3d(10.0, -5.0, 0.0);
  v.euler = Eigen::Vector3d(0.0, 0.0, heading_deg * kDeg);
  v.speed = speed;
  v.max_acceleration = 0.05;
  v.max_yaw_acceleration = 0.2 * kDeg;
  return v;
}

// the velocity and the turn rate are the derivatives of position and heading, and the
// acceleration of the velocity, at every 0.37 s over [0, t_end]
void CheckDerivatives(const VesselCourse& course, double t_end) {
  for (double t = kFdDt; t < t_end; t += 0.37) {
    const CourseSample a = course.At(t - kFdDt), b = course.At(t + kFdDt), c = course.At(t);
    const Eigen::Vector3d v_fd = (b.position - a.position) / (2.0 * kFdDt);
    EXPECT_LT((v_fd - c.velocity).norm(), kFdTol) << "t = " << t;
    const Eigen::Vector3d a_fd = (b.velocity - a.velocity) / (2.0 * kFdDt);
    EXPECT_LT((a_fd - c.acceleration).norm(), 1e-4) << "t = " << t;
    EXPECT_NEAR((b.heading - a.heading) / (2.0 * kFdDt), c.turn_rate, kFdTol) << "t = " << t;
    EXPECT_NEAR((b.turn_rate - a.turn_rate) / (2.0 * kFdDt), c.yaw_acceleration, 1e-6)
        << "t = " << t;
  }
}

TEST(VesselCourse, ConstantSpeedIsAStraightLine) {
  const Vessel v = Ship(3.0, 30.0);
  const VesselCourse course(v);
  const CourseSample s = course.At(100.0);
  const Eigen::Vector3d expected =
      v.position + 300.0 * Eigen::Vector3d(std::cos(30 * kDeg), std::sin(30 * kDeg), 0.0);
  EXPECT_LT((s.position - expected).norm(), kExact);
  EXPECT_NEAR(s.heading, 30 * kDeg, kExact);
  EXPECT_LT(s.acceleration.norm(), kExact);
}

TEST(VesselCourse, SpeedChangeRampsWithinTheLimit) {
  Vessel v = Ship(2.0, 0.0);
  CourseChange c;
  c.at = 10.0;
  c.set_speed = true;
  c.speed = 3.0;
  v.course = {c};
  const VesselCourse course(v);
  // T = pi dU / (2 a_max) = pi / 0.1 = 31.4 s
  const double T = 0.5 * kPi * 1.0 / v.max_acceleration;
  EXPECT_NEAR(course.At(10.0).speed, 2.0, kExact);
  EXPECT_NEAR(course.At(10.0 + T).speed, 3.0, kExact);
  EXPECT_NEAR(course.At(200.0).speed, 3.0, kExact);
  double peak = 0.0;
  for (double t = 0.0; t < 60.0; t += 0.01) peak = std::max(peak, course.At(t).acceleration.norm());
  EXPECT_LE(peak, v.max_acceleration * (1.0 + 1e-12));
  EXPECT_GE(peak, v.max_acceleration * (1.0 - 1e-5));
  // the distance: 2 m/s for 10 s, the ramp's mean (2 + 3) / 2 over T, then 3 m/s
  const double x = course.At(100.0).position.x() - v.position.x();
  EXPECT_NEAR(x, 20.0 + 2.5 * T + 3.0 * (90.0 - T), kExact);
  CheckDerivatives(course, 60.0);
}

TEST(VesselCourse, HeadingChangeEndsOnTheTargetWithinTheLimits) {
  Vessel v = Ship(2.5, 350.0);
  CourseChange c;
  c.at = 5.0;
  c.set_heading = true;
  c.heading = 80.0 * kDeg;  // from 350: the shorter way is +90 deg (to starboard)
  c.set_turn_rate = true;
  c.turn_rate = 1.0 * kDeg;
  v.course = {c};
  const VesselCourse course(v);
  double peak_rate = 0.0, peak_accel = 0.0, min_rate = 0.0;
  for (double t = 0.0; t < 200.0; t += 0.01) {
    const CourseSample s = course.At(t);
    peak_rate = std::max(peak_rate, s.turn_rate);
    min_rate = std::min(min_rate, s.turn_rate);
    peak_accel = std::max(peak_accel, std::abs(s.yaw_acceleration));
  }
  EXPECT_NEAR(peak_rate, 1.0 * kDeg, kExact);
  EXPECT_GE(min_rate, 0.0);  // to starboard all the way
  // sampled every 0.01 s: the peak's sample lies within 1e-5 of it; never above the limit
  EXPECT_LE(peak_accel, v.max_yaw_acceleration * (1.0 + 1e-12));
  EXPECT_GE(peak_accel, v.max_yaw_acceleration * (1.0 - 1e-5));
  // 350 + 90 = 440 deg, unwrapped
  EXPECT_NEAR(course.At(200.0).heading, 440.0 * kDeg, kExact);
  EXPECT_NEAR(course.At(200.0).turn_rate, 0.0, kExact);
  CheckDerivatives(course, 200.0);
}

TEST(VesselCourse, SmallHeadingChangeLowersThePeakRate) {
  Vessel v = Ship(2.0, 10.0);
  CourseChange c;
  c.at = 0.0;
  c.set_heading = true;
  c.heading = 8.0 * kDeg;  // -2 deg: too small to reach 2 deg/s at 0.2 deg/s^2
  c.set_turn_rate = true;
  c.turn_rate = 2.0 * kDeg;
  v.course = {c};
  const VesselCourse course(v);
  double peak = 0.0;
  for (double t = 0.0; t < 60.0; t += 0.01) peak = std::max(peak, -course.At(t).turn_rate);
  // the peak P of two ramps and no hold: pi P^2 / (2 alpha) = |dpsi| (rho_0 = 0)
  EXPECT_NEAR(peak, std::sqrt(2.0 * v.max_yaw_acceleration * 2.0 * kDeg / kPi), 1e-7);
  EXPECT_NEAR(course.At(60.0).heading, 8.0 * kDeg, kExact);
  CheckDerivatives(course, 60.0);
}

TEST(VesselCourse, SteadyTurnIsACircleOfRadiusSpeedOverRate) {
  Vessel v = Ship(3.0, 0.0);
  CourseChange c;
  c.at = 0.0;
  c.set_turn_rate = true;
  c.turn_rate = -1.5 * kDeg;  // to port
  v.course = {c};
  const VesselCourse course(v);
  const double r = 1.5 * kDeg, radius = 3.0 / r;
  // once the rate holds, the centre lies radius to port of the velocity
  const CourseSample s0 = course.At(100.0);
  const Eigen::Vector3d port(std::sin(s0.heading), -std::cos(s0.heading), 0.0);
  const Eigen::Vector3d centre = s0.position + radius * port;
  for (double t = 100.0; t < 700.0; t += 13.0)
    EXPECT_NEAR((course.At(t).position - centre).norm(), radius, 1e-6) << "t = " << t;
  EXPECT_NEAR(course.At(400.0).acceleration.norm(), 3.0 * r, 1e-9);  // U^2 / R
  CheckDerivatives(course, 120.0);
}

TEST(VesselCourse, AnEntryDuringARampStartsFromTheValuesThen) {
  Vessel v = Ship(1.0, 0.0);
  CourseChange a, b;
  a.at = 0.0;
  a.set_speed = true;
  a.speed = 4.0;  // a 94 s ramp
  b.at = 20.0;
  b.set_speed = true;
  b.speed = 1.5;
  v.course = {a, b};
  const VesselCourse course(v);
  // continuous speed through the cut; the second target reached
  EXPECT_NEAR(course.At(20.0 - 1e-9).speed, course.At(20.0 + 1e-9).speed, 1e-9);
  EXPECT_NEAR(course.At(300.0).speed, 1.5, kExact);
  CheckDerivatives(course, 19.9);
}

}  // namespace
}  // namespace towsim::core
