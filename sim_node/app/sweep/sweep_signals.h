#pragma once
// The results of a sweep case (docs/sweeps.md "Results"): a statistic of a named signal,
// computed from the case's CSV files (the columns of io/csv_writer.h) and from sim_node's
// summary line (run_stats.h). Signals:
//   <body>.x y z roll pitch yaw u v w p q r   bodies.csv (world NED [m], rad, body frame)
//   <body>.depth                              z (NED: down is positive) [m]
//   <body>.speed                              |(u, v, w)| [m/s]
//   <body>.track_error                        signed cross-track distance [m] from the line
//                                             through the body's t = 0 position along its
//                                             t = 0 heading (positive to starboard)
//   <body>.fx fy fz mx my mz                  forces.csv: the cable's force and moment on it
//   <body>.cable_force                        |(fx, fy, fz)| [N]
//   [<cable>.]layback                         horizontal distance from the tow point (cable
//                                             node 0) to the towed end (the last node) [m]
//   [<cable>.]top_tension, end_tension,       axial force at node 0, at the last node, the
//             max_tension                     largest over the nodes [N] (cable.csv; with a
//                                             qualifier <cable>.csv of that cable of a
//                                             network, main.top_tension; without one the
//                                             scene's first or only cable)
//   newton_iterations, residual, step_wall_us status.csv (the steps at the output times)
// Statistics over the output rows in the window [from, to]: final, initial, min, max,
// max_abs, mean, rms, std (population). `settled` (SweepSettled): over the rows of that window
// with t >= t_last - window, change = max - min; settled when change < tolerance and the rows
// span the window (t_last - t_first >= window: a shorter run has not shown it settled). Run totals,
// from the summary line (no statistic):
//   steps, rtf, run_wall_s (the stepping loop), newton_iterations_mean, newton_iterations_max,
//   substeps, coupling_iterations_mean.

#include <string>
#include <vector>

#include "app/sweep/sweep_file.h"

namespace towsim::app {

// Checks every result's signal and statistic against the scene's body and cable names (the
// one cable of a `cable:` scene is "cable"); a time signal without a statistic takes `final`;
// sets each cable signal's SweepResult::cable. Throws scene::ConfigError (key
// results.<name>.signal, the result's location, the rule with the allowed names).
void CheckSweepResults(std::vector<SweepResult>* results,
                       const std::vector<std::string>& body_names,
                       const std::vector<std::string>& cable_names = {"cable"});

// the settled check of one result
struct SettledCheck {
  bool asked = false;    // the result has `settled`
  bool settled = false;  // change < tolerance over a window the rows span
  double change = 0.0;   // max - min over the final window [the signal's unit]
  double span = 0.0;     // t_last - t_first of the result's rows [s]
};

// the check of `settled` on the (t, value) rows of a result's window, in time order (at
// least one); throws std::runtime_error if the final window holds fewer than 2 rows
SettledCheck CheckSettled(const std::vector<std::pair<double, double>>& rows,
                          const SweepSettled& settled);

// The value of each result for the case whose CSV files are in `case_dir`; `sim_node_stdout`
// holds its summary line; `settled` (if not null) gets each result's settled check. Throws
// std::runtime_error naming the file, or the result and window with no rows.
std::vector<double> ComputeSweepResults(const std::vector<SweepResult>& results,
                                        const std::string& case_dir,
                                        const std::string& sim_node_stdout,
                                        std::vector<SettledCheck>* settled = nullptr);

}  // namespace towsim::app
