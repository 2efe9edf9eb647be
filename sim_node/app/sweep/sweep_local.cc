#include "app/sweep/sweep_local.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "app/common/stop_signal.h"
#include "app/sweep/sweep_case.h"

extern char** environ;

namespace towsim::app {
namespace {

using Clock = std::chrono::steady_clock;

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

struct Running {
  pid_t pid = -1;
  size_t number = 0;  // index into the cases
  Clock::time_point start;
};

pid_t Spawn(const std::string& sim_node, const LocalCase& c) {
  std::vector<std::string> argv_text = {sim_node};
  argv_text.insert(argv_text.end(), c.arguments.begin(), c.arguments.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string out = c.dir + "/sim_node.out", err = c.dir + "/sim_node.err";

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  // the child starts with default SIGINT / SIGTERM handling
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF);
  pid_t pid = -1;
  const int error = posix_spawn(&pid, sim_node.c_str(), &actions, &attr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  if (error != 0) {
    throw std::runtime_error("cannot start " + sim_node + ": " + std::strerror(error));
  }
  return pid;
}

int ExitCode(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

}  // namespace

int RunLocal(const std::string& sim_node, const std::vector<LocalCase>& cases, int workers,
             const std::function<bool(size_t case_number)>& on_finished, SweepProgress* progress) {
  const Clock::time_point start = Clock::now();
  std::vector<Running> running;
  size_t next = 0;
  int done = 0, failed = 0;
  while (next < cases.size() || !running.empty()) {
    if (const int signal = StopRequested()) {
      // stop cleanly: SIGTERM to each of our sim_node processes, then wait for each
      for (const Running& r : running) kill(r.pid, SIGTERM);
      for (const Running& r : running) {
        int status = 0;
        while (waitpid(r.pid, &status, 0) < 0 && errno == EINTR) {
        }
      }
      progress->Finish();
      return 128 + signal;
    }
    while (static_cast<int>(running.size()) < workers && next < cases.size()) {
      ClearCaseStatus(cases[next].dir);
      running.push_back({Spawn(sim_node, cases[next]), next, Clock::now()});
      ++next;
    }
    // reap the processes that ended
    for (size_t i = 0; i < running.size();) {
      int status = 0;
      const pid_t pid = waitpid(running[i].pid, &status, WNOHANG);
      if (pid != running[i].pid) {
        ++i;
        continue;
      }
      const int code = ExitCode(status);
      const Running r = running[i];
      running.erase(running.begin() + static_cast<long>(i));
      // a case stopped by SIGINT / SIGTERM (Ctrl-C reaches the whole process group) has not
      // finished: no status, so --resume runs it again
      if (code == 130 || code == 143) continue;
      WriteCaseStatus(cases[r.number].dir, {code, Seconds(Clock::now() - r.start)});
      ++done;
      if (!on_finished(r.number)) ++failed;
      progress->Update(done, failed, static_cast<int>(running.size()),
                       Seconds(Clock::now() - start), true);
    }
    progress->Update(done, failed, static_cast<int>(running.size()), Seconds(Clock::now() - start));
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  progress->Finish();
  return 0;
}

}  // namespace towsim::app
