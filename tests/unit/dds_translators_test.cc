// sim_node/dds/translators: state -> message -> fields, and the incoming messages, without DDS
// entities (no participant).

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "core/constants.h"
#include "core/script.h"
#include "core/simulation.h"
#include "dds/command_arbiter.h"
#include "dds/translators.h"
#include "network_scene.h"
#include "scene/scene_loader.h"

namespace towsim::dds {
namespace {

using core::kPi;
constexpr double kExact = 0.0;  // copied numbers: no tolerance
// a rotation applied to a vector and back: a few ulps of the vector's size
constexpr double kRotationTol = 1e-12;

// a towing vehicle heading east (yaw 90 deg) on a short cable to a sphere, under thrust
constexpr const char* kScene = R"(
name: dds_translators
time: {step: 0.05, duration: 1, output_rate: 10}
cable:
  length: 50
  elements: 4
  diameter: 0.041
  density: 1300
  youngs_modulus: 7.0e8
  initial: vertical
  start: {body: tow_vehicle, at: [0, 0, 0.2]}
  end: {body: fish, at: [0, 0, 0]}
bodies:
  fish: {type: sphere, mass: 100, volume: 0.02, position: [0, 0, 53.7]}
  tow_vehicle: {model: ../vehicles/tow_vehicle.yaml, position: [0, 0, 3.5], euler_deg: [0, 0, 90]}
script:
  - {at: 0, body: tow_vehicle, thrust: 4000}
)";

class StateTranslation : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    model_ = new core::Model(scene::LoadSceneFromString(
        kScene, "dds_translators.yaml", std::string(TOWSIM_SOURCE_DIR) + "/config/scenes"));
    sim_ = new core::Simulation(*model_);
    core::ScriptRunner script(*model_);
    for (int k = 0; k < 20; ++k) {
      script.Apply(sim_);
      ASSERT_TRUE(sim_->Step().ok());
    }
  }
  static void TearDownTestSuite() {
    delete sim_;
    delete model_;
  }
  static int Body(const std::string& name) {
    for (int b = 0; b < sim_->num_bodies(); ++b) {
      if (sim_->body_name(b) == name) return b;
    }
    return -1;
  }
  static core::Model* model_;
  static core::Simulation* sim_;
};
core::Model* StateTranslation::model_ = nullptr;
core::Simulation* StateTranslation::sim_ = nullptr;

TEST(TimeMsgTest, SplitsIntoSecondsAndNanoseconds) {
  const TimeMsg t = ToTimeMsg(12.25);
  EXPECT_EQ(t.sec, 12);
  EXPECT_EQ(t.nanosec, 250000000u);
  // rounded to the nearest nanosecond, carried into the seconds
  const TimeMsg u = ToTimeMsg(2.9999999999);
  EXPECT_EQ(u.sec, 3);
  EXPECT_EQ(u.nanosec, 0u);
  // 3 steps of 0.05 s do not sum to 0.15 exactly; the stamp does not care
  const TimeMsg v = ToTimeMsg(0.05 + 0.05 + 0.05);
  EXPECT_EQ(v.sec, 0);
  EXPECT_EQ(v.nanosec, 150000000u);
  // negative times floor (nanosec stays in [0, 1e9))
  const TimeMsg w = ToTimeMsg(-0.25);
  EXPECT_EQ(w.sec, -1);
  EXPECT_EQ(w.nanosec, 750000000u);
  EXPECT_DOUBLE_EQ(FromTimeMsg(t), 12.25);
  EXPECT_DOUBLE_EQ(FromTimeMsg(w), -0.25);
}

