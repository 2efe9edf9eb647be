#pragma once
// The winch's command on the wire (docs/winch_dds.md): towsim_msgs/WinchCommand on
// rt/<ns>/winch/command -> core::WinchCommand, checked like a vehicle's ActuatorCommand
// (dds/translators.h FromActuatorCommand). Pure: no DDS entities, no clocks
// (tests/unit/dds_winch_command_test.cc).
//
//   mode SPEED   value = drum speed dL/dt [m/s], + pays out; clamped to +-max_speed
//   mode LENGTH  value = the paid-out length to drive to [m]; clamped to [min_length, max_length]
//   NaN or infinite value, or a mode other than SPEED / LENGTH: rejected (the held command stays)
//
// The limits are the winch's own (core::WinchParams, the scene's cable.winch), through the
// core's WinchCommandRange, the same the core clamps to (Simulation::SetWinchCommand), so that
// each limit is written once.

#include <cstdint>
#include <string>

#include "core/winch.h"
#include "dds/messages.h"
#include "dds/translators.h"

namespace towsim::dds {

// the name the winch goes by in the command arbitration, SimStatus.failsafe_bodies and
// --lockstep-bodies (and its topic: rt/<ns>/winch/command)
inline constexpr const char* kWinchName = "winch";

struct CheckedWinchCommand {
  CheckedCommand::Verdict verdict = CheckedCommand::kAccepted;
  core::WinchCommand command;  // clamped (kClamped) or as sent (kAccepted); unset if rejected
  uint64_t step = 0;           // the step the command answers
  std::string reason;          // kClamped / kRejected: what and why
};

// NaN / infinite value or unknown mode: rejected; beyond the limits: clamped
CheckedWinchCommand FromWinchCommand(const WinchCommandMsg& msg, const core::WinchParams& winch);

}  // namespace towsim::dds
