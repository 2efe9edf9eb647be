// sim_node/dds/frames: the tf tree of a scene (docs/frames.md) against rotations written out
// by hand, element by element, from the frame definitions (REP-103 / REP-105): no quaternion
// code of the library under test is used for the reference.

#include <cmath>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "core/constants.h"
#include "core/script.h"
#include "core/simulation.h"
#include "dds/frames.h"
#include "network_scene.h"
#include "scene/scene_loader.h"

namespace towsim::dds {
namespace {

using core::kPi;
// rotation matrices from unit quaternions and products of three of them: a few ulps
constexpr double kRotationTol = 1e-12;
// the cable end held on its attachment point: the joint constraint (Eq. 24) holds to the
// Newton tolerance 1e-8 relative on a 50 m cable
constexpr double kJointTol = 1e-6;  // [m]

// a towing vehicle rolled, pitched and heading east on a short cable to a sphere
constexpr const char* kScene = R"(
name: dds_frames
time: {step: 0.05, duration: 1, output_rate: 10}
cable:
  length: 50
  elements: 4
  diameter: 0.041
  density: 1300
  youngs_modulus: 7.0e8
  initial: vertical
  start: {body: tow_vehicle, at: [0.5, 0.1, 0.2]}
  end: {body: fish, at: [0, 0, 0]}
bodies:
  fish: {type: sphere, mass: 100, volume: 0.02, position: [-0.153396, 0.459974, 53.7547]}
  tow_vehicle: {model: ../vehicles/tow_vehicle.yaml, position: [0, 0, 3.5], euler_deg: [8, -5, 100]}
script:
  - {at: 0, body: tow_vehicle, thrust: 4000, rudder_deg: 10}
)";

Eigen::Matrix3d Matrix(const TransformStampedMsg& t) {
  const auto& r = t.transform.rotation;
  return Eigen::Quaterniond(r.w, r.x, r.y, r.z).toRotationMatrix();
}
core::Vec3 Translation(const TransformStampedMsg& t) {
  return {t.transform.translation.x, t.transform.translation.y, t.transform.translation.z};
}

// R_WB of ZYX Euler angles (roll phi, pitch theta, yaw psi), written out (Fossen 2011, Eq. 2.18)
Eigen::Matrix3d EulerZyx(double phi, double theta, double psi) {
  const double cf = std::cos(phi), sf = std::sin(phi), ct = std::cos(theta), st = std::sin(theta),
               cp = std::cos(psi), sp = std::sin(psi);
  Eigen::Matrix3d R;
  R << cp * ct, -sp * cf + cp * st * sf, sp * sf + cp * cf * st,  //
      sp * ct, cp * cf + sf * st * sp, -cp * sf + st * sp * cf,   //
      -st, ct * sf, ct * cf;
  return R;
}

TEST(FramesTest, EnuNedAndFrdFluAreTheAxisPermutationsOfRep103) {
  // columns: the child's axes in the parent. NED in ENU: north = y_E, east = x_E, down = -z_E
  Eigen::Matrix3d enu_ned;
  enu_ned << 0, 1, 0, 1, 0, 0, 0, 0, -1;
  EXPECT_LE((EnuFromNed().toRotationMatrix() - enu_ned).cwiseAbs().maxCoeff(), kRotationTol);
  // FLU in FRD: forward = x, left = -starboard, up = -down
  const Eigen::Matrix3d frd_flu = Eigen::Vector3d(1, -1, -1).asDiagonal();
  EXPECT_LE((FrdFromFlu().toRotationMatrix() - frd_flu).cwiseAbs().maxCoeff(), kRotationTol);
  const core::Vec3 p(1.5, -2.0, 30.0);  // north, east, down
  EXPECT_EQ(NedToEnu(p), core::Vec3(-2.0, 1.5, -30.0));
  EXPECT_LE((enu_ned * p - NedToEnu(p)).cwiseAbs().maxCoeff(), 0.0);
}

class SceneFrames : public ::testing::Test {
 protected:
  void SetUp() override {
    model_ = scene::LoadSceneFromString(kScene, "dds_frames.yaml",
                                        std::string(TOWSIM_SOURCE_DIR) + "/config/scenes");
    sim_ = std::make_unique<core::Simulation>(model_);
    core::ScriptRunner script(model_);
    for (int k = 0; k < 20; ++k) {
      script.Apply(sim_.get());
      ASSERT_TRUE(sim_->Step().ok());
    }
  }
  core::Model model_;
  std::unique_ptr<core::Simulation> sim_;
};

TEST_F(SceneFrames, EveryFrameResolvesToWorldWithTheHandWrittenRotation) {
  const auto statics = StaticTransforms(*sim_);
  const auto bodies = BodyTransforms(*sim_);
  ToBodyTransforms(*sim_, bodies.get());
  // child -> (parent, transform)
  std::map<std::string, const TransformStampedMsg*> edges;
  for (auto* m : {statics.get(), bodies.get()}) {
    for (int i = 0; i < m->size(); ++i) {
      const TransformStampedMsg& t = m->transform(i);
      EXPECT_EQ(edges.count(t.child_frame_id), 0u) << "two parents of " << t.child_frame_id;
      edges[t.child_frame_id] = &t;
      EXPECT_EQ(t.header.stamp.sec, 1);  // 20 steps of 0.05 s
      EXPECT_EQ(t.header.stamp.nanosec, 0u);
    }
  }
  // pose of a frame in world: walk up
  auto in_world = [&](std::string frame, Eigen::Matrix3d* R, core::Vec3* p) {
    *R = Eigen::Matrix3d::Identity();
    *p = core::Vec3::Zero();
    for (int hops = 0; frame != kEnuWorldFrame; ++hops) {
      if (hops > 10 || edges.count(frame) == 0) return false;
      const TransformStampedMsg& t = *edges.at(frame);
      *p = Matrix(t) * *p + Translation(t);
      *R = Matrix(t) * *R;
      frame = t.header.frame_id;
    }
    return true;
  };
  Eigen::Matrix3d enu_ned;
  enu_ned << 0, 1, 0, 1, 0, 0, 0, 0, -1;
  const Eigen::Matrix3d frd_flu = Eigen::Vector3d(1, -1, -1).asDiagonal();
  for (const std::string frame : {"world_ned", "tow_vehicle_frd", "tow_vehicle", "fish_frd", "fish",
                                  "cable_start", "cable_end"}) {
    Eigen::Matrix3d R;
    core::Vec3 p;
    EXPECT_TRUE(in_world(frame, &R, &p)) << frame;
  }

  const int tv = 1;  // spheres first
  ASSERT_EQ(sim_->body_name(tv), "tow_vehicle");
  const core::VehicleState& s = sim_->vehicle_state(0);
  // roll, pitch, yaw of the state's quaternion, by the ZYX formulas
  const Eigen::Quaterniond& q = s.q_WB;
  const double phi =
      std::atan2(2 * (q.w() * q.x() + q.y() * q.z()), 1 - 2 * (q.x() * q.x() + q.y() * q.y()));
  const double theta = std::asin(2 * (q.w() * q.y() - q.z() * q.x()));
  const double psi =
      std::atan2(2 * (q.w() * q.z() + q.x() * q.y()), 1 - 2 * (q.y() * q.y() + q.z() * q.z()));
  EXPECT_GT(std::abs(phi), 1e-3);  // a general attitude, not an axis permutation
  Eigen::Matrix3d R;
  core::Vec3 p;
  ASSERT_TRUE(in_world("tow_vehicle", &R, &p));
  EXPECT_LE((R - enu_ned * EulerZyx(phi, theta, psi) * frd_flu).cwiseAbs().maxCoeff(),
            kRotationTol);
  EXPECT_LE((p - enu_ned * sim_->body_position(tv)).cwiseAbs().maxCoeff(), 1e-12 * 100);
  ASSERT_TRUE(in_world("tow_vehicle_frd", &R, &p));
  EXPECT_LE((R - enu_ned * EulerZyx(phi, theta, psi)).cwiseAbs().maxCoeff(), kRotationTol);

  // the attachment frames sit where the cable's end nodes are held
  ASSERT_TRUE(in_world("cable_start", &R, &p));
  EXPECT_LE((p - enu_ned * sim_->node_position(0)).norm(), kJointTol);
  EXPECT_EQ(edges.at("cable_start")->header.frame_id, std::string("tow_vehicle_frd"));
  EXPECT_EQ(Translation(*edges.at("cable_start")), core::Vec3(0.5, 0.1, 0.2));
  ASSERT_TRUE(in_world("cable_end", &R, &p));
  EXPECT_LE((p - enu_ned * sim_->node_position(sim_->num_nodes() - 1)).norm(), kJointTol);
  EXPECT_EQ(edges.at("cable_end")->header.frame_id, std::string("fish_frd"));
}

TEST(FramesTest, FixedEndsHangFromWorldNedAndFreeEndsHaveNoFrame) {
  const char* scene = R"(
name: hanging
time: {step: 0.05, duration: 1, output_rate: 10}
cable: {length: 10, elements: 2, diameter: 0.02, density: 1300, youngs_modulus: 7.0e8,
        initial: vertical, start: {fixed: [1, 2, 3]}, end: {free: true}}
bodies: {}
)";
  const core::Model model = scene::LoadSceneFromString(scene, "hanging.yaml", ".");
  const core::Simulation sim(model);
  const auto statics = StaticTransforms(sim);
  ASSERT_EQ(statics->size(), 2);  // world -> world_ned, world_ned -> cable_start
  EXPECT_STREQ(statics->transform(1).header.frame_id, "world_ned");
  EXPECT_STREQ(statics->transform(1).child_frame_id, "cable_start");
  EXPECT_EQ(Translation(statics->transform(1)), core::Vec3(1, 2, 3));
}

