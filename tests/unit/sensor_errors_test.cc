// sim_node/dds/sensor_errors: the sensor models applied to the messages the node publishes
// (docs/sensors.md "Sensor models"). A sensor with no errors publishes the translator's message
// bit for bit; a scene without sensor keys has no model at all; the odometry's position and
// linear velocity take their own errors while its orientation and angular velocity stay true;
// +-inf ranges stay +-inf.

#include "dds/sensor_errors.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

#include <gtest/gtest.h>

#include "core/simulation.h"
#include "dds/frames.h"
#include "dds/sensor_translators.h"
#include "dds/translators.h"
#include "hanging_sphere_scene.h"

namespace towsim::dds {
namespace {

core::Model Load(const std::string& extra) {
  return test::LoadHangingSphere(
      "environment:\n"
      "  waves: {regular: {height: 1.5, period: 8}}\n"
      "  seabed: {depth: 40, slope_deg: 5}\n" +
      extra);
}

// bitwise equality of two numbers (a -0 or a NaN payload would differ)
template <class T>
bool Same(T a, T b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

bool Same(const RangeMsg& a, const RangeMsg& b) {
  return Same(a.header.stamp.sec, b.header.stamp.sec) &&
         Same(a.header.stamp.nanosec, b.header.stamp.nanosec) &&
         std::strcmp(a.header.frame_id, b.header.frame_id) == 0 &&
         Same(a.radiation_type, b.radiation_type) && Same(a.field_of_view, b.field_of_view) &&
         Same(a.min_range, b.min_range) && Same(a.max_range, b.max_range) &&
         Same(a.range, b.range) && Same(a.variance, b.variance);
}

bool Same(const FluidPressureMsg& a, const FluidPressureMsg& b) {
  return Same(a.header.stamp.sec, b.header.stamp.sec) &&
         Same(a.header.stamp.nanosec, b.header.stamp.nanosec) &&
         Same(a.fluid_pressure, b.fluid_pressure) && Same(a.variance, b.variance);
}

bool Same(const OdometryMsg& a, const OdometryMsg& b) {
  bool same = Same(a.header.stamp.sec, b.header.stamp.sec) &&
              Same(a.header.stamp.nanosec, b.header.stamp.nanosec);
  const auto& pa = a.pose.pose;
  const auto& pb = b.pose.pose;
  const auto& ta = a.twist.twist;
  const auto& tb = b.twist.twist;
  for (auto [x, y] : {std::pair{pa.position.x, pb.position.x},
                      {pa.position.y, pb.position.y},
                      {pa.position.z, pb.position.z},
                      {pa.orientation.x, pb.orientation.x},
                      {pa.orientation.y, pb.orientation.y},
                      {pa.orientation.z, pb.orientation.z},
                      {pa.orientation.w, pb.orientation.w},
                      {ta.linear.x, tb.linear.x},
                      {ta.linear.y, tb.linear.y},
                      {ta.linear.z, tb.linear.z},
                      {ta.angular.x, tb.angular.x},
                      {ta.angular.y, tb.angular.y},
                      {ta.angular.z, tb.angular.z}}) {
    same = same && Same(x, y);
  }
  for (int i = 0; i < 36; ++i) {
    same = same && Same(a.pose.covariance[i], b.pose.covariance[i]) &&
           Same(a.twist.covariance[i], b.twist.covariance[i]);
  }
  return same;
}

TEST(SensorErrors, WithoutSensorKeysThereIsNoModel) {
  const core::Model m = Load("");
  EXPECT_TRUE(m.sensors.empty());
  for (Sensor s : {Sensor::kAltimeter, Sensor::kPressure, Sensor::kOdometry}) {
    EXPECT_EQ(FindSensorErrors(m, "ball", s), nullptr);
  }
}

TEST(SensorErrors, AModelWithoutErrorsPublishesTheTranslatorsMessageBitForBit) {
  // every step of a short run: the default errors (no noise, bias, latency, rate, dropout)
  const core::Model m = Load("");
  core::Simulation sim(m);
  const core::SensorErrors none;
  core::SensorModel ma = MakeSensorModel(none, Sensor::kAltimeter, m.time.step);
  core::SensorModel mp = MakeSensorModel(none, Sensor::kPressure, m.time.step);
  core::SensorModel mo = MakeSensorModel(none, Sensor::kOdometry, m.time.step);
  RangeMessage r0("ball"), r1("ball");
  FluidPressureMessage p0("ball"), p1("ball");
  OdometryMessage o0(kWorldFrame, FrdFrame("ball")), o1(kWorldFrame, FrdFrame("ball"));
  for (std::uint64_t n = 0; n < 20; ++n) {
    ToAltitude(sim, 0, &r0.msg);
    ToAltitude(sim, 0, &r1.msg);
    ToPressure(sim, 0, &p0.msg);
    ToPressure(sim, 0, &p1.msg);
    ToOdometry(sim, 0, &o0.msg);
    ToOdometry(sim, 0, &o1.msg);
    ASSERT_TRUE(ApplySensorErrors(&ma, n, true, &r1.msg));
    ASSERT_TRUE(ApplySensorErrors(&mp, n, true, &p1.msg));
    ASSERT_TRUE(ApplySensorErrors(&mo, n, true, &o1.msg));
    EXPECT_TRUE(Same(r0.msg, r1.msg)) << n;
    EXPECT_TRUE(Same(p0.msg, p1.msg)) << n;
    EXPECT_TRUE(Same(o0.msg, o1.msg)) << n;
    ASSERT_TRUE(sim.Step().ok());
  }
}

TEST(SensorErrors, OdometryPositionAndVelocityTakeTheirErrorsOrientationStaysTrue) {
  const core::Model m = Load("");
  const core::Simulation sim(m);
  core::SensorErrors e;
  e.bias = 2.0;
  e.velocity_bias = -0.25;
  core::SensorModel model = MakeSensorModel(e, Sensor::kOdometry, m.time.step);
  OdometryMessage truth(kWorldFrame, FrdFrame("ball")), o(kWorldFrame, FrdFrame("ball"));
  ToOdometry(sim, 0, &truth.msg);
  ToOdometry(sim, 0, &o.msg);
  ASSERT_TRUE(ApplySensorErrors(&model, 0, true, &o.msg));
  EXPECT_EQ(o.msg.pose.pose.position.x, truth.msg.pose.pose.position.x + 2.0);
  EXPECT_EQ(o.msg.pose.pose.position.y, truth.msg.pose.pose.position.y + 2.0);
  EXPECT_EQ(o.msg.pose.pose.position.z, truth.msg.pose.pose.position.z + 2.0);
  EXPECT_EQ(o.msg.twist.twist.linear.x, truth.msg.twist.twist.linear.x - 0.25);
  EXPECT_EQ(o.msg.twist.twist.linear.z, truth.msg.twist.twist.linear.z - 0.25);
  EXPECT_TRUE(Same(o.msg.pose.pose.orientation.x, truth.msg.pose.pose.orientation.x));
  EXPECT_TRUE(Same(o.msg.pose.pose.orientation.y, truth.msg.pose.pose.orientation.y));
  EXPECT_TRUE(Same(o.msg.pose.pose.orientation.z, truth.msg.pose.pose.orientation.z));
  EXPECT_TRUE(Same(o.msg.pose.pose.orientation.w, truth.msg.pose.pose.orientation.w));
  EXPECT_TRUE(Same(o.msg.twist.twist.angular.x, truth.msg.twist.twist.angular.x));
  EXPECT_TRUE(Same(o.msg.twist.twist.angular.y, truth.msg.twist.twist.angular.y));
  EXPECT_TRUE(Same(o.msg.twist.twist.angular.z, truth.msg.twist.twist.angular.z));
  EXPECT_EQ(o.msg.header.stamp.sec, truth.msg.header.stamp.sec);
  EXPECT_EQ(o.msg.header.stamp.nanosec, truth.msg.header.stamp.nanosec);
  // noise: the covariance diagonals are its variance
  core::SensorErrors n;
  n.noise = 0.5;
  n.velocity_noise = 0.1;
  core::SensorModel noisy = MakeSensorModel(n, Sensor::kOdometry, m.time.step);
  ASSERT_TRUE(ApplySensorErrors(&noisy, 0, true, &o.msg));
  for (int i : {0, 7, 14}) {
    EXPECT_EQ(o.msg.pose.covariance[i], 0.25);
    EXPECT_NEAR(o.msg.twist.covariance[i], 0.01, 1e-17);
  }
  EXPECT_NE(o.msg.pose.pose.position.x, truth.msg.pose.pose.position.x + 2.0);
}

TEST(SensorErrors, RangeAndPressureTakeBiasAndNoiseVariance) {
  const core::Model m = Load("");
  const core::Simulation sim(m);
  core::SensorErrors e;
  e.bias = 0.5;
  core::SensorModel ma = MakeSensorModel(e, Sensor::kAltimeter, m.time.step);
  RangeMessage truth("ball"), r("ball");
  ToAltitude(sim, 0, &truth.msg);
  ToAltitude(sim, 0, &r.msg);
  ASSERT_TRUE(ApplySensorErrors(&ma, 0, true, &r.msg));
  EXPECT_EQ(r.msg.range, static_cast<float>(static_cast<double>(truth.msg.range) + 0.5));
  e.noise = 30.0;
  core::SensorModel mp = MakeSensorModel(e, Sensor::kPressure, m.time.step);
  FluidPressureMessage p("ball");
  ToPressure(sim, 0, &p.msg);
  ASSERT_TRUE(ApplySensorErrors(&mp, 0, true, &p.msg));
  EXPECT_EQ(p.msg.variance, 900.0);
  // no echo: +inf stays +inf whatever the errors
  core::SensorModel inf = MakeSensorModel(e, Sensor::kAltimeter, m.time.step);
  r.msg.range = std::numeric_limits<float>::infinity();
  ASSERT_TRUE(ApplySensorErrors(&inf, 0, true, &r.msg));
  EXPECT_EQ(r.msg.range, std::numeric_limits<float>::infinity());
}

}  // namespace
}  // namespace towsim::dds
