#include "dds/command_arbiter.h"

#include <cmath>
#include <cstdio>
#include <utility>

namespace towsim::dds {

CommandArbiter::CommandArbiter(std::vector<Vehicle> vehicles, double command_timeout)
    : vehicles_(std::move(vehicles)), state_(vehicles_.size()), command_timeout_(command_timeout) {}

bool CommandArbiter::Count(int v, CheckedCommand::Verdict verdict, const std::string& reason,
                           uint64_t step, double t) {
  ++received_;
  state_[v].heard = true;
  if (verdict == CheckedCommand::kRejected) {
    ++rejected_;
    last_event_ = vehicles_[v].name + ": command rejected (" + reason + ")";
    return false;
  }
  if (verdict == CheckedCommand::kClamped) {
    ++clamped_;
    last_event_ = vehicles_[v].name + ": " + reason;
  }
  State& s = state_[v];
  s.has_command = true;
  s.held_step = step;
  s.last_time = t;
  s.failsafe = false;  // commands resumed
  s.waited_for = true;
  s.fresh = true;
  return true;
}

CheckedCommand CommandArbiter::Receive(int v, const ActuatorCommandMsg& msg, double t) {
  CheckedCommand checked = FromActuatorCommand(msg, vehicles_[v].limits);
  if (Count(v, checked.verdict, checked.reason, checked.step, t)) state_[v].held = checked.command;
  return checked;
}

CheckedWinchCommand CommandArbiter::Receive(int v, const WinchCommandMsg& msg, double t) {
  CheckedWinchCommand checked = FromWinchCommand(msg, vehicles_[v].winch_params);
  if (Count(v, checked.verdict, checked.reason, checked.step, t)) {
    state_[v].held_winch = checked.command;
  }
  return checked;
}

CheckedPose CommandArbiter::Receive(int v, const OdometryMsg& msg, double t, uint64_t step,
                                    double h) {
  CheckedPose checked = FromPoseCommand(msg, vehicles_[v].name);
  State& s = state_[v];
  if (checked.verdict == CheckedCommand::kAccepted && s.has_command &&
      checked.t < s.held_pose_time) {
    // older than the pose held (out of order): counted, the newest stays
    ++received_;
    s.heard = true;
    return checked;
  }
  // the state nearest the stamp
  const int64_t state = static_cast<int64_t>(step) + std::llround((checked.t - t) / h);
  if (Count(v, checked.verdict, checked.reason, step, t)) {
    s.held_pose = checked.pose;
    s.held_pose_time = checked.t;
    s.held_state = state;
  }
  return checked;
}

void CommandArbiter::EnterFailsafe(int v, const std::string& why) {
  State& s = state_[v];
  if (!s.failsafe) {
    s.failsafe = true;
    ++failsafe_count_;
    last_event_ = vehicles_[v].name + ": failsafe (" + why + ")";
    last_failsafe_reason_ = why;
  }
  s.fresh = false;
}

int CommandArbiter::CheckTimeouts(double t) {
  int n = 0;
  for (int v = 0; v < size(); ++v) {
    const State& s = state_[v];
    if (!s.has_command || s.failsafe) continue;
    const double silent = t - s.last_time;
    if (silent >= command_timeout_ - kCommandTimeTolerance) {
      char why[128];
      std::snprintf(why, sizeof why,
                    vehicles_[v].vessel
                        ? "no pose for %.3g s of simulation time (its last motion carried on)"
                        : "no command for %.3g s of simulation time",
                    silent);
      EnterFailsafe(v, why);
      ++n;
    }
  }
  return n;
}

bool CommandArbiter::Answers(int v, int64_t step) const {
  const State& s = state_[v];
  if (vehicles_[v].vessel) return s.has_command && s.held_state >= step + 1;
  return step < 0 || (s.has_command && s.held_step == static_cast<uint64_t>(step));
}

bool CommandArbiter::ReadyFor(int64_t step) const {
  for (int v = 0; v < size(); ++v) {
    if (!vehicles_[v].lockstep || !state_[v].waited_for) continue;
    if (!Answers(v, step)) return false;
  }
  return true;
}

std::vector<int> CommandArbiter::Missing(int64_t step) const {
  std::vector<int> missing;
  for (int v = 0; v < size(); ++v) {
    if (!vehicles_[v].lockstep || !state_[v].waited_for) continue;
    if (!Answers(v, step)) missing.push_back(v);
  }
  return missing;
}

int CommandArbiter::CountMissingPoses(uint64_t step) {
  int started = 0;
  for (int v = 0; v < size(); ++v) {
    if (!vehicles_[v].vessel) continue;
    State& s = state_[v];
    const bool on_time = Answers(v, static_cast<int64_t>(step));
    if (on_time) {
      s.late = false;
      continue;
    }
    ++poses_missing_;
    if (!s.late) {
      s.late = true;
      ++started;
      last_event_ = vehicles_[v].name + ": no pose for the end of step " + std::to_string(step) +
                    " (its last motion carried on)";
    }
  }
  return started;
}

int CommandArbiter::TimeOut(int64_t step, bool unheard_too) {
  int n = 0;
  for (int v : Missing(step)) {
    State& s = state_[v];
    // never heard from: the controller may still be starting (until unheard_too)
    if (!s.heard && !unheard_too) continue;
    s.waited_for = false;
    ++lockstep_timeouts_;
    ++n;
    if (vehicles_[v].vessel) {
      EnterFailsafe(v, std::string(s.has_command || !s.heard ? "lockstep: no pose"
                                                             : "lockstep: no valid pose") +
                           (step < 0 ? std::string(" for the initial state")
                                     : " for the end of step " + std::to_string(step)) +
                           " in time (its last motion carried on)");
      continue;
    }
    EnterFailsafe(v, std::string(s.has_command || !s.heard ? "lockstep: no command"
                                                           : "lockstep: no valid command") +
                         " for step " + std::to_string(step) + " in time");
  }
  return n;
}

// the failsafe command is the default one: zero thrust and fins centred (VehicleCommand), speed
// 0, the drum held (WinchCommand)
template <class Command>
bool CommandArbiter::TakeHeld(State& s, const Command& held, Command* command) {
  if (s.failsafe) {
    *command = Command{};
    return true;
  }
  if (!s.fresh) return false;
  s.fresh = false;
  *command = held;
  return true;
}

bool CommandArbiter::Take(int v, core::VehicleCommand* command) {
  return TakeHeld(state_[v], state_[v].held, command);
}

bool CommandArbiter::Take(int v, core::WinchCommand* command) {
  return TakeHeld(state_[v], state_[v].held_winch, command);
}

bool CommandArbiter::Take(int v, core::VesselPose* pose, double* t, int64_t* state) {
  State& s = state_[v];
  if (!s.fresh) return false;
  s.fresh = false;
  *pose = s.held_pose;
  *t = s.held_pose_time;
  *state = s.held_state;
  return true;
}

void CommandArbiter::Reset() {
  for (State& s : state_) s = State{};
  received_ = rejected_ = clamped_ = failsafe_count_ = lockstep_timeouts_ = poses_missing_ = 0;
  last_event_.clear();
  last_failsafe_reason_.clear();
}

std::vector<std::string> CommandArbiter::failsafe_names() const {
  std::vector<std::string> names;
  for (int v = 0; v < size(); ++v) {
    if (state_[v].failsafe) names.push_back(vehicles_[v].name);
  }
  return names;
}

}  // namespace towsim::dds
