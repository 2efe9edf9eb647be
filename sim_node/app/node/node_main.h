#pragma once
// main() of sim_node (docs/contract.md §4-5): the command line, the scene, the CSV files and the run.
// Two executables share it, so that an offline run loads no DDS library (docs/benchmarks.md,
// "Start-up"):
//
//   sim_node      links the core, the scene reader and the CSV writer only. An offline run
//                 runs here; for a DDS mode (realtime, fast, lockstep) it replaces itself with
//                 the DDS program (app/node/dds_program.h: execv, same process id, same arguments),
//                 once the command line has been checked.
//   sim_node_dds  every mode in its own process, DDS included: the program sim_node hands the
//                 DDS modes to (P/libexec/towsim/sim_node_dds in an installation).
//
// Both print as `sim_node` and share the exit codes of README "Exit codes".

#include "app/node/command_line.h"
#include "core/model.h"
#include "io/csv_writer.h"

namespace towsim::app {

// runs a DDS mode in this process: the scene's model (its duration already set from
// --duration), the options and the CSV writer (null without --csv); returns the exit code
using DdsModeRunner = int (*)(const core::Model& model, const Options& options, io::CsvWriter* csv);

// the whole program: returns its exit code. `run_dds` null (sim_node): a DDS mode execs the
// DDS program before the scene is read; else (sim_node_dds) a DDS mode runs through it.
int NodeMain(int argc, char** argv, DdsModeRunner run_dds);

}  // namespace towsim::app
