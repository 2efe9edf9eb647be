// core/pose_spline.h: a vessel's time history as six splines, and what it does before the
// first and after the last sample.
#include "core/pose_spline.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/constants.h"

namespace towsim::core {
namespace {

// channel c moves as p_c(t) = (c + 1) (0.3 t + 0.2 sin(0.5 t)) + c
TimeHistory Wavy(double t0, double t1, double dt) {
  TimeHistory h;
  for (double t = t0; t <= t1 + 1e-12; t += dt) {
    h.t.push_back(t);
    Eigen::Matrix<double, 6, 1> p;
    for (int c = 0; c < 6; ++c) p(c) = (c + 1) * (0.3 * t + 0.2 * std::sin(0.5 * t)) + c;
    h.pose.push_back(p);
  }
  return h;
}

TEST(PoseSpline, EvaluatesEachChannelBetweenTheSamples) {
  const TimeHistory h = Wavy(-2.0, 40.0, 0.1);
  const PoseSpline s(h);
  EXPECT_EQ(s.start_time(), -2.0);
  EXPECT_NEAR(s.end_time(), 40.0, 1e-9);
  // w dt = 0.05: errors ~ 1e-8 (position), 1e-6 (rate), 1e-4 (acceleration), relative to the
  // sine's 0.2, 0.1 and 0.05 per unit of (c + 1); away from the ends
  for (double t : {0.0, 3.33, 17.05, 29.99}) {
    const PoseSample p = s.Evaluate(t);
    for (int c = 0; c < 6; ++c) {
      const double k = c + 1;
      EXPECT_NEAR(p.pose(c), k * (0.3 * t + 0.2 * std::sin(0.5 * t)) + c, 1e-7 * k) << c;
      EXPECT_NEAR(p.velocity(c), k * (0.3 + 0.1 * std::cos(0.5 * t)), 1e-5 * k) << c;
      EXPECT_NEAR(p.acceleration(c), -k * 0.05 * std::sin(0.5 * t), 1e-3 * k) << c;
    }
  }
}

TEST(PoseSpline, HoldsTheFirstPoseBeforeAndContinuesTheLastRateAfter) {
  const TimeHistory h = Wavy(0.0, 10.0, 0.5);
  const PoseSpline s(h);
  const PoseSample before = s.Evaluate(-3.0);
  const PoseSample first = s.Evaluate(0.0);
  const PoseSample last = s.Evaluate(10.0);
  for (int c = 0; c < 6; ++c) {
    EXPECT_EQ(before.pose(c), h.pose.front()(c));
    EXPECT_EQ(before.velocity(c), 0.0);
    EXPECT_EQ(before.acceleration(c), 0.0);
    EXPECT_EQ(first.pose(c), h.pose.front()(c));
  }
  for (double dt : {0.01, 2.0, 50.0}) {
    const PoseSample after = s.Evaluate(10.0 + dt);
    for (int c = 0; c < 6; ++c) {
      EXPECT_NEAR(after.pose(c), h.pose.back()(c) + last.velocity(c) * dt, 1e-12 * (1 + dt)) << c;
      EXPECT_EQ(after.velocity(c), last.velocity(c));
      EXPECT_EQ(after.acceleration(c), 0.0);
    }
  }
  // the last rate is the spline's, not a finite difference: it differs from the last chord
  const double chord = (h.pose.back()(0) - h.pose[h.pose.size() - 2](0)) / 0.5;
  EXPECT_GT(std::abs(last.velocity(0) - chord), 1e-4);
}

}  // namespace
}  // namespace towsim::core
