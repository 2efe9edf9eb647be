#include "app/common/run_stats.h"

#include <algorithm>
#include <cstdio>
#include <regex>

namespace towsim::app {

void RunStats::Add(const core::StepStatus& status, int coupling_iterations) {
  ++steps;
  coupling_sum += coupling_iterations;
  iterations_sum += status.iterations;
  iterations_max = std::max(iterations_max, status.iterations);
  if (status.substeps > 1) ++substepped_steps;
}

double RunStats::iterations_mean() const {
  return steps > 0 ? static_cast<double>(iterations_sum) / static_cast<double>(steps) : 0.0;
}

double RunStats::coupling_mean() const {
  return steps > 0 ? static_cast<double>(coupling_sum) / static_cast<double>(steps) : 0.0;
}

double RunStats::real_time_factor() const { return wall_time > 0.0 ? sim_time / wall_time : 0.0; }

std::string SummaryLine(const std::string& scene_name, const RunStats& stats) {
  const double rtf = stats.real_time_factor();
  char line[512];
  std::snprintf(line, sizeof line,
                "sim_node: %s: %ld steps, %.6g s simulated in %.3f s (RTF %.*f), "
                "Newton iterations mean %.2f max %d, substeps %ld",
                scene_name.c_str(), stats.steps, stats.sim_time, stats.wall_time,
                rtf < 10.0 ? 2 : 0, rtf, stats.iterations_mean(), stats.iterations_max,
                stats.substepped_steps);
  std::string text = line;
  if (stats.has_vehicles) {
    std::snprintf(line, sizeof line, ", coupling iterations mean %.2f", stats.coupling_mean());
    text += line;
  }
  return text;
}

std::optional<RunSummary> ParseSummaryLine(const std::string& text) {
  // the fixed part after "sim_node: <scene>: " (the scene name may hold anything)
  static const std::regex kLine(
      "([0-9]+) steps, ([^ ]+) s simulated in ([^ ]+) s \\(RTF ([^)]+)\\), Newton iterations "
      "mean ([^ ]+) max ([0-9]+), substeps ([0-9]+)(, coupling iterations mean ([^ ,\\n]+))?");
  std::optional<RunSummary> found;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), kLine);
       it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    RunSummary s;
    try {
      s.steps = std::stol(m[1]);
      s.sim_time = std::stod(m[2]);
      s.wall_time = std::stod(m[3]);
      s.real_time_factor = std::stod(m[4]);
      s.iterations_mean = std::stod(m[5]);
      s.iterations_max = std::stoi(m[6]);
      s.substepped_steps = std::stol(m[7]);
      if (m[9].matched) s.coupling_mean = std::stod(m[9]);
    } catch (const std::exception&) {
      continue;  // not numbers: not a summary line
    }
    found = s;
  }
  return found;
}

}  // namespace towsim::app
