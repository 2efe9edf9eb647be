#pragma once
// The exit codes of towsim's programs, in one place (docs/command_line.md "Exit codes").
// Offline, sim_node and towsim_sweep stopped by a signal exit 128 + the signal (130 SIGINT,
// 143 SIGTERM, app/common/stop_signal.h); the DDS programs exit 0 then.

namespace towsim::app {

inline constexpr int kExitOk = 0;
// unexpected: an output could not be written (disk full), sbatch failed, ...
inline constexpr int kExitError = 1;
// bad input: the command line, an input file, a DDS setup failure, a port in use
inline constexpr int kExitBadInput = 2;
// sim_node: the static solve or a step failed
inline constexpr int kExitSolver = 3;
// the job was done in part: towsim_export / towsim_replay --recover skipped damaged byte
// ranges; towsim_sweep ran every case and some failed (results.csv)
inline constexpr int kExitIncomplete = 4;
// sim_node --fail-on-failsafe: a body entered failsafe or a lockstep step timed out; the run
// ended after that step with its outputs complete and a final status FAILED naming the body,
// the step and the reason (docs/command_line.md "Exit codes")
inline constexpr int kExitFailsafe = 5;

}  // namespace towsim::app
