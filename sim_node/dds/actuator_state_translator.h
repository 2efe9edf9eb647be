#pragma once
// A vehicle's actuators on the wire (docs/topics.md, "Actuator state"): a pure translator from
// the core's command in force (Simulation::vehicle_command) and actuator states
// (Simulation::vehicle_state(v).actuator) to towsim_msgs/ActuatorState, the values and the
// order of the node's actuators.csv row of the same step (io/csv_writer.h, WriteActuatorRow);
// no DDS entities, no clocks (tests/unit/actuator_state_translator_test.cc).
//
//   thrust_command, rudder_command, elevator_command   the command in force [N, rad]
//   thrust, rudder, elevator                           the actuators' states [N, rad]
//   failsafe                                           the command arbiter's flag
//   source                                             who set the command in force (below)
//
// Header: stamp = simulation time, frame_id = <body>_frd (the thrust's frame).

#include <cstdint>
#include <string>

#include "core/simulation.h"
#include "dds/messages.h"

namespace towsim::dds {

// ActuatorState.source: who set the command a vehicle holds (docs/topics.md "Actuator state")
inline constexpr std::uint8_t kSourceNone = towsim_msgs_msg_dds__ActuatorState_Constants_SOURCE_NONE;
inline constexpr std::uint8_t kSourceScript =
    towsim_msgs_msg_dds__ActuatorState_Constants_SOURCE_SCRIPT;
inline constexpr std::uint8_t kSourceDds = towsim_msgs_msg_dds__ActuatorState_Constants_SOURCE_DDS;
inline constexpr std::uint8_t kSourceFailsafe =
    towsim_msgs_msg_dds__ActuatorState_Constants_SOURCE_FAILSAFE;

// what the node knows of a vehicle's command beyond the simulation (the arbiter's)
struct ActuatorFlags {
  bool failsafe = false;              // in failsafe (actuators.csv's failsafe column)
  std::uint8_t source = kSourceNone;  // kSource*
};

class ActuatorStateMessage {
 public:
  // frame_id: the vehicle's body frame, <body>_frd
  explicit ActuatorStateMessage(std::string frame_id);
  ActuatorStateMessage(const ActuatorStateMessage&) = delete;
  ActuatorStateMessage& operator=(const ActuatorStateMessage&) = delete;
  ActuatorStateMsg msg;

 private:
  std::string frame_id_;
};

// vehicle v's (Model::vehicles order) command and actuators after `step` steps; never allocates
void ToActuatorState(const core::Simulation& sim, int vehicle, uint64_t step,
                     const ActuatorFlags& flags, ActuatorStateMsg* msg);

}  // namespace towsim::dds
