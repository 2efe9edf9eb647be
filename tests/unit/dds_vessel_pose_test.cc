// dds/vessel_pose_translator: an external vessel's pose on the wire (docs/vessels.md "External
// vessels"). The oracle of the round trip is the pose itself: VesselPose -> the node's odometry
// of it -> VesselPose gives the position, the attitude and the body twist back bit for bit
// (they travel as doubles and are kept as given), and the Euler angles, their rates and the
// world velocity (recomputed from them) within kRoundTripTol.

#include <cmath>
#include <fstream>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "core/simulation.h"
#include "core/vessel_motion.h"
#include "dds/translators.h"
#include "dds/vessel_pose_translator.h"
#include "scene/scene_loader.h"
#include "temp_dir.h"

namespace towsim::dds {
namespace {

// a few ulps of angles and rates of order 1 through atan2/asin and a 3x3 rotation
constexpr double kRoundTripTol = 1e-12;

core::VesselPose SomePose() {
  core::VesselPose p;
  p.position = core::Vec3(120.5, -33.25, -1.75);
  p.euler = core::Vec3(0.12, -0.07, 2.6);
  p.velocity = core::Vec3(-2.9, 1.4, 0.35);
  p.euler_rate = core::Vec3(0.031, -0.022, 0.015);
  return p;
}

void ExpectBitwise(const core::VesselPose& a, const core::VesselPose& b) {
  for (int k = 0; k < 3; ++k) EXPECT_EQ(a.position(k), b.position(k)) << k;
  const Eigen::Quaterniond qa = a.attitude(), qb = b.attitude();
  EXPECT_EQ(qa.w(), qb.w());
  EXPECT_EQ(qa.x(), qb.x());
  EXPECT_EQ(qa.y(), qb.y());
  EXPECT_EQ(qa.z(), qb.z());
  const Eigen::Matrix<double, 6, 1> ta = a.twist(), tb = b.twist();
  for (int k = 0; k < 6; ++k) EXPECT_EQ(ta(k), tb(k)) << k;
}

TEST(VesselPoseTranslator, RoundTripThroughTheMessage) {
  const core::VesselPose pose = SomePose();
  OdometryMessage m(kWorldFrame, "ship_frd");
  ToPoseCommand(pose, 12.34, &m.msg);
  const CheckedPose back = FromPoseCommand(m.msg, "ship");
  ASSERT_EQ(back.verdict, CheckedCommand::kAccepted) << back.reason;
  EXPECT_NEAR(back.t, 12.34, 0.5e-9);  // whole nanoseconds on the wire
  ASSERT_TRUE(back.pose.given.has_value());
  ExpectBitwise(back.pose, pose);
  EXPECT_LT((back.pose.euler - pose.euler).norm(), kRoundTripTol);
  EXPECT_LT((back.pose.euler_rate - pose.euler_rate).norm(), kRoundTripTol);
  EXPECT_LT((back.pose.velocity - pose.velocity).norm(), kRoundTripTol);
  // and again: what came back goes out the same
  OdometryMessage again(kWorldFrame, "ship_frd");
  ToPoseCommand(back.pose, 12.34, &again.msg);
  ExpectBitwise(FromPoseCommand(again.msg, "ship").pose, pose);
}

// a ship with a time history and a sphere on a short cable: the node's odometry of the ship
// (ToOdometry of the simulation) fed to the same scene with the ship external gives the ship's
// pose back, bit for bit where it is reported and attached
std::string Scene(const std::string& ship) {
  return "name: v\n"
         "time: {step: 0.05, duration: 4, output_rate: 10}\n"
         "cable: {length: 50, elements: 4, diameter: 0.03, density: 1300, youngs_modulus: 1e9,\n"
         "        initial: straight, initial_velocity: [0, 0, 0],\n"
         "        start: {body: ship, at: [-20, 0, 1]}, end: {body: fish}}\n"
         "bodies:\n"
         "  ship: {type: vessel, " +
         ship +
         "}\n"
         "  fish: {type: sphere, mass: 400, volume: 0.2, position: [-60, 0, 30]}\n";
}

TEST(VesselPoseTranslator, TheNodesOdometryFedBackGivesThePose) {
  test::TempDir dir;
  std::ofstream(dir.path() / "track.csv") << "t,x,y,z,roll,pitch,yaw\n"
                                             "0,0,0,0,0,0,0\n"
                                             "1,2,0.1,-0.3,0.02,-0.01,0.05\n"
                                             "2,4.1,0.3,0.2,-0.03,0.02,0.1\n"
                                             "3,6.0,0.2,-0.1,0.01,0.01,0.2\n"
                                             "5,10,0,0,0,0,0.3\n";
  const core::Model logged =
      scene::LoadSceneFromString(Scene("time_history: track.csv"), "t.yaml", dir.path().string());
  const core::Model fed = scene::LoadSceneFromString(Scene("external: true, position: [0, 0, 0]"),
                                                     "t.yaml", dir.path().string());
  core::Simulation a(logged), b(fed);
  const int ship = a.num_spheres() + a.num_vehicles();  // bodies: spheres, vehicles, vessels
  ASSERT_TRUE(a.body_is_vessel(ship));
  for (int n = 0; n < 3; ++n) a.Step();
  const double t = a.time();
  OdometryMessage odom(kWorldFrame, "ship_frd");
  ToOdometry(a, ship, &odom.msg);
  const CheckedPose got = FromPoseCommand(odom.msg, "ship");
  ASSERT_EQ(got.verdict, CheckedCommand::kAccepted) << got.reason;
  ExpectBitwise(got.pose, a.vessel_pose(0));
  EXPECT_LT((got.pose.euler - a.vessel_pose(0).euler).norm(), kRoundTripTol);
  EXPECT_LT((got.pose.euler_rate - a.vessel_pose(0).euler_rate).norm(), kRoundTripTol);
  EXPECT_LT((got.pose.velocity - a.vessel_pose(0).velocity).norm(), kRoundTripTol);
  // given for the external ship's time now (its initial state), it is the pose reported now,
  // and the body's odometry says the same as the logged ship's
  b.SetVesselPose(0, b.time(), got.pose);
  ExpectBitwise(b.vessel_pose(0), a.vessel_pose(0));
  OdometryMessage odom_b(kWorldFrame, "ship_frd");
  ToOdometry(b, ship, &odom_b.msg);
  EXPECT_EQ(odom_b.msg.pose.pose.orientation.z, odom.msg.pose.pose.orientation.z);
  EXPECT_EQ(odom_b.msg.twist.twist.angular.x, odom.msg.twist.twist.angular.x);
  // given for another time, it is carried to the step's end by its rates (no longer as given)
  b.SetVesselPose(0, t, got.pose);
  b.Step();
  EXPECT_FALSE(b.vessel_pose(0).given.has_value());
  const core::Vec3 expected = got.pose.position + (b.time() - t) * got.pose.velocity;
  EXPECT_LT((b.vessel_pose(0).position - expected).norm(), kRoundTripTol);
}

CheckedPose Fed(void (*change)(OdometryMsg*)) {
  static OdometryMessage m(kWorldFrame, "ship_frd");
  ToPoseCommand(SomePose(), 1.0, &m.msg);
  OdometryMsg msg = m.msg;
  change(&msg);
  return FromPoseCommand(msg, "ship");
}

TEST(VesselPoseTranslator, RejectsWhatIsNotAPose) {
  CheckedPose c = Fed(
      [](OdometryMsg* m) { m->pose.pose.position.y = std::numeric_limits<double>::quiet_NaN(); });
  EXPECT_EQ(c.verdict, CheckedCommand::kRejected);
  EXPECT_EQ(c.reason, "pose.pose.position: NaN or infinite");
  c = Fed([](OdometryMsg* m) { m->twist.twist.angular.z = INFINITY; });
  EXPECT_EQ(c.reason, "twist.twist.angular: NaN or infinite");
  c = Fed([](OdometryMsg* m) { m->pose.pose.orientation.w *= 1.1; });
  EXPECT_EQ(c.verdict, CheckedCommand::kRejected);
  EXPECT_NE(c.reason.find("|q| = "), std::string::npos) << c.reason;
  EXPECT_NE(c.reason.find("must be 1 within 1e-06"), std::string::npos) << c.reason;
  c = Fed([](OdometryMsg* m) { m->header.frame_id = const_cast<char*>("world"); });
  EXPECT_EQ(c.reason, "header.frame_id 'world': must be world_ned (NED, as the node's odometry)");
  c = Fed([](OdometryMsg* m) { m->child_frame_id = const_cast<char*>("ship"); });
  EXPECT_EQ(c.reason,
            "child_frame_id 'ship': must be ship_frd (the twist in the body frame forward, "
            "starboard, down)");
  // bow straight up: q = rotation by 90 deg about y
  c = Fed([](OdometryMsg* m) {
    m->pose.pose.orientation = {0.0, std::sqrt(0.5), 0.0, std::sqrt(0.5)};
  });
  EXPECT_EQ(c.verdict, CheckedCommand::kRejected);
  EXPECT_NE(c.reason.find("Euler rates are singular"), std::string::npos) << c.reason;
  // empty frames are the node's
  c = Fed([](OdometryMsg* m) {
    m->header.frame_id = const_cast<char*>("");
    m->child_frame_id = nullptr;
  });
  EXPECT_EQ(c.verdict, CheckedCommand::kAccepted) << c.reason;
}

}  // namespace
}  // namespace towsim::dds
