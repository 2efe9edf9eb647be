#pragma once
// The offline mode (docs/contract.md §4): no DDS; the simulation is stepped as fast as it goes, commands
// come from the scene's script, output goes to CSV.

#include "core/model.h"
#include "io/csv_writer.h"

namespace towsim::app {

// Builds a core::Simulation from `model` and steps it round(duration / h) times.
//
// `csv` (may be null) receives the state at t = 0, every k = max(1, round(1 / (output_rate h)))
// steps, and the last state reached if that is not already written (end of the run, or where
// SIGINT / SIGTERM stopped it; not after a failed step). The progress line goes to stderr, the
// summary line (run_stats.h) to stdout.
//
// Returns the exit code: 0 done, 3 solver failure (initial state or a step; the diagnosis is
// printed on stderr), 128 + signal when stopped by SIGINT / SIGTERM (stop_signal.h).
// Throws std::runtime_error if writing the CSV fails.
int RunOffline(const core::Model& model, double duration, io::CsvWriter* csv);

}  // namespace towsim::app