// a driven end (a towing point moving at constant velocity) has its frame on /tf, a child of
// world_ned at the driven point of the same time, where the solver holds the cable's node
// (Eq. 24 to the Newton tolerance); it is not on /tf_static
TEST(FramesTest, DrivenEndsMoveOnTfAtTheirDrivenPoint) {
  const char* scene = R"(
name: driven
time: {step: 0.05, duration: 1, output_rate: 10}
cable: {length: 20, elements: 3, diameter: 0.02, density: 1300, youngs_modulus: 7.0e8,
        initial: vertical, start: {driven: {position: [1, 2, 3], velocity: [2, -1, 0.5]}},
        end: {body: fish}}
bodies:
  fish: {type: sphere, mass: 50, volume: 0.01, position: [1, 2, 23]}
)";
  const core::Model model = scene::LoadSceneFromString(scene, "driven.yaml", ".");
  core::Simulation sim(model);
  for (int k = 0; k < 8; ++k) ASSERT_TRUE(sim.Step().ok());
  const auto statics = StaticTransforms(sim);
  for (int i = 0; i < statics->size(); ++i) {
    EXPECT_STRNE(statics->transform(i).child_frame_id, "cable_start");
  }
  const auto tf = BodyTransforms(sim);
  ToBodyTransforms(sim, tf.get());
  ASSERT_EQ(tf->size(), 2);  // world_ned -> fish_frd, world_ned -> cable_start
  const TransformStampedMsg& t = tf->transform(1);
  EXPECT_STREQ(t.header.frame_id, "world_ned");
  EXPECT_STREQ(t.child_frame_id, "cable_start");
  EXPECT_EQ(t.header.stamp.sec, 0);
  EXPECT_EQ(t.header.stamp.nanosec, 400000000u);  // 8 steps of 0.05 s
  // r(0.4 s) = (1, 2, 3) + 0.4 (2, -1, 0.5), written out
  EXPECT_NEAR(t.transform.translation.x, 1.8, 1e-15);
  EXPECT_NEAR(t.transform.translation.y, 1.6, 1e-15);
  EXPECT_NEAR(t.transform.translation.z, 3.2, 1e-15);
  EXPECT_EQ(t.transform.rotation.w, 1.0);
  EXPECT_LE((Translation(t) - sim.node_position(0)).norm(), kJointTol);
}