TEST_F(StateTranslation, OdometryIsPoseInWorldAndTwistInBody) {
  const int b = Body("tow_vehicle");
  ASSERT_GE(b, 0);
  OdometryMessage m(kWorldFrame, "tow_vehicle");
  ToOdometry(*sim_, b, &m.msg);
  EXPECT_STREQ(m.msg.header.frame_id, "world_ned");
  EXPECT_STREQ(m.msg.child_frame_id, "tow_vehicle");
  const TimeMsg stamp = ToTimeMsg(sim_->time());
  EXPECT_EQ(m.msg.header.stamp.sec, stamp.sec);
  EXPECT_EQ(m.msg.header.stamp.nanosec, stamp.nanosec);

  const core::Vec3 p = sim_->body_position(b);
  EXPECT_EQ(m.msg.pose.pose.position.x, p.x());
  EXPECT_EQ(m.msg.pose.pose.position.y, p.y());
  EXPECT_EQ(m.msg.pose.pose.position.z, p.z());
  const Eigen::Quaterniond q = sim_->body_attitude(b);
  EXPECT_EQ(m.msg.pose.pose.orientation.x, q.x());
  EXPECT_EQ(m.msg.pose.pose.orientation.y, q.y());
  EXPECT_EQ(m.msg.pose.pose.orientation.z, q.z());
  EXPECT_EQ(m.msg.pose.pose.orientation.w, q.w());
  // heading east: q_WB is (close to) a yaw of +90 deg about z (down)
  EXPECT_NEAR(m.msg.pose.pose.orientation.z, std::sin(kPi / 4), 1e-3);
  EXPECT_NEAR(m.msg.pose.pose.orientation.w, std::cos(kPi / 4), 1e-3);

  // the twist is [u v w p q r] in the body frame: the world velocity rotated into B
  const core::Vec6 nu = sim_->body_twist(b);
  EXPECT_EQ(m.msg.twist.twist.linear.x, nu(0));
  EXPECT_EQ(m.msg.twist.twist.angular.z, nu(5));
  const core::Vec3 v_B = q.conjugate() * sim_->body_velocity(b);
  EXPECT_NEAR(m.msg.twist.twist.linear.x, v_B.x(), kRotationTol);
  EXPECT_NEAR(m.msg.twist.twist.linear.y, v_B.y(), kRotationTol);
  EXPECT_NEAR(m.msg.twist.twist.linear.z, v_B.z(), kRotationTol);
  // thrust moves it forward (surge > 0), which is east in the world
  EXPECT_GT(m.msg.twist.twist.linear.x, 0.05);
  EXPECT_GT(sim_->body_velocity(b).y(), 0.05);
  for (double c : m.msg.pose.covariance) EXPECT_EQ(c, kExact);
  for (double c : m.msg.twist.covariance) EXPECT_EQ(c, kExact);
}

TEST_F(StateTranslation, SphereTwistIsItsWorldVelocity) {
  const int b = Body("fish");
  ASSERT_GE(b, 0);
  OdometryMessage m(kWorldFrame, "fish");
  ToOdometry(*sim_, b, &m.msg);
  const core::Vec3 v = sim_->body_velocity(b);
  EXPECT_EQ(m.msg.twist.twist.linear.x, v.x());
  EXPECT_EQ(m.msg.twist.twist.linear.z, v.z());
  EXPECT_EQ(m.msg.twist.twist.angular.x, 0.0);
  EXPECT_EQ(m.msg.pose.pose.orientation.w, 1.0);
}

TEST_F(StateTranslation, CableForceIsTheBodyFrameWrench) {
  const int b = Body("tow_vehicle");
  WrenchStampedMessage m("tow_vehicle");
  ToCableForce(*sim_, b, &m.msg);
  EXPECT_STREQ(m.msg.header.frame_id, "tow_vehicle");
  core::Vec3 f, moment;
  sim_->BodyCableWrench(b, &f, &moment);
  EXPECT_EQ(m.msg.wrench.force.x, f.x());
  EXPECT_EQ(m.msg.wrench.force.y, f.y());
  EXPECT_EQ(m.msg.wrench.force.z, f.z());
  EXPECT_EQ(m.msg.wrench.torque.x, moment.x());
  EXPECT_EQ(m.msg.wrench.torque.y, moment.y());
  EXPECT_EQ(m.msg.wrench.torque.z, moment.z());
  // the cable hangs below: it pulls the vehicle down (+z in B, which is +z in W at level trim)
  EXPECT_GT(m.msg.wrench.force.z, 100.0);
  // the world-frame force rotated into B
  const core::Vec3 f_B = sim_->body_attitude(b).conjugate() * sim_->BodyCableForce(b);
  EXPECT_NEAR(m.msg.wrench.force.x, f_B.x(), kRotationTol * f.norm());
}

TEST_F(StateTranslation, CableStateHasEveryNode) {
  CableStateMessage m(kWorldFrame, sim_->num_nodes());
  ToCableState(*sim_, 20, &m);
  ASSERT_EQ(m.msg.positions._length, 5u);
  ASSERT_EQ(m.msg.velocities._length, 5u);
  ASSERT_EQ(m.msg.tensions._length, 5u);
  EXPECT_EQ(m.msg.step, 20u);
  EXPECT_STREQ(m.msg.header.frame_id, "world_ned");
  for (int i = 0; i < sim_->num_nodes(); ++i) {
    const core::Vec3 r = sim_->node_position(i), v = sim_->node_velocity(i);
    EXPECT_EQ(m.msg.positions._buffer[i].x, r.x());
    EXPECT_EQ(m.msg.positions._buffer[i].z, r.z());
    EXPECT_EQ(m.msg.velocities._buffer[i].y, v.y());
    EXPECT_EQ(m.msg.tensions._buffer[i], sim_->NodeTension(i));
  }
  // node 0 is the cable start, on the towing vehicle
  EXPECT_NEAR(m.msg.positions._buffer[0].z, 3.7, 0.5);
}

