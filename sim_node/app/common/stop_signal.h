#pragma once
// SIGINT / SIGTERM ask the run to stop at the next step boundary: the handler only records
// the signal; the loop polls StopRequested(), flushes its output and exits with 128 + signal
// (130 for SIGINT, 143 for SIGTERM), as a shell expects.

namespace towsim::app {

// installs the handlers for SIGINT and SIGTERM (once, at start-up)
void InstallStopHandlers();

// the signal number received, 0 if none
int StopRequested();

}  // namespace towsim::app
