// sim_node/dds/actuator_state_translator: a vehicle's command in force and actuator states
// (towsim_msgs/ActuatorState) are the simulation's own values, field for field, with the
// node's failsafe flag and source, stamped with the simulation time; each vehicle's its own.
// Case 1 (config/scenes/case1_forward.yaml) stepped with a rudder and elevator step, so that
// the rate-limited fins lie strictly between their start and their commands and no field can
// stand in for another.

#include "dds/actuator_state_translator.h"

#include <string>

#include <gtest/gtest.h>

#include "core/simulation.h"
#include "core/vehicle_model.h"
#include "dds/frames.h"
#include "dds/translators.h"
#include "scene/scene_loader.h"

namespace towsim::dds {
namespace {

core::Model Case1() { return scene::LoadScene(TOWSIM_SOURCE_DIR "/config/scenes/case1_forward.yaml"); }

TEST(ActuatorStateTranslator, ValuesInAreValuesOut) {
  core::Simulation sim(Case1());
  ASSERT_EQ(sim.num_vehicles(), 2);
  core::VehicleCommand command;
  command.thrust = 4165.0;
  command.rudder = 0.3;
  command.elevator = -0.05;
  sim.SetVehicleCommand(0, command);
  for (int k = 0; k < 3; ++k) ASSERT_TRUE(sim.Step().ok());

  const int tow = sim.num_spheres();  // the tow vehicle's body index
  ActuatorStateMessage a(FrdFrame(sim.body_name(tow)));
  ToActuatorState(sim, 0, 3, ActuatorFlags{false, kSourceDds}, &a.msg);
  const core::VehicleState& s = sim.vehicle_state(0);
  EXPECT_EQ(a.msg.thrust_command, 4165.0);
  EXPECT_EQ(a.msg.rudder_command, 0.3);
  EXPECT_EQ(a.msg.elevator_command, -0.05);
  EXPECT_EQ(a.msg.thrust, s.actuator[core::kThrust]);
  EXPECT_EQ(a.msg.rudder, s.actuator[core::kRudder]);
  EXPECT_EQ(a.msg.elevator, s.actuator[core::kElevator]);
  // 0.15 s into the step: the fins on their way (rate limited), not yet at the command
  EXPECT_GT(a.msg.rudder, 0.0);
  EXPECT_LT(a.msg.rudder, 0.3);
  EXPECT_LT(a.msg.elevator, 0.0);
  EXPECT_GT(a.msg.elevator, -0.05);
  EXPECT_FALSE(a.msg.failsafe);
  EXPECT_EQ(a.msg.source, kSourceDds);
  EXPECT_EQ(a.msg.step, 3u);
  const TimeMsg t = ToTimeMsg(sim.time());
  EXPECT_EQ(a.msg.header.stamp.sec, t.sec);
  EXPECT_EQ(a.msg.header.stamp.nanosec, t.nanosec);
  EXPECT_EQ(std::string(a.msg.header.frame_id), "tow_vehicle_frd");

  // the towfish: its own command (the scene's) and states, the flags as given
  ActuatorStateMessage f(FrdFrame(sim.body_name(tow + 1)));
  ToActuatorState(sim, 1, 3, ActuatorFlags{true, kSourceFailsafe}, &f.msg);
  const core::VehicleState& sf = sim.vehicle_state(1);
  EXPECT_EQ(f.msg.thrust_command, sim.vehicle_command(1).thrust);
  EXPECT_EQ(f.msg.rudder_command, sim.vehicle_command(1).rudder);
  EXPECT_EQ(f.msg.elevator_command, sim.vehicle_command(1).elevator);
  EXPECT_EQ(f.msg.thrust, sf.actuator[core::kThrust]);
  EXPECT_EQ(f.msg.rudder, sf.actuator[core::kRudder]);
  EXPECT_EQ(f.msg.elevator, sf.actuator[core::kElevator]);
  EXPECT_TRUE(f.msg.failsafe);
  EXPECT_EQ(f.msg.source, kSourceFailsafe);
  EXPECT_EQ(std::string(f.msg.header.frame_id), "towfish_frd");
}

// the source constants are the IDL's and the .msg's (msgs/), in this order
TEST(ActuatorStateTranslator, SourceConstants) {
  EXPECT_EQ(kSourceNone, 0);
  EXPECT_EQ(kSourceScript, 1);
  EXPECT_EQ(kSourceDds, 2);
  EXPECT_EQ(kSourceFailsafe, 3);
  EXPECT_EQ(ActuatorFlags{}.source, kSourceNone);
  EXPECT_FALSE(ActuatorFlags{}.failsafe);
}

}  // namespace
}  // namespace towsim::dds