TEST_F(StateTranslation, CableStateCarriesTheWinchFieldsAndTheNodeCount) {
  // sized for more nodes than in use (a winch scene's bound): the sequences carry those in use
  CableStateMessage m(kWorldFrame, sim_->num_nodes() + 7);
  ToCableState(*sim_, 20, &m);
  EXPECT_EQ(m.msg.node_count, static_cast<uint32_t>(sim_->num_nodes()));
  EXPECT_EQ(m.msg.positions._length, m.msg.node_count);
  EXPECT_EQ(m.msg.tensions._length, m.msg.node_count);
  EXPECT_EQ(m.msg.paid_out_length, sim_->cable_length());
  EXPECT_EQ(m.msg.winch_speed, sim_->winch_speed());
  EXPECT_EQ(m.msg.drum_tension, sim_->DrumTension());
  // no winch in this scene: the fixed length, speed 0, and the storage is the node count
  EXPECT_EQ(m.msg.paid_out_length, 50.0);
  EXPECT_EQ(m.msg.winch_speed, 0.0);
  EXPECT_EQ(MaxCableNodes(*sim_), sim_->num_nodes());
  // fewer storage than nodes: grown
  CableStateMessage small(kWorldFrame, 1);
  ToCableState(*sim_, 20, &small);
  ASSERT_EQ(small.msg.positions._length, 5u);
  EXPECT_EQ(small.msg.positions._buffer[4].z, sim_->node_position(4).z());
}

TEST(MaxCableNodesTest, BoundsTheNodesAtTheWinchsMaxLength) {
  core::Model model = scene::LoadSceneFromString(
      kScene, "winch.yaml", std::string(TOWSIM_SOURCE_DIR) + "/config/scenes");
  core::WinchParams w;
  w.min_length = 20.0;
  w.max_length = 125.0;
  w.max_speed = 1.0;
  w.max_acceleration = 0.1;
  model.cables[0].winch = w;
  const core::Simulation sim(model);
  // 4 elements of 12.5 m: 125 m hold 10 of them, + 3 (docs/winch.md)
  EXPECT_EQ(MaxCableNodes(sim), 13);
}

// a network (tests/unit/network_scene.h): each cable's state is that cable's nodes, and a cable
// without the winch carries its own length, speed 0 and the tension at its start
TEST(NetworkCableStateTest, EachCableCarriesItsOwnNodes) {
  const core::Model model = test::LoadNetwork();
  core::Simulation sim(model);
  for (int k = 0; k < 5; ++k) ASSERT_TRUE(sim.Step().ok());
  ASSERT_EQ(sim.num_cables(), 2);
  const int sizes[2] = {5, 4};  // elements + 1
  const double lengths[2] = {30.0, 10.0};
  for (int c = 0; c < 2; ++c) {
    SCOPED_TRACE(sim.cable_name(c));
    EXPECT_EQ(MaxCableNodes(sim, c), sizes[c]);
    CableStateMessage m(kWorldFrame, MaxCableNodes(sim, c));
    ToCableState(sim, 5, &m, c);
    ASSERT_EQ(m.msg.node_count, static_cast<uint32_t>(sizes[c]));
    ASSERT_EQ(m.msg.positions._length, m.msg.node_count);
    EXPECT_EQ(m.msg.step, 5u);
    for (int i = 0; i < sizes[c]; ++i) {
      EXPECT_EQ(m.msg.positions._buffer[i].z, sim.node_position(i, c).z()) << i;
      EXPECT_EQ(m.msg.velocities._buffer[i].x, sim.node_velocity(i, c).x()) << i;
      EXPECT_EQ(m.msg.tensions._buffer[i], sim.NodeTension(i, c)) << i;
    }
    EXPECT_EQ(m.msg.paid_out_length, lengths[c]);
    EXPECT_EQ(m.msg.winch_speed, 0.0);
    EXPECT_EQ(m.msg.drum_tension, sim.NodeTension(0, c));
  }
  // the tether's start is held 0.5 m below the depressor's centre (Eq. 24 to the Newton
  // tolerance), the main cable's end at it
  constexpr double kJointTol = 1e-6;  // [m]
  CableStateMessage tether(kWorldFrame, 4);
  ToCableState(sim, 5, &tether, 1);
  const core::Vec3 p_depressor = sim.body_position(0);
  EXPECT_NEAR(tether.msg.positions._buffer[0].z, p_depressor.z() + 0.5, kJointTol);
  EXPECT_NEAR(tether.msg.positions._buffer[0].x, p_depressor.x(), kJointTol);
  EXPECT_GT(tether.msg.tensions._buffer[0], 0.0);
}

