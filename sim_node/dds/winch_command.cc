#include "dds/winch_command.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "towsim_msgs.h"

namespace towsim::dds {

CheckedWinchCommand FromWinchCommand(const WinchCommandMsg& msg, const core::WinchParams& winch) {
  CheckedWinchCommand out;
  out.step = msg.step;
  const char* what = "";
  switch (msg.mode) {
    case towsim_msgs_msg_dds__WinchCommand_Constants_SPEED:
      out.command.mode = core::WinchCommand::Mode::kSpeed;
      what = "speed";
      break;
    case towsim_msgs_msg_dds__WinchCommand_Constants_LENGTH:
      out.command.mode = core::WinchCommand::Mode::kLength;
      what = "length";
      break;
    default:
      out.verdict = CheckedCommand::kRejected;
      out.reason = "mode " + std::to_string(msg.mode) + " is neither SPEED (0) nor LENGTH (1)";
      return out;
  }
  if (!std::isfinite(msg.value)) {
    out.verdict = CheckedCommand::kRejected;
    out.reason = std::string(what) + " is " + (std::isnan(msg.value) ? "NaN" : "infinite");
    return out;
  }
  out.command.value = msg.value;
  const core::Actuator range = core::WinchCommandRange(winch, out.command.mode);
  if (range.Clamp(&out.command.value)) {
    char text[160];
    std::snprintf(text, sizeof text, "winch %s %g clamped to the winch's limits [%g, %g]", what,
                  msg.value, range.min, range.max);
    out.verdict = CheckedCommand::kClamped;
    out.reason = text;
  }
  return out;
}

}  // namespace towsim::dds
