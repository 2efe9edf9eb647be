#include "core/script.h"

#include "core/constants.h"

namespace towsim::core {
namespace {

constexpr double kRadToDeg = 180.0 / kPi;

}  // namespace

double ConditionQuantity(ScriptCondition::Quantity quantity, const VehicleState& s) {
  switch (quantity) {
    case ScriptCondition::kX:
      return s.p_W.x();
    case ScriptCondition::kY:
      return s.p_W.y();
    case ScriptCondition::kZ:
      return s.p_W.z();
    case ScriptCondition::kRollDeg:
      return kRadToDeg * EulerZYX(s.q_WB).x();
    case ScriptCondition::kPitchDeg:
      return kRadToDeg * EulerZYX(s.q_WB).y();
    case ScriptCondition::kYawDeg:
      return kRadToDeg * EulerZYX(s.q_WB).z();
    case ScriptCondition::kU:
    case ScriptCondition::kV:
    case ScriptCondition::kW:
    case ScriptCondition::kP:
    case ScriptCondition::kQ:
    case ScriptCondition::kR:
      return s.nu(quantity - ScriptCondition::kU);
    case ScriptCondition::kSpeed:
      return s.nu.head<3>().norm();
  }
  return 0.0;
}

bool ConditionHolds(const ScriptCondition& condition, const VehicleState& s) {
  const double x = ConditionQuantity(condition.quantity, s);
  switch (condition.op) {
    case ScriptCondition::kGreaterEqual:
      return x >= condition.value;
    case ScriptCondition::kLessEqual:
      return x <= condition.value;
    case ScriptCondition::kGreater:
      return x > condition.value;
    case ScriptCondition::kLess:
      return x < condition.value;
  }
  return false;
}

ScriptRunner::ScriptRunner(const Model& model)
    : entries_(model.script),
      fired_(model.script.size(), false),
      remaining_(static_cast<int>(model.script.size())) {}

int ScriptRunner::Apply(Simulation* sim, std::vector<bool>* set) {
  int fired = 0;
  for (size_t i = 0; i < entries_.size(); ++i) {
    const ScriptEntry& e = entries_[i];
    if (fired_[i] || sim->time() < e.at - kScriptTimeTolerance) continue;
    if (e.has_condition && !ConditionHolds(e.condition, sim->vehicle_state(e.condition.vehicle))) {
      continue;
    }
    // the given fields replace those of the command held so far
    if (e.vehicle >= 0) {
      VehicleCommand command = sim->vehicle_command(e.vehicle);
      if (e.set_thrust) command.thrust = e.thrust;
      if (e.set_rudder) command.rudder = e.rudder;
      if (e.set_elevator) command.elevator = e.elevator;
      sim->SetVehicleCommand(e.vehicle, command);
      if (set != nullptr) (*set)[e.vehicle] = true;
    }
    if (e.set_winch) sim->SetWinchCommand(e.winch, e.winch_index);
    fired_[i] = true;
    --remaining_;
    ++fired;
  }
  return fired;
}

}  // namespace towsim::core