// a towing vehicle held by two cables (a bridle), each to its own sphere, and a riser from a
// driven point left free: forces.csv's rows and the end force topics (docs/topics.md "Cable
// end forces")
constexpr const char* kBridleScene = R"(
name: bridle
time: {step: 0.05, duration: 1, output_rate: 10}
bodies:
  fish: {type: sphere, mass: 100, volume: 0.02, position: [0, 0, 33.7]}
  fish2: {type: sphere, mass: 80, volume: 0.02, position: [1, 0, 33.7]}
  tow_vehicle: {model: ../vehicles/tow_vehicle.yaml, position: [0, 0, 3.5], euler_deg: [0, 0, 0]}
cables:
  port: {length: 30, elements: 3, diameter: 0.03, density: 1300, youngs_modulus: 7.0e8,
         initial: vertical, start: {body: tow_vehicle, at: [0, 0, 0.2]}, end: {body: fish}}
  starboard: {length: 30, elements: 3, diameter: 0.03, density: 1300, youngs_modulus: 7.0e8,
              initial: vertical, start: {body: tow_vehicle, at: [1, 0, 0.2]},
              end: {body: fish2}}
  riser: {length: 10, elements: 2, diameter: 0.02, density: 1300, youngs_modulus: 7.0e8,
          initial: vertical, start: {driven: {position: [5, 0, 0], velocity: [0.5, 0, 0]}},
          end: {free: true}}
script:
  - {at: 0, body: tow_vehicle, thrust: 3000, rudder_deg: 10}
)";

// the force and moment of each attachment of a body sum to its cable wrench (the sum over its
// joint multipliers, Eq. 29-30: BodyCableWrench, computed apart): a few ulps of the forces
constexpr double kSumTol = 1e-9;  // relative to |f| (and |f| * 1 m for the moments)

TEST(EndForceTest, HeldEndsAndAttachmentsOfABodyWithSeveral) {
  const core::Model model = scene::LoadSceneFromString(
      kBridleScene, "bridle.yaml", std::string(TOWSIM_SOURCE_DIR) + "/config/scenes");
  core::Simulation sim(model);
  core::ScriptRunner script(model);
  for (int k = 0; k < 10; ++k) {
    script.Apply(&sim);
    ASSERT_TRUE(sim.Step().ok());
  }
  ASSERT_EQ(sim.num_cables(), 3);
  const int tv = 2;  // spheres first
  ASSERT_EQ(sim.body_name(tv), "tow_vehicle");
  // the vehicle's two attachments (it holds two ends), the driven start; not the spheres' ends
  // (one each: their totals are their cable_force) nor the free end
  EXPECT_TRUE(HasEndForce(sim, 0, 0));
  EXPECT_TRUE(HasEndForce(sim, 0, 1));
  EXPECT_FALSE(HasEndForce(sim, 1, 0));
  EXPECT_FALSE(HasEndForce(sim, 1, 1));
  EXPECT_TRUE(HasEndForce(sim, 0, 2));
  EXPECT_FALSE(HasEndForce(sim, 1, 2));

  core::Vec3 f_total, m_total;
  sim.BodyCableWrench(tv, &f_total, &m_total);
  core::Vec3 f_sum = core::Vec3::Zero(), m_sum = core::Vec3::Zero();
  for (int c = 0; c < 2; ++c) {
    WrenchStampedMessage w("tow_vehicle_frd");
    ToCableEndForce(sim, 0, c, &w.msg);
    EXPECT_EQ(w.msg.header.stamp.sec, 0);
    EXPECT_EQ(w.msg.header.stamp.nanosec, 500000000u);  // 10 steps of 0.05 s
    const core::Vec3 f(w.msg.wrench.force.x, w.msg.wrench.force.y, w.msg.wrench.force.z);
    const core::Vec3 m(w.msg.wrench.torque.x, w.msg.wrench.torque.y, w.msg.wrench.torque.z);
    // the end's own force in B, and its moment about the origin from its attachment point
    const core::Vec3 f_B = sim.body_attitude(tv).conjugate() * sim.end_force(0, c);
    EXPECT_LE((f - f_B).norm(), kRotationTol * f_B.norm()) << c;
    const core::Vec3 at_B = c == 0 ? core::Vec3(0, 0, 0.2) : core::Vec3(1, 0, 0.2);
    EXPECT_LE((m - at_B.cross(f_B)).norm(), kRotationTol * f_B.norm()) << c;
    EXPECT_GT(f.norm(), 1.0) << c;  // each holds a sphere and its cable
    f_sum += f;
    m_sum += m;
  }
  EXPECT_LE((f_sum - f_total).norm(), kSumTol * f_total.norm());
  EXPECT_LE((m_sum - m_total).norm(), kSumTol * f_total.norm());
  EXPECT_GT(m_total.norm(), 1.0);  // the offsets give a moment to check

  // the driven support: the force on it in W, no moment
  WrenchStampedMessage support(kWorldFrame);
  ToCableEndForce(sim, 0, 2, &support.msg);
  EXPECT_EQ(support.msg.wrench.force.x, sim.end_force(0, 2).x());
  EXPECT_EQ(support.msg.wrench.force.z, sim.end_force(0, 2).z());
  EXPECT_GT(support.msg.wrench.force.z, 0.0);  // the hanging riser pulls its support down
  EXPECT_EQ(support.msg.wrench.torque.x, 0.0);
  EXPECT_EQ(support.msg.wrench.torque.y, 0.0);
  EXPECT_EQ(support.msg.wrench.torque.z, 0.0);
}

