#pragma once
// What the DDS node counts over its run, and the summary line that reports it
// (app/node/dds_node.h, docs/app_layer.md). A RESET starts a new run of the same process: the
// node adds the run that ends to what it counted before (operator+=), so the summary covers the
// whole process. The line, on stdout at the end:
//
//   sim_node: <scene>: <mode>, <steps> steps, <sim s> s simulated in <wall s> s (RTF <x>),
//   overruns <n>, failsafes <n>, commands <n> (rejected <n>, clamped <n>), lockstep timeouts
//   <n>, resets <n>[, vessel poses missing <n>][, max cable strain ...][, other nodes in the
//   namespace: <names>]
//   [, lateness p50 <us> us p99 <us> us max <us> us]
//
// (one line; at most 639 characters, the rest cut off).

#include <cstdint>
#include <optional>
#include <string>

namespace towsim::app {

struct RunCounters {
  long steps = 0;                  // completed steps
  double sim_time = 0.0;           // simulated time covered [s]
  uint64_t overruns = 0;           // realtime: steps that started after their deadline
  uint64_t received = 0;           // commands the arbiter received, valid or not
  uint64_t rejected = 0;           // of those, rejected (non-finite)
  uint64_t clamped = 0;            // of those, clamped to the actuator's range
  uint64_t failsafes = 0;          // times a command entry went to failsafe
  uint64_t lockstep_timeouts = 0;  // lockstep waits that ended by timeout
  // commands on the topic of no commandable body, and on the winch's under --winch script:
  // received and rejected
  uint64_t unknown_commands = 0;
  int resets = 0;  // SimControl RESETs
  // steps an external vessel took without a pose for their end (docs/vessels.md "External
  // vessels"); in the line when the scene has external vessels
  uint64_t poses_missing = 0;
  int external_vessels = 0;  // of the scene (not summed)
};

// fieldwise sum: `a` then covers the runs of both
RunCounters& operator+=(RunCounters& a, const RunCounters& b);

// realtime pacing: the lateness of the steps' starts behind their deadlines [s]
struct SummaryLateness {
  double p50 = 0.0, p99 = 0.0, max = 0.0;
};

// the summary line (above), without the newline. `strain`: StrainWatch::SummaryPart(), ""
// unless extreme; `other_nodes`: the names of other nodes seen in the namespace, if any;
// `lateness`: realtime with paced steps only.
std::string NodeSummaryLine(const std::string& scene, const std::string& mode,
                            const RunCounters& totals, double wall, const std::string& strain,
                            const std::optional<std::string>& other_nodes,
                            const std::optional<SummaryLateness>& lateness);

}  // namespace towsim::app
