#pragma once
// The Slurm runner of towsim_sweep (--slurm; docs/sweeps.md "On a Slurm cluster"): the cases
// to run become one job array, task i = case i. Files under DIR/slurm/:
//   cases.txt     the folder of case i on line i + 1 (every case of the sweep)
//   sweep.sbatch  the batch script: task i runs DIR/<case i>/command.sh (sweep_case.h)
//   task_<i>.out  Slurm's output of task i
//   job_id        the job id sbatch returned
// Submitted with `sbatch --parsable --array=<indices>[%<workers>] sweep.sbatch`; SBATCH_*
// environment variables (partition, time limit, account) apply as sbatch reads them. The
// runner then waits: every 0.5 s it looks for case_status.txt files (each finished case
// calls `on_finished`) and asks `squeue -h -j <job>` whether tasks remain. SIGINT / SIGTERM
// cancel the job (`scancel <job>`). DIR must be on a file system every node sees.

#include <functional>
#include <string>
#include <vector>

#include "app/sweep/sweep_progress.h"

namespace towsim::app {

struct SlurmRun {
  std::string out_dir;                 // DIR
  std::vector<std::string> case_dirs;  // of every case, by case index
  std::vector<size_t> todo;            // case indices to run, ascending
  int max_parallel = 0;                // tasks at once (%N); 0: as Slurm schedules
  bool wait = true;                    // false: submit and return
};

// "0-3,5,7-9" from ascending indices
std::string ArrayIndices(const std::vector<size_t>& indices);

// Submits (and unless !wait, waits for) the job array. Returns 0 when every task ended (or
// when submitted with !wait), 128 + signal when stopped (the job cancelled), 1 when sbatch
// failed (its message on stderr).
int RunOnSlurm(const SlurmRun& run, const std::function<bool(size_t case_index)>& on_finished,
               SweepProgress* progress);

}  // namespace towsim::app