// SceneOf: the cables with their node counts in the scene's order; the one-cable fields are
// the first cable's; no winch: none listed
TEST(SceneInfoTest, ListsTheCablesOfANetwork) {
  const core::Model model = test::LoadNetwork();
  const core::Simulation sim(model);
  SceneInfoSample s;
  SceneOf(sim, &s);
  EXPECT_EQ(s.bodies, (std::vector<std::string>{"depressor", "towfish"}));
  EXPECT_EQ(s.cables, (std::vector<std::string>{"main", "tether"}));
  EXPECT_EQ(s.cable_node_counts, (std::vector<uint32_t>{5, 4}));
  EXPECT_EQ(s.cable_nodes, 5);
  EXPECT_FALSE(s.has_winch);
  EXPECT_TRUE(s.winches.empty());
  EXPECT_TRUE(s.winch_cables.empty());
  SceneInfoMessage m;
  ToSceneInfo(s, &m);
  ASSERT_EQ(m.msg.cables._length, 2u);
  EXPECT_STREQ(m.msg.cables._buffer[0], "main");
  EXPECT_STREQ(m.msg.cables._buffer[1], "tether");
  ASSERT_EQ(m.msg.cable_node_counts._length, 2u);
  EXPECT_EQ(m.msg.cable_node_counts._buffer[0], 5u);
  EXPECT_EQ(m.msg.cable_node_counts._buffer[1], 4u);
  EXPECT_EQ(m.msg.winches._length, 0u);
  EXPECT_EQ(m.msg.winch_cables._length, 0u);
}

// the one-cable form: one cable named "cable", and a winch named "winch" on it
TEST(SceneInfoTest, TheOneCableIsNamedCableAndItsWinchWinch) {
  core::Model model = scene::LoadSceneFromString(
      kScene, "winch.yaml", std::string(TOWSIM_SOURCE_DIR) + "/config/scenes");
  core::WinchParams w;
  w.min_length = 20.0;
  w.max_length = 125.0;
  w.max_speed = 1.0;
  w.max_acceleration = 0.1;
  model.cables[0].winch = w;
  const core::Simulation sim(model);
  SceneInfoSample s;
  SceneOf(sim, &s);
  EXPECT_EQ(s.cables, (std::vector<std::string>{"cable"}));
  EXPECT_EQ(s.cable_node_counts, (std::vector<uint32_t>{5}));
  EXPECT_EQ(s.cable_nodes, 5);
  EXPECT_TRUE(s.has_winch);
  EXPECT_EQ(s.winch_min_length, 20.0);
  EXPECT_EQ(s.winch_max_length, 125.0);
  EXPECT_EQ(s.winch_max_speed, 1.0);
  EXPECT_EQ(s.winch_max_acceleration, 0.1);
  EXPECT_EQ(s.winches, (std::vector<std::string>{"winch"}));
  EXPECT_EQ(s.winch_cables, (std::vector<std::string>{"cable"}));
  SceneInfoMessage m;
  ToSceneInfo(s, &m);
  ASSERT_EQ(m.msg.winches._length, 1u);
  EXPECT_STREQ(m.msg.winches._buffer[0], "winch");
  EXPECT_STREQ(m.msg.winch_cables._buffer[0], "cable");
}

