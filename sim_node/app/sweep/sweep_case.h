#pragma once
// One case of a sweep on disk (docs/sweeps.md "Files"): its folder DIR/<case>/ holds
//   command.sh        runs the case by hand or as a Slurm task: sim_node offline with the
//                     case's --set values and --csv into the folder (with controllers:
//                     towsim_sweep --run-case DIR/<case>), then writes case_status.txt
//   case_args.txt     the sim_node arguments, one a line (compared by --resume)
//   controllers.txt   with controllers: each one's name, program and arguments (compared by
//                     --resume): "controller <name> <n>", then n lines: the program, the args
//   sim_node.out/.err sim_node's stdout (the summary line) and stderr; <controller>.out/.err
//   bodies.csv cable.csv forces.csv status.csv   the CSV files of --csv
//   case_status.txt   "exit_code=N", "wall_s=S", with controllers "domain=D" and, when a
//                     controller failed, "message=...", written (atomically) when it ended
// A case without case_status.txt has not run (or was stopped); with it, it is finished.

#include <optional>
#include <string>
#include <vector>

#include "app/sweep/sweep_combinator.h"
#include "app/sweep/sweep_controllers.h"
#include "app/sweep/sweep_file.h"
#include "app/sweep/sweep_signals.h"

namespace towsim::app {

// the sim_node arguments of a case (without the program): --scene, --mode offline (with
// controllers: lockstep [--lockstep-timeout S]), --fail-on-failsafe, [--duration], --set per
// parameter (not those of the controllers only), --csv `case_dir`; paths absolute. The domain
// of a case with controllers is added when it starts. Offline --fail-on-failsafe changes
// nothing; with controllers a failsafe or a lockstep timeout ends the case, failed (exit 5),
// rather than letting it go on uncontrolled (docs/sweeps.md)
std::vector<std::string> CaseArguments(const SweepSpec& spec, const SweepCase& c,
                                       const std::string& case_dir);

// `s` as one shell word: single-quoted, a ' inside written '\''
std::string ShellWord(const std::string& s);

// what runs a case: towsim_sweep itself, sim_node, and the DDS domain ids of a case with
// controllers
struct CaseRunner {
  std::string sweep;  // towsim_sweep (command.sh of a case with controllers runs it)
  std::string sim_node;
  int domain_first = kDefaultSweepDomain;
  int domain_last = kMaxSweepDomain;
};

// Creates the folder and writes command.sh, case_args.txt and, with controllers,
// controllers.txt. Throws std::runtime_error if they cannot be written.
void PrepareCase(const std::string& case_dir, const CaseRunner& runner,
                 const std::vector<std::string>& arguments,
                 const std::vector<CaseController>& controllers = {});

// true if the folder's case_args.txt holds exactly `arguments` and its controllers.txt
// `controllers` (the case is the same)
bool SameArguments(const std::string& case_dir, const std::vector<std::string>& arguments,
                   const std::vector<CaseController>& controllers = {});

// the text of controllers.txt, and back (throws std::runtime_error for a malformed file)
std::string ControllersText(const std::vector<CaseController>& controllers);
std::vector<CaseController> ParseControllersText(const std::string& text);

struct CaseStatus {
  int exit_code = 0;
  double wall_s = 0.0;
  std::string message;  // a controller's failure (one line); empty: sim_node's stderr says
  int domain = -1;      // the DDS domain id it ran on (with controllers), else -1
};

// writes case_status.txt atomically (a temporary file renamed); throws std::runtime_error
void WriteCaseStatus(const std::string& case_dir, const CaseStatus& status);
// reads case_status.txt; nullopt if absent or unreadable (the case has not finished)
std::optional<CaseStatus> ReadCaseStatus(const std::string& case_dir);
// removes case_status.txt (before a rerun)
void ClearCaseStatus(const std::string& case_dir);

// A row of results.csv
struct SweepRow {
  std::string case_name;
  bool ok = false;
  int exit_code = 0;
  std::string message;  // failed: the last line of sim_node's stderr, or why results failed
  double wall_s = 0.0;
  std::vector<std::string> parameters;  // the case's values, YAML flow style
  std::vector<double> results;          // empty for a failed case
  std::vector<SettledCheck> settled;    // per result (SettledCheck::asked: it has settled:)
  // the names of the results asked to settle that did not (an ok case)
  std::vector<std::string> Unsettled(const SweepSpec& spec) const;
};

// The row of a finished case (nullopt if it has not finished, or sim_node was stopped by
// SIGINT / SIGTERM: exit 130 / 143): ok when sim_node exited 0 and every result could be
// computed from its files.
std::optional<SweepRow> CollectCase(const SweepSpec& spec, const SweepCase& c,
                                    const std::string& case_dir);

// the last non-empty line of `text` (lines end at \n or \r: sim_node's progress line uses \r)
std::string LastLine(const std::string& text);

}  // namespace towsim::app
