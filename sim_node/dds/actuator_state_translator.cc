#include "dds/actuator_state_translator.h"

#include <utility>

#include "core/vehicle_model.h"
#include "dds/translators.h"

namespace towsim::dds {

ActuatorStateMessage::ActuatorStateMessage(std::string frame_id)
    : msg{}, frame_id_(std::move(frame_id)) {
  msg.header.frame_id = frame_id_.data();
}

void ToActuatorState(const core::Simulation& sim, int vehicle, uint64_t step,
                     const ActuatorFlags& flags, ActuatorStateMsg* msg) {
  msg->header.stamp = ToTimeMsg(sim.time());
  msg->step = step;
  // the columns of actuators.csv (io/csv_writer.cc, WriteActuatorRow), from the same values
  const core::VehicleCommand& command = sim.vehicle_command(vehicle);
  msg->thrust_command = command.thrust;
  msg->rudder_command = command.rudder;
  msg->elevator_command = command.elevator;
  const core::VehicleState& state = sim.vehicle_state(vehicle);
  msg->thrust = state.actuator[core::kThrust];
  msg->rudder = state.actuator[core::kRudder];
  msg->elevator = state.actuator[core::kElevator];
  msg->failsafe = flags.failsafe;
  msg->source = flags.source;
}

}  // namespace towsim::dds