TEST(ClockTest, CarriesTheSimulationTime) {
  ClockMsg c{};
  ToClock(1.5, &c);
  EXPECT_EQ(c.clock.sec, 1);
  EXPECT_EQ(c.clock.nanosec, 500000000u);
}

TEST(StatusTest, CopiesEveryField) {
  StatusSample s;
  s.run_id = "case1-0123456789abcdef";
  s.mode = "lockstep";
  s.state = towsim_msgs_msg_dds__SimStatus_Constants_STATE_WAITING;
  s.health = towsim_msgs_msg_dds__SimStatus_Constants_HEALTH_FAILSAFE;
  s.message = "towfish: failsafe (no command for 0.5 s of simulation time)";
  s.step = 42;
  s.sim_time = 2.1;
  s.rate = 2.0;
  s.real_time_factor = 1.98;
  s.overruns = 3;
  s.newton_iterations = 4;
  s.residual = 1e-9;
  s.failsafe_count = 1;
  s.failsafe_bodies = {"towfish", "tow_vehicle"};
  s.commands_received = 10;
  s.commands_rejected = 2;
  s.commands_clamped = 1;
  s.lockstep_timeouts = 1;
  SimStatusMessage m;
  ToSimStatus(s, &m);
  s = StatusSample{};  // the message owns copies
  EXPECT_STREQ(m.msg.run_id, "case1-0123456789abcdef");
  EXPECT_STREQ(m.msg.mode, "lockstep");
  EXPECT_EQ(m.msg.state, 2);
  EXPECT_EQ(m.msg.health, 1);
  EXPECT_STREQ(m.msg.message, "towfish: failsafe (no command for 0.5 s of simulation time)");
  EXPECT_EQ(m.msg.step, 42u);
  EXPECT_EQ(m.msg.header.stamp.sec, 2);
  EXPECT_EQ(m.msg.header.stamp.nanosec, 100000000u);
  EXPECT_EQ(m.msg.rate, 2.0);
  EXPECT_EQ(m.msg.overruns, 3u);
  EXPECT_EQ(m.msg.newton_iterations, 4);
  ASSERT_EQ(m.msg.failsafe_bodies._length, 2u);
  EXPECT_STREQ(m.msg.failsafe_bodies._buffer[0], "towfish");
  EXPECT_STREQ(m.msg.failsafe_bodies._buffer[1], "tow_vehicle");
  EXPECT_EQ(m.msg.commands_rejected, 2u);
  EXPECT_EQ(m.msg.commands_clamped, 1u);
  EXPECT_EQ(m.msg.lockstep_timeouts, 1u);
}

