#pragma once
// The offline script (Model::script): commands that fire once each, at a time and optionally
// when a condition on a vehicle's state holds, e.g.
//   {at: 55, when: "tow_vehicle.yaw_deg >= 170", body: tow_vehicle, rudder_deg: 0},
//   {at: 10, winch_speed: 1.0}, {at: 200, winch_length: 150} (the winch: winch.h).
//
//   ScriptRunner script(model);
//   script.Apply(&sim);                          // at t = 0
//   while (...) { sim.Step(); script.Apply(&sim); }
//
// Pure logic on the simulation's time and vehicle states; no clocks, no I/O.

#include <vector>

#include "core/model.h"
#include "core/simulation.h"
#include "core/vehicle_model.h"

namespace towsim::core {

// An entry fires at the first Apply with t >= at - kScriptTimeTolerance (steps of a fixed h
// land on at = k h only up to rounding).
inline constexpr double kScriptTimeTolerance = 1e-9;  // [s]

// The condition's quantity of `s`: x, y, z of the origin in W [m]; roll, pitch, yaw (ZYX,
// (-180, 180]) [deg]; u, v, w [m/s] and p, q, r [rad/s] in the body frame; speed |(u, v, w)|.
double ConditionQuantity(ScriptCondition::Quantity quantity, const VehicleState& s);

// `quantity op value` on the state `s` of the condition's vehicle
bool ConditionHolds(const ScriptCondition& condition, const VehicleState& s);

class ScriptRunner {
 public:
  explicit ScriptRunner(const Model& model);

  // Fires, in script order, every entry not yet fired whose time has come (sim->time() >= at)
  // and whose condition (if any) holds on the current vehicle states: its given fields
  // (thrust, rudder, elevator) replace those of the vehicle's command, through
  // Simulation::SetVehicleCommand; a winch_speed or winch_length replaces the winch's command
  // (Simulation::SetWinchCommand). Returns the number of entries fired. With `set`, sized to
  // the vehicles, set[v] becomes true for each vehicle v whose command an entry fired set.
  int Apply(Simulation* sim, std::vector<bool>* set = nullptr);

  // every entry has fired
  bool done() const { return remaining_ == 0; }

 private:
  std::vector<ScriptEntry> entries_;
  std::vector<bool> fired_;
  int remaining_ = 0;
};

}  // namespace towsim::core
