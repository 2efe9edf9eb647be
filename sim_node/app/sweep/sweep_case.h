#pragma once
// One case of a sweep on disk (docs/sweeps.md "Files"): its folder DIR/<case>/ holds
//   command.sh        runs the case by hand or as a Slurm task: sim_node offline with the
//                     case's --set values and --csv into the folder, then writes case_status.txt
//   case_args.txt     the sim_node arguments, one a line (compared by --resume)
//   sim_node.out/.err sim_node's stdout (the summary line) and stderr
//   bodies.csv cable.csv forces.csv status.csv   the CSV files of --csv
//   case_status.txt   "exit_code=N" and "wall_s=S", written (atomically) when the run ended
// A case without case_status.txt has not run (or was stopped); with it, it is finished.

#include <optional>
#include <string>
#include <vector>

#include "app/sweep/sweep_combinator.h"
#include "app/sweep/sweep_file.h"

namespace towsim::app {

// the sim_node arguments of a case (without the program): --scene, --mode offline,
// --fail-on-failsafe, [--duration], --set per parameter, --csv `case_dir`; paths absolute.
// Offline has no failsafe, so --fail-on-failsafe changes nothing today; it is passed so that a
// case that ever runs with DDS controllers fails loudly (exit 5: a failed case) rather than
// going on uncontrolled (docs/sweeps.md)
std::vector<std::string> CaseArguments(const SweepSpec& spec, const SweepCase& c,
                                       const std::string& case_dir);

// `s` as one shell word: single-quoted, a ' inside written '\''
std::string ShellWord(const std::string& s);

// Creates the folder and writes command.sh (running `sim_node`) and case_args.txt.
// Throws std::runtime_error if they cannot be written.
void PrepareCase(const std::string& case_dir, const std::string& sim_node,
                 const std::vector<std::string>& arguments);

// true if the folder's case_args.txt holds exactly `arguments` (the case is the same)
bool SameArguments(const std::string& case_dir, const std::vector<std::string>& arguments);

struct CaseStatus {
  int exit_code = 0;
  double wall_s = 0.0;
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
};

// The row of a finished case (nullopt if it has not finished, or sim_node was stopped by
// SIGINT / SIGTERM: exit 130 / 143): ok when sim_node exited 0 and every result could be
// computed from its files.
std::optional<SweepRow> CollectCase(const SweepSpec& spec, const SweepCase& c,
                                    const std::string& case_dir);

// the last non-empty line of `text` (lines end at \n or \r: sim_node's progress line uses \r)
std::string LastLine(const std::string& text);

}  // namespace towsim::app
