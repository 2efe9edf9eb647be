#pragma once
// The reason a run under sim_node --fail-on-failsafe ends (exit code 5, kExitFailsafe;
// docs/command_line.md "Exit codes", docs/topics.md "Commands and lockstep"): which body,
// when and why, for stderr and the message of the final SimStatus (state FAILED). Pure: the
// node passes what it saw; no clocks, no DDS.
//
//   failsafe: body towfish at t = 12.34 s (step 1234): no command for 0.5 s of simulation time
//   lockstep timeout: body towfish at step 1234 (t = 12.34 s): no command after 2 s
//   (--lockstep-timeout 2)
//   lockstep timeout: body towfish at step 0 (t = 0 s): no command after 30 s (never heard
//   from: is its controller running?)
//
// Steps are numbered as the commands are stamped: step k goes from state k (at t) to k + 1.

#include <cstdint>
#include <string>

#include "dds/command_arbiter.h"

namespace towsim::app {

// the arbiter's entries now in failsafe: "body towfish", "body a, body b", "the winch"
std::string FailsafeEntries(const dds::CommandArbiter& arbiter);

// a failsafe entered after `command_timeout` of silence (CommandArbiter::CheckTimeouts):
// `entries` from FailsafeEntries, `why` CommandArbiter::last_failsafe_reason()
std::string FailsafeFailure(const std::string& entries, double t, uint64_t step,
                            const std::string& why);

// lockstep waited out `waited` wall seconds (the bound it gave up at: --lockstep-timeout, or
// the longer start-up limit) for the commands of `step` (state at t); `limit`:
// --lockstep-timeout [s]; `never_heard`: the entries never sent a command (the start-up limit)
std::string LockstepTimeoutFailure(const std::string& entries, double t, uint64_t step,
                                   double waited, double limit, bool never_heard);

}  // namespace towsim::app