// the status's command counts, health and message (ToStatusCommands): each source of the
// message in its order of precedence
TEST(StatusTest, CommandsHealthAndMessage) {
  CommandLimits limits;
  limits.thrust_min = -1000.0;
  limits.thrust_max = 1000.0;
  limits.rudder_max = 0.5;
  limits.elevator_max = 0.5;
  CommandArbiter arbiter({{"tow_vehicle", limits, false}}, /*command_timeout=*/0.5);
  arbiter.Receive(0, ActuatorCommandMsg{}, 0.0);  // valid: zero thrust and fins
  ActuatorCommandMsg nan{};
  nan.thrust = std::numeric_limits<double>::quiet_NaN();
  arbiter.Receive(0, nan, 0.0);  // rejected: the arbiter's last event
  StatusSample s;
  s.state = towsim_msgs_msg_dds__SimStatus_Constants_STATE_RUNNING;
  StatusNotes notes;
  notes.unknown_commands = 2;
  notes.unknown_event = "command on rt/towsim/nobody/command: no such body";
  ToStatusCommands(arbiter, notes, &s);
  EXPECT_EQ(s.commands_received, 4u);  // 2 + 2 unknown
  EXPECT_EQ(s.commands_rejected, 3u);  // 1 + 2 unknown
  EXPECT_EQ(s.commands_clamped, 0u);
  EXPECT_EQ(s.health, towsim_msgs_msg_dds__SimStatus_Constants_HEALTH_OK);
  EXPECT_EQ(s.message, arbiter.last_event());  // the arbiter's event over the unknown one
  EXPECT_FALSE(s.message.empty());
  notes.control = "sim_control: STEP ignored: the node is not paused";
  ToStatusCommands(arbiter, notes, &s);
  EXPECT_EQ(s.message, notes.control);
  notes.strain = "strain 2.1 % exceeds 2 %";
  ToStatusCommands(arbiter, notes, &s);
  EXPECT_EQ(s.message, notes.strain);
  notes.peer = "warning: another node runs on DDS domain 0";
  ToStatusCommands(arbiter, notes, &s);
  EXPECT_EQ(s.message, notes.peer);
  // failsafe after the command timeout: health FAILSAFE with the arbiter's event
  arbiter.CheckTimeouts(1.0);
  ToStatusCommands(arbiter, notes, &s);
  EXPECT_EQ(s.health, towsim_msgs_msg_dds__SimStatus_Constants_HEALTH_FAILSAFE);
  ASSERT_EQ(s.failsafe_bodies.size(), 1u);
  EXPECT_EQ(s.failsafe_bodies[0], "tow_vehicle");
  EXPECT_EQ(s.message, arbiter.last_event());
  // failed: health ERROR with the failure, over everything else
  s.state = towsim_msgs_msg_dds__SimStatus_Constants_STATE_FAILED;
  notes.failure = "solver failure at t = 1 s (step 20): not converged";
  ToStatusCommands(arbiter, notes, &s);
  EXPECT_EQ(s.health, towsim_msgs_msg_dds__SimStatus_Constants_HEALTH_ERROR);
  EXPECT_EQ(s.message, notes.failure);
}

TEST(SceneInfoTest, ListsBodies) {
  SceneInfoSample s;
  s.run_id = "r";
  s.scene = "case1_forward";
  s.mode = "fast";
  s.step_size = 0.05;
  s.duration = -1.0;
  s.command_timeout = 0.5;
  s.bodies = {"tow_vehicle", "towfish"};
  s.commanded_bodies = {"tow_vehicle"};
  s.cable_nodes = 21;
  s.has_winch = true;
  s.winch_min_length = 100.0;
  s.winch_max_length = 300.0;
  s.winch_max_speed = 1.5;
  s.winch_max_acceleration = 0.2;
  SceneInfoMessage m;
  ToSceneInfo(s, &m);
  EXPECT_TRUE(m.msg.has_winch);
  EXPECT_EQ(m.msg.winch_min_length, 100.0);
  EXPECT_EQ(m.msg.winch_max_length, 300.0);
  EXPECT_EQ(m.msg.winch_max_speed, 1.5);
  EXPECT_EQ(m.msg.winch_max_acceleration, 0.2);
  EXPECT_STREQ(m.msg.scene, "case1_forward");
  ASSERT_EQ(m.msg.bodies._length, 2u);
  EXPECT_STREQ(m.msg.bodies._buffer[1], "towfish");
  ASSERT_EQ(m.msg.commanded_bodies._length, 1u);
  EXPECT_EQ(m.msg.cable_nodes, 21u);
  EXPECT_EQ(m.msg.duration, -1.0);
}

core::VehicleParams Vehicle(bool propeller, bool rudder, bool elevator) {
  core::VehicleParams p;
  p.has_propeller = propeller;
  p.max_thrust = 12000.0;
  p.rudder.max_deflection = 0.5;
  p.elevator.max_deflection = 0.4;
  auto add = [&p](const char* name, core::Channel channel) {
    core::LiftingSurface s;
    s.name = name;
    s.channel = channel;
    p.surfaces.push_back(s);
  };
  if (rudder) add("rudder", core::Channel::kRudder);
  if (elevator) add("elevator", core::Channel::kElevator);
  add("wing", core::Channel::kNone);
  return p;
}

ActuatorCommandMsg Command(double thrust, double rudder, double elevator, uint64_t step = 7) {
  ActuatorCommandMsg m{};
  m.step = step;
  m.thrust = thrust;
  m.rudder = rudder;
  m.elevator = elevator;
  return m;
}

