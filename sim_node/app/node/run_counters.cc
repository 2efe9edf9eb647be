#include "app/node/run_counters.h"

#include <algorithm>
#include <cstdio>

namespace towsim::app {

RunCounters& operator+=(RunCounters& a, const RunCounters& b) {
  a.steps += b.steps;
  a.sim_time += b.sim_time;
  a.overruns += b.overruns;
  a.received += b.received;
  a.rejected += b.rejected;
  a.clamped += b.clamped;
  a.failsafes += b.failsafes;
  a.lockstep_timeouts += b.lockstep_timeouts;
  a.unknown_commands += b.unknown_commands;
  a.resets += b.resets;
  a.poses_missing += b.poses_missing;
  a.external_vessels = std::max(a.external_vessels, b.external_vessels);
  return a;
}

std::string NodeSummaryLine(const std::string& scene, const std::string& mode, const RunCounters& c,
                            double wall, const std::string& strain,
                            const std::optional<std::string>& other_nodes,
                            const std::optional<SummaryLateness>& lateness) {
  // RTF = simulated time / wall time, 2 decimals below 10
  const double rtf = wall > 0.0 ? c.sim_time / wall : 0.0;
  char line[640];
  int n = std::snprintf(
      line, sizeof line,
      "sim_node: %s: %s, %ld steps, %.6g s simulated in %.3f s (RTF %.*f), overruns %llu, "
      "failsafes %llu, commands %llu (rejected %llu, clamped %llu), lockstep timeouts %llu, "
      "resets %d",
      scene.c_str(), mode.c_str(), c.steps, c.sim_time, wall, rtf < 10.0 ? 2 : 0, rtf,
      static_cast<unsigned long long>(c.overruns), static_cast<unsigned long long>(c.failsafes),
      static_cast<unsigned long long>(c.received + c.unknown_commands),
      static_cast<unsigned long long>(c.rejected + c.unknown_commands),
      static_cast<unsigned long long>(c.clamped),
      static_cast<unsigned long long>(c.lockstep_timeouts), c.resets);
  if (c.external_vessels > 0 && n > 0 && n < static_cast<int>(sizeof line)) {
    n += std::snprintf(line + n, sizeof line - n, ", vessel poses missing %llu",
                       static_cast<unsigned long long>(c.poses_missing));
  }
  if (!strain.empty() && n > 0 && n < static_cast<int>(sizeof line)) {
    n += std::snprintf(line + n, sizeof line - n, "%s", strain.c_str());
  }
  if (other_nodes && n > 0 && n < static_cast<int>(sizeof line)) {
    n += std::snprintf(line + n, sizeof line - n, ", other nodes in the namespace: %s",
                       other_nodes->c_str());
  }
  if (lateness && n > 0 && n < static_cast<int>(sizeof line)) {
    std::snprintf(line + n, sizeof line - n, ", lateness p50 %.0f us p99 %.0f us max %.0f us",
                  1e6 * lateness->p50, 1e6 * lateness->p99, 1e6 * lateness->max);
  }
  return line;
}

}  // namespace towsim::app
