#include "app/node/offline_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

#include "app/common/exit_codes.h"
#include "app/common/run_stats.h"
#include "app/common/stop_signal.h"
#include "app/node/progress.h"
#include "app/node/fold_watch.h"
#include "app/node/strain_watch.h"
#include "core/script.h"
#include "core/simulation.h"
#include "io/output_error.h"

namespace towsim::app {
namespace {

using Clock = std::chrono::steady_clock;

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

}  // namespace

int RunOffline(const core::Model& model, double duration, io::CsvWriter* csv) {
  std::optional<core::Simulation> sim;
  try {
    sim.emplace(model, [] { return StopRequested() != 0; });  // Ctrl-C in the static solve
  } catch (const core::StopRequestedError& e) {
    std::fprintf(stderr, "sim_node: %s\n", e.what());
    std::printf("%s\n", SummaryLine(model.name.empty() ? "scene" : model.name, RunStats{}).c_str());
    std::fflush(stdout);
    return 128 + StopRequested();
  } catch (const core::SolverError& e) {
    std::fprintf(stderr, "sim_node: solver failure while building the initial state: %s\n",
                 e.what());
    return kExitSolver;
  }

  if (!sim->initial_report().empty())
    std::fprintf(stderr, "sim_node: initial: static: %s\n", sim->initial_report().c_str());

  // steps and output stride: k = max(1, round(1 / (output_rate h)))
  const double h = model.time.step;
  const long steps = std::max(0L, std::lround(duration / h));
  const double output_rate = model.time.output_rate;
  const long stride = output_rate > 0.0
                          ? std::max(1L, std::lround(1.0 / (output_rate * h)))
                          : std::max(1L, steps);  // no rate: first and last state only

  RunStats stats;
  stats.has_vehicles = !model.vehicles.empty();
  core::ScriptRunner script(model);
  Progress progress(static_cast<double>(steps) * h);
  const double t_start = sim->time();
  double t_reached = t_start;  // time of the last completed step [s]
  const Clock::time_point start = Clock::now();

  core::StepStatus status;  // of the last completed step; default (0 iterations) at t = 0
  long wall_us = 0;         // wall time of the last completed step [us]
  StrainWatch strain;       // at the output times
  FoldWatch fold(h);        // every FoldWatch::kCheckInterval
  strain.Observe(*sim);
  long written = 0;  // last step written to CSV
  int exit_code = kExitOk;
  try {
    if (csv != nullptr) csv->Write(*sim, status, wall_us);
    for (long k = 1; k <= steps; ++k) {
      if (const int signal = StopRequested()) {
        exit_code = 128 + signal;
        break;
      }
      const double t_before = sim->time();
      // the script entries due at the state reached (t = 0 first) hold during this step
      script.Apply(&*sim);
      const Clock::time_point t0 = Clock::now();
      const core::StepStatus step_status = sim->Step();
      const Clock::time_point t1 = Clock::now();

      if (!step_status.ok()) {
        progress.Finish();
        std::fprintf(stderr, "sim_node: solver failure at t = %.9g s (step %ld): %s\n", t_before, k,
                     step_status.message.c_str());
        exit_code = kExitSolver;
        break;
      }
      status = step_status;
      wall_us =
          static_cast<long>(std::chrono::duration_cast<std::chrono::microseconds>(t1 - t0).count());
      stats.Add(status, sim->coupling_iterations());
      t_reached = sim->time();
      const FoldWatch::Event folded = fold.Observe(*sim, k);
      if (folded == FoldWatch::Event::kFolded) {
        progress.Finish();
        std::fprintf(stderr, "sim_node: %s\n", fold.Warning().c_str());
      } else if (folded == FoldWatch::Event::kFailed) {
        progress.Finish();
        std::fprintf(stderr, "sim_node: solver failure at t = %.9g s (step %ld): %s\n",
                     sim->time(), k, fold.Failure().c_str());
        exit_code = kExitSolver;
        break;
      }
      if (k % stride == 0 && strain.Observe(*sim)) {
        progress.Finish();
        std::fprintf(stderr, "sim_node: %s\n", strain.Warning().c_str());
      }
      if (csv != nullptr && k % stride == 0) {
        csv->Write(*sim, status, wall_us);
        written = k;
      }
      progress.Update(t_reached - t_start, Seconds(t1 - start));
    }

    // the last state reached, unless already written or not trustworthy (failed step)
    if (csv != nullptr && exit_code != kExitSolver && written != stats.steps) {
      csv->Write(*sim, status, wall_us);
    }
  } catch (const io::OutputError& e) {
    // the CSV holds every row set written before (docs/command_line.md "Exit codes": 1)
    progress.Finish();
    std::fprintf(stderr, "sim_node: error: --csv: %s\n", e.what());
    exit_code = kExitError;
  }
  progress.Finish();

  stats.sim_time = t_reached - t_start;
  stats.wall_time = Seconds(Clock::now() - start);
  const std::string name = model.name.empty() ? std::string("scene") : model.name;
  strain.Observe(*sim);
  std::printf("%s%s\n", SummaryLine(name, stats).c_str(), strain.SummaryPart().c_str());
  std::fflush(stdout);
  return exit_code;
}

}  // namespace towsim::app
