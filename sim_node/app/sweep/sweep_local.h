#pragma once
// The local runner of towsim_sweep: up to `workers` sim_node processes at once, one per case
// (posix_spawn; stdin /dev/null, stdout and stderr to the case's sim_node.out / .err). When a
// case's process ends, its exit code and wall time go to its case_status.txt (sweep_case.h) and
// `on_finished` is called (it returns whether the case is ok). SIGINT / SIGTERM (stop_signal.h)
// stop the sweep: every running sim_node gets SIGTERM and is waited for; stopped cases (exit 130 /
// 143) are not recorded, so
// --resume runs them again.

#include <functional>
#include <string>
#include <vector>

#include "app/sweep/sweep_progress.h"

namespace towsim::app {

struct LocalCase {
  std::string dir;                     // the case's folder
  std::vector<std::string> arguments;  // sim_node's arguments
};

// Runs `cases` in order with `workers` processes of `sim_node`. Returns 0 when all ended, or
// 128 + signal when stopped. Throws std::runtime_error if a process cannot be started.
int RunLocal(const std::string& sim_node, const std::vector<LocalCase>& cases, int workers,
             const std::function<bool(size_t case_number)>& on_finished, SweepProgress* progress);

}  // namespace towsim::app
