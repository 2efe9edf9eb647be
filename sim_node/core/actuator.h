#pragma once
// An actuator: the one model of every commanded device (the propeller's thrust, the fins; the
// same form fits a winch's drum speed). A command u drives the actuator's state x through a
// range, a rate limit and a first-order lag:
//   x_dot = clamp( (clamp(u, min, max) - x) / T, -max_rate, max_rate )
// The range is also what an incoming command is clamped to (the DDS command check takes it
// from here: sim_node/dds/translators.h, LimitsOf), so each limit is written once.
//
// The vehicles' actuators (docs/physics.md "Vehicles"):
//   thrust:  range [-max_thrust / 4, max_thrust] (a propeller astern gives about a quarter of its
//            ahead thrust), no rate limit, T = thrust_time_constant (vehicle file);
//   fins:    range +-max_deflection, rate +-max_rate (vehicle file), T = kFinServoTimeConstant.

#include <array>
#include <limits>

#include "core/vehicle_model.h"

namespace towsim::core {

// fin servo lag: fast against every rigid-body time constant (> 0.5 s), and it keeps the
// right-hand side Lipschitz for RK4 (a pure rate limiter, sign(u - x) max_rate, chatters about
// the target)
constexpr double kFinServoTimeConstant = 0.05;  // [s]

// astern thrust as a fraction of the ahead limit max_thrust
constexpr double kAsternThrustFraction = 0.25;

struct Actuator {
  bool fitted = true;           // false: the vehicle has none (its state does not move)
  double min = 0.0, max = 0.0;  // range of the command and the state [unit]
  double max_rate = std::numeric_limits<double>::infinity();  // |x_dot| [unit/s]
  double time_constant = 1.0;                                 // T [s], > 0

  // u clamped into [min, max]
  double Target(double u) const;
  // clamps *u into [min, max]; returns whether it had to
  bool Clamp(double* u) const;
  // x_dot for command u at state x (the law above)
  double Rate(double u, double x) const;
};

// the propeller of a vehicle (a vehicle without one: not fitted, range [0, 0])
Actuator ThrustActuator(const VehicleParams& p);
// a fin channel's servo with its limits from the vehicle file
Actuator FinActuator(const ActuatorLimits& limits);
Actuator RudderActuator(const VehicleParams& p);    // FinActuator(p.rudder)
Actuator ElevatorActuator(const VehicleParams& p);  // FinActuator(p.elevator)

// One row per vehicle actuator, in the order of VehicleActuator (vehicle_model.h): the command
// that drives it and its law.
struct VehicleActuatorRow {
  double VehicleCommand::*command;
  Actuator (*law)(const VehicleParams&);
};
inline constexpr std::array<VehicleActuatorRow, kVehicleActuatorCount> kVehicleActuators = {{
    {&VehicleCommand::thrust, ThrustActuator},      // kThrust
    {&VehicleCommand::rudder, RudderActuator},      // kRudder
    {&VehicleCommand::elevator, ElevatorActuator},  // kElevator
}};

// the actuators' rates x_dot (the law above; 0 for one not fitted), indexed by VehicleActuator
std::array<double, kVehicleActuatorCount> ActuatorRates(const VehicleParams& p,
                                                        const VehicleCommand& cmd,
                                                        const VehicleState& s);

}  // namespace towsim::core
