#include "app/node/failsafe_failure.h"

#include <cstdio>

namespace towsim::app {

std::string FailsafeEntries(const dds::CommandArbiter& arbiter) {
  std::string text;
  for (int v = 0; v < arbiter.size(); ++v) {
    if (!arbiter.failsafe(v)) continue;
    if (!text.empty()) text += ", ";
    const std::string& name = arbiter.vehicle(v).name;
    if (!arbiter.vehicle(v).winch) {
      text += "body " + name;
    } else {
      text += name == dds::kWinchName ? std::string("the winch") : "the winch " + name;
    }
  }
  return text;
}

std::string FailsafeFailure(const std::string& entries, double t, uint64_t step,
                            const std::string& why) {
  char when[96];
  std::snprintf(when, sizeof when, " at t = %.9g s (step %llu): ", t,
                static_cast<unsigned long long>(step));
  return "failsafe: " + entries + when + why;
}

std::string LockstepTimeoutFailure(const std::string& entries, double t, uint64_t step,
                                   double waited, double limit, bool never_heard) {
  char text[160];
  if (never_heard) {
    std::snprintf(text, sizeof text,
                  " at step %llu (t = %.9g s): no command after %.3g s (never heard from: is its "
                  "controller running?)",
                  static_cast<unsigned long long>(step), t, waited);
  } else {
    std::snprintf(text, sizeof text,
                  " at step %llu (t = %.9g s): no command after %.3g s (--lockstep-timeout %g)",
                  static_cast<unsigned long long>(step), t, waited, limit);
  }
  return "lockstep timeout: " + entries + text;
}

}  // namespace towsim::app
