#include "core/actuator.h"

#include <algorithm>

namespace towsim::core {

double Actuator::Target(double u) const { return std::clamp(u, min, max); }

bool Actuator::Clamp(double* u) const {
  const double c = Target(*u);
  const bool clamped = c != *u;
  *u = c;
  return clamped;
}

double Actuator::Rate(double u, double x) const {
  // x_dot = clamp((clamp(u) - x) / T, +-max_rate)
  return std::clamp((Target(u) - x) / time_constant, -max_rate, max_rate);
}

Actuator ThrustActuator(const VehicleParams& p) {
  Actuator a;
  a.fitted = p.has_propeller;
  if (!a.fitted) return a;
  a.min = -kAsternThrustFraction * p.max_thrust;
  a.max = p.max_thrust;
  a.time_constant = p.thrust_time_constant;
  return a;
}

Actuator FinActuator(const ActuatorLimits& limits) {
  Actuator a;
  a.min = -limits.max_deflection;
  a.max = limits.max_deflection;
  a.max_rate = limits.max_rate;
  a.time_constant = kFinServoTimeConstant;
  return a;
}

Actuator RudderActuator(const VehicleParams& p) { return FinActuator(p.rudder); }

Actuator ElevatorActuator(const VehicleParams& p) { return FinActuator(p.elevator); }

std::array<double, kVehicleActuatorCount> ActuatorRates(const VehicleParams& p,
                                                        const VehicleCommand& cmd,
                                                        const VehicleState& s) {
  std::array<double, kVehicleActuatorCount> rate{};
  for (int i = 0; i < kVehicleActuatorCount; ++i) {
    const Actuator a = kVehicleActuators[i].law(p);
    if (a.fitted) rate[i] = a.Rate(cmd.*kVehicleActuators[i].command, s.actuator[i]);
  }
  return rate;
}

}  // namespace towsim::core
