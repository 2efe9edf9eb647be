#pragma once
// The local runner of towsim_sweep: up to `workers` cases at once (sweep_case_run.h: sim_node
// alone, or beside the sweep's controllers on a DDS domain of the case's own). When a case
// has ended, its exit code, wall time and (a controller's failure) message go to its
// case_status.txt (sweep_case.h) and `on_finished` is called (it returns whether the case is
// ok). SIGINT / SIGTERM (stop_signal.h) stop the sweep: every running process gets SIGTERM and
// is waited for; stopped cases are not recorded, so --resume runs them again.

#include <functional>
#include <string>
#include <vector>

#include "app/sweep/sweep_case_run.h"
#include "app/sweep/sweep_progress.h"

namespace towsim::app {

// Runs `cases` in order, `workers` at once. Returns 0 when all ended, or 128 + signal when
// stopped. Throws std::runtime_error if a process cannot be started.
int RunLocal(const std::string& sim_node, const std::vector<LocalCase>& cases, int workers,
             const std::function<bool(size_t case_number)>& on_finished, SweepProgress* progress);

}  // namespace towsim::app
