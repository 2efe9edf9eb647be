#pragma once
// The sweep's table DIR/results.csv and its summary (docs/sweeps.md "Results table"):
//   case,status,exit_code,message,wall_s,<parameter key paths...>,<result names...>,
//   <name>.settled for each result with settled: (1 or 0, empty for a failed case)
// one row per finished case in case order; status ok or failed; parameter values in YAML flow
// style; results "%.9g", empty for a failed case; wall_s "%.3f". Fields quoted as
// io::CsvField does. Rewritten whole (a temporary file renamed) after every finished case, so a
// killed sweep leaves a complete table of every case that finished.

#include <optional>
#include <string>
#include <vector>

#include "app/sweep/sweep_case.h"
#include "app/sweep/sweep_file.h"

namespace towsim::app {

// the header line of results.csv for `spec`
std::string ResultsHeader(const SweepSpec& spec);

// DIR/columns.json: what each column of results.csv is, for plotting scripts:
//   {"parameters": [{"name": P, "controllers_only": false}, ...],
//    "results": [{"name": R, "signal": S, "stat": T, "settled": {"window": W,
//                 "tolerance": X} or null, "settled_column": "R.settled" or null}, ...]}
std::string ColumnsJson(const SweepSpec& spec);

// writes `rows` (the finished ones; nullopt = not finished) to `path` atomically; throws
// std::runtime_error if it cannot be written
void WriteResultsTable(const std::string& path, const SweepSpec& spec,
                       const std::vector<std::optional<SweepRow>>& rows);

struct SweepTiming {
  double wall_s = 0.0;  // of this invocation [s]
  int workers = 1;      // local workers, or Slurm tasks at once (0: as Slurm schedules)
  bool slurm = false;
  int ran = 0;  // cases run by this invocation
};

// the summary: counts, the failed cases with their messages, the ok cases whose results did
// not settle (each with its change over the window and the tolerance), the range of each
// result over the ok cases with the cases where it is reached; lines end with '\n'
std::string SweepSummary(const SweepSpec& spec, const std::vector<SweepCase>& cases,
                         const std::vector<std::optional<SweepRow>>& rows,
                         const SweepTiming& timing);

}  // namespace towsim::app
