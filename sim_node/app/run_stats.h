#pragma once
// Statistics of a run and the one-line summary printed at its end:
//
//   sim_node: <scene>: <steps> steps, <sim s> s simulated in <wall s> s (RTF <x>),
//             Newton iterations mean <m> max <M>, substeps <n>
//
// (one line). Newton iterations are per step, summed over its substeps (StepStatus);
// substeps counts the steps that had to be sub-stepped (StepStatus::substeps > 1).

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

  // accounts for one completed step
  void Add(const core::StepStatus& status);
  double iterations_mean() const;
  double real_time_factor() const;  // sim_time / wall_time; 0 if no wall time elapsed
};

// the summary line, without the trailing newline
std::string SummaryLine(const std::string& scene_name, const RunStats& stats);

}  // namespace towsim::app
