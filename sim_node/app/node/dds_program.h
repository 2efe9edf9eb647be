#pragma once
// sim_node's DDS program (app/node/node_main.h): sim_node_dds, which sim_node replaces itself with
// for --mode realtime, fast and lockstep, so that sim_node itself links no DDS library
// (docs/benchmarks.md, "Start-up"). It lies beside sim_node in a build tree and in
// P/libexec/towsim beside an installed P/bin/sim_node (installed/installed_data.h).

#include <filesystem>
#include <vector>

#include "app/node/command_line.h"

namespace towsim::app {

inline constexpr const char* kDdsProgramName = "sim_node_dds";

// where the DDS program of the program `exe` may be, in order: beside it (a build tree), then
// P/libexec/towsim/ when `exe` is installed under P (installed::InstallPrefix)
std::vector<std::filesystem::path> DdsProgramCandidates(const std::filesystem::path& exe);

// replaces this process with the first candidate for /proc/self/exe that is an executable
// file, with the same arguments `argv` (execv: same process id, environment and open files).
// Returns only when it cannot: 1, with `sim_node: error: --mode <mode>: ...` on stderr naming
// the places looked at.
int ExecDdsProgram(Mode mode, char** argv);

}  // namespace towsim::app