// a network (tests/unit/network_scene.h): one frame per held end of each cable, named
// <cable>_start / <cable>_end, in the scene's order, on its support or body, at the node it holds
TEST(FramesTest, ANetworkHasTheEndFramesOfEveryCable) {
  const core::Model model = test::LoadNetwork();
  core::Simulation sim(model);
  for (int k = 0; k < 5; ++k) ASSERT_TRUE(sim.Step().ok());
  EXPECT_EQ(CableEndFrame("cable", 0), kCableStartFrame);
  EXPECT_EQ(CableEndFrame("cable", 1), kCableEndFrame);
  const auto statics = StaticTransforms(sim);
  // world -> world_ned, two bodies' <b>_frd -> <b>, then four cable ends
  ASSERT_EQ(statics->size(), 1 + 2 + 4);
  const struct {
    const char* parent;
    const char* child;
    core::Vec3 offset;
    int cable, node;
  } expected[4] = {{"world_ned", "main_start", core::Vec3(0, 0, 0), 0, 0},
                   {"depressor_frd", "main_end", core::Vec3(0, 0, 0), 0, 4},
                   {"depressor_frd", "tether_start", core::Vec3(0, 0, 0.5), 1, 0},
                   {"towfish_frd", "tether_end", core::Vec3(0, 0, 0), 1, 3}};
  for (int k = 0; k < 4; ++k) {
    const TransformStampedMsg& t = statics->transform(3 + k);
    SCOPED_TRACE(expected[k].child);
    EXPECT_STREQ(t.header.frame_id, expected[k].parent);
    EXPECT_STREQ(t.child_frame_id, expected[k].child);
    EXPECT_EQ(Translation(t), expected[k].offset);
    // a sphere's frame stays aligned with world_ned: the frame's origin in NED is the parent's
    // position plus the offset, where the end node is held (Eq. 24)
    const int parent_body = k == 0 ? -1 : (k == 3 ? 1 : 0);
    const core::Vec3 origin =
        (parent_body < 0 ? core::Vec3::Zero() : sim.body_position(parent_body)) + Translation(t);
    EXPECT_LE((origin - sim.node_position(expected[k].node, expected[k].cable)).norm(), kJointTol);
  }
}

}  // namespace
}  // namespace towsim::dds