TEST(CommandTest, LimitsComeFromTheVehicle) {
  const CommandLimits l = LimitsOf(Vehicle(true, true, false));
  EXPECT_EQ(l.thrust_min, -3000.0);
  EXPECT_EQ(l.thrust_max, 12000.0);
  EXPECT_EQ(l.rudder_max, 0.5);
  EXPECT_EQ(l.elevator_max, 0.0);  // no surface on the elevator channel
  EXPECT_TRUE(IsCommandable(Vehicle(false, false, true)));
  EXPECT_FALSE(IsCommandable(Vehicle(false, false, false)));  // wings on no channel only
}

TEST(CommandTest, AcceptsWithinLimits) {
  const CommandLimits l = LimitsOf(Vehicle(true, true, true));
  const CheckedCommand c = FromActuatorCommand(Command(4500.0, -0.2, 0.1), l);
  EXPECT_EQ(c.verdict, CheckedCommand::kAccepted);
  EXPECT_EQ(c.command.thrust, 4500.0);
  EXPECT_EQ(c.command.rudder, -0.2);
  EXPECT_EQ(c.command.elevator, 0.1);
  EXPECT_EQ(c.step, 7u);
}

TEST(CommandTest, ClampsOutOfRange) {
  const CommandLimits l = LimitsOf(Vehicle(true, true, true));
  const CheckedCommand c = FromActuatorCommand(Command(1e6, -2.0, 0.1), l);
  EXPECT_EQ(c.verdict, CheckedCommand::kClamped);
  EXPECT_EQ(c.command.thrust, 12000.0);
  EXPECT_EQ(c.command.rudder, -0.5);
  EXPECT_EQ(c.command.elevator, 0.1);
  EXPECT_EQ(c.reason, "thrust, rudder clamped to the vehicle's limits");
  const CheckedCommand d = FromActuatorCommand(Command(-1e4, 0, 0), l);
  EXPECT_EQ(d.command.thrust, -3000.0);
}

TEST(CommandTest, RejectsNanAndInfinity) {
  const CommandLimits l = LimitsOf(Vehicle(true, true, true));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const CheckedCommand c = FromActuatorCommand(Command(100.0, nan, 0), l);
  EXPECT_EQ(c.verdict, CheckedCommand::kRejected);
  EXPECT_EQ(c.reason, "rudder is NaN");
  const CheckedCommand d = FromActuatorCommand(Command(100.0, 0, -inf), l);
  EXPECT_EQ(d.verdict, CheckedCommand::kRejected);
  EXPECT_EQ(d.reason, "elevator is infinite");
}

SimControlMsg Control(uint8_t command, uint32_t steps = 0, double rate = 0.0) {
  SimControlMsg m{};
  m.command = command;
  m.steps = steps;
  m.rate = rate;
  return m;
}

TEST(ControlTest, TranslatesEachCommand) {
  EXPECT_EQ(FromSimControl(Control(towsim_msgs_msg_dds__SimControl_Constants_PAUSE)).kind,
            ControlRequest::kPause);
  EXPECT_EQ(FromSimControl(Control(towsim_msgs_msg_dds__SimControl_Constants_RESUME)).kind,
            ControlRequest::kResume);
  const ControlRequest s =
      FromSimControl(Control(towsim_msgs_msg_dds__SimControl_Constants_STEP, 5));
  EXPECT_EQ(s.kind, ControlRequest::kStep);
  EXPECT_EQ(s.steps, 5);
  EXPECT_EQ(FromSimControl(Control(towsim_msgs_msg_dds__SimControl_Constants_RESET)).kind,
            ControlRequest::kReset);
  const ControlRequest r =
      FromSimControl(Control(towsim_msgs_msg_dds__SimControl_Constants_SET_RATE, 0, 2.5));
  EXPECT_EQ(r.kind, ControlRequest::kSetRate);
  EXPECT_EQ(r.rate, 2.5);
}

TEST(ControlTest, RefusesBadRequests) {
  const ControlRequest a =
      FromSimControl(Control(towsim_msgs_msg_dds__SimControl_Constants_STEP, 0));
  EXPECT_EQ(a.kind, ControlRequest::kInvalid);
  EXPECT_EQ(a.error, "STEP needs steps >= 1");
  const ControlRequest b =
      FromSimControl(Control(towsim_msgs_msg_dds__SimControl_Constants_SET_RATE, 0,
                             std::numeric_limits<double>::quiet_NaN()));
  EXPECT_EQ(b.kind, ControlRequest::kInvalid);
  const ControlRequest c = FromSimControl(Control(0));
  EXPECT_EQ(c.kind, ControlRequest::kInvalid);
  EXPECT_EQ(c.error, "unknown command 0");
}

}  // namespace
}  // namespace towsim::dds
