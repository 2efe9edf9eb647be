#include "app/sweep/sweep_slurm.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "app/common/stop_signal.h"
#include "app/common/text_file.h"
#include "app/sweep/sweep_case.h"

extern char** environ;

namespace towsim::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

struct CommandResult {
  int exit_code = -1;  // 127: could not be started
  std::string out, err;
};

// runs `argv` (found on the PATH), stdout and stderr to files under `dir`, and waits
CommandResult RunCommand(const std::vector<std::string>& argv_text, const std::string& dir) {
  const std::string out = dir + "/." + argv_text[0] + ".out";
  const std::string err = dir + "/." + argv_text[0] + ".err";
  std::vector<std::string> copy = argv_text;
  std::vector<char*> argv;
  for (std::string& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  const int error = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  CommandResult result;
  if (error != 0) {
    result.exit_code = 127;
    result.err =
        argv_text[0] + ": " + std::strerror(error) + " (is Slurm installed and on the PATH?)";
    return result;
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.out = ReadTextFile(out);
  result.err = ReadTextFile(err);
  return result;
}

std::string Trimmed(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
  return s;
}

}  // namespace

std::string ArrayIndices(const std::vector<size_t>& indices) {
  std::string text;
  for (size_t i = 0; i < indices.size();) {
    size_t j = i;
    while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1) ++j;
    if (!text.empty()) text += ",";
    text += std::to_string(indices[i]);
    if (j > i) text += "-" + std::to_string(indices[j]);
    i = j + 1;
  }
  return text;
}

int RunOnSlurm(const SlurmRun& run, const std::function<bool(size_t case_index)>& on_finished,
               SweepProgress* progress) {
  const fs::path slurm_dir = fs::absolute(fs::path(run.out_dir) / "slurm").lexically_normal();
  fs::create_directories(slurm_dir);
  std::string cases;
  for (const std::string& dir : run.case_dirs) {
    cases += fs::absolute(dir).lexically_normal().string() + "\n";
  }
  WriteTextFileAtomically((slurm_dir / "cases.txt").string(), cases);
  const std::string cases_txt = ShellWord((slurm_dir / "cases.txt").string());
  WriteTextFileAtomically(
      (slurm_dir / "sweep.sbatch").string(),
      "#!/bin/bash\n"
      "#SBATCH --job-name=towsim_sweep\n"
      "#SBATCH --output=" +
          (slurm_dir / "task_%a.out").string() +
          "\n"
          "#SBATCH --ntasks=1\n"
          "#SBATCH --cpus-per-task=1\n"
          "# one array task = one case of a towsim sweep (docs/sweeps.md): task i runs the\n"
          "# command.sh of case i, whose folder is line i + 1 of cases.txt\n"
          "case_dir=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" " +
          cases_txt +
          ")\n"
          "exec bash \"$case_dir/command.sh\"\n");
  for (size_t i : run.todo) ClearCaseStatus(run.case_dirs[i]);

  std::string array = ArrayIndices(run.todo);
  if (run.max_parallel > 0) array += "%" + std::to_string(run.max_parallel);
  const CommandResult submitted = RunCommand(
      {"sbatch", "--parsable", "--array=" + array, (slurm_dir / "sweep.sbatch").string()},
      slurm_dir.string());
  if (submitted.exit_code != 0) {
    std::fprintf(stderr, "towsim_sweep: error: sbatch failed (exit %d): %s\n", submitted.exit_code,
                 Trimmed(submitted.err).c_str());
    return 1;
  }
  // --parsable: "<job id>[;<cluster>]"
  std::string job = Trimmed(submitted.out);
  job = job.substr(0, job.find(';'));
  WriteTextFileAtomically((slurm_dir / "job_id").string(), job + "\n");
  std::fprintf(stderr, "towsim_sweep: submitted Slurm job %s, array %s (%zu cases)\n", job.c_str(),
               array.c_str(), run.todo.size());
  if (!run.wait) return 0;

  const Clock::time_point start = Clock::now();
  std::vector<bool> seen(run.case_dirs.size(), false);
  int done = 0, failed = 0;
  bool cancelled = false;
  int stop_signal = 0;
  int squeue_failures = 0;
  while (true) {
    if (const int signal = StopRequested(); signal != 0 && !cancelled) {
      RunCommand({"scancel", job}, slurm_dir.string());
      cancelled = true;
      stop_signal = signal;
    }
    // the job's tasks still known to squeue: one state per line (R, PD, CG, ...)
    const CommandResult queue =
        RunCommand({"squeue", "-h", "-j", job, "-o", "%t"}, slurm_dir.string());
    int running = 0;
    std::stringstream states(queue.out);
    std::string state;
    bool any = false;
    while (states >> state) {
      any = true;
      if (state == "R" || state == "CG") ++running;
    }
    // a finished job leaves squeue (or squeue no longer knows its id); other squeue
    // failures (slurmctld restarting) are retried for a minute
    bool over = queue.exit_code == 0 && !any;
    if (queue.exit_code != 0) {
      if (queue.err.find("Invalid job id") != std::string::npos) {
        over = true;
      } else if (++squeue_failures > 120) {
        progress->Finish();
        std::fprintf(stderr, "towsim_sweep: error: squeue fails (exit %d): %s\n", queue.exit_code,
                     Trimmed(queue.err).c_str());
        return 1;
      }
    } else {
      squeue_failures = 0;
    }
    for (size_t i : run.todo) {
      if (seen[i] || !ReadCaseStatus(run.case_dirs[i])) continue;
      seen[i] = true;
      ++done;
      if (!on_finished(i)) ++failed;
    }
    progress->Update(done, failed, running, Seconds(Clock::now() - start), true);
    if (over) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
  }
  progress->Finish();
  for (size_t i : run.todo) {
    if (!seen[i] && !cancelled) {
      std::fprintf(stderr,
                   "towsim_sweep: warning: case %zu: its Slurm task ended without a result "
                   "(see %s/task_%zu.out); --resume runs it again\n",
                   i, slurm_dir.c_str(), i);
    }
  }
  return cancelled ? 128 + stop_signal : 0;
}

}  // namespace towsim::app
