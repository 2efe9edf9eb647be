#pragma once
// Statistics of a run and the one-line summary printed at its end:
//
//   sim_node: <scene>: <steps> steps, <sim s> s simulated in <wall s> s (RTF <x>),
//             Newton iterations mean <m> max <M>, substeps <n>[, coupling iterations mean <c>]
//
// (one line). Newton iterations are per step, summed over its substeps (StepStatus);
// substeps counts the steps that had to be sub-stepped (StepStatus::substeps > 1). The
// coupling iterations (vehicle-cable joint-force iterations per step,
// Simulation::coupling_iterations) are shown when the scene has vehicles.

#include <optional>
#include <string>

#include "core/simulation.h"

namespace towsim::app {

struct RunStats {
  long steps = 0;             // completed steps
  double sim_time = 0.0;      // simulated time covered [s]
  double wall_time = 0.0;     // wall time of the stepping loop, output included [s]
  long iterations_sum = 0;    // Newton iterations over all completed steps
  int iterations_max = 0;     // most Newton iterations in one step
  long substepped_steps = 0;  // steps with StepStatus::substeps > 1
  bool has_vehicles = false;  // show the coupling iterations
  long coupling_sum = 0;      // vehicle-cable coupling iterations over all completed steps

  // accounts for one completed step and its coupling iterations
  void Add(const core::StepStatus& status, int coupling_iterations = 0);
  double iterations_mean() const;
  double coupling_mean() const;
  double real_time_factor() const;  // sim_time / wall_time; 0 if no wall time elapsed
};

// the summary line, without the trailing newline
std::string SummaryLine(const std::string& scene_name, const RunStats& stats);

// The numbers of a summary line, read back (towsim_sweep reads each case's stdout)
struct RunSummary {
  long steps = 0;
  double sim_time = 0.0;   // [s]
  double wall_time = 0.0;  // [s], 3 decimals as printed
  double real_time_factor = 0.0;
  double iterations_mean = 0.0;  // Newton iterations per step
  int iterations_max = 0;
  long substepped_steps = 0;
  std::optional<double> coupling_mean;  // scenes with vehicles
};

// the summary line in `text` (the last one if several); nullopt if there is none
std::optional<RunSummary> ParseSummaryLine(const std::string& text);

}  // namespace towsim::app
