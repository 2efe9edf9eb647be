#include "app/sweep/sweep_case_run.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "app/common/text_file.h"
#include "app/sweep/sweep_case.h"

extern char** environ;

namespace towsim::app {
namespace {

double Seconds(CaseRun::Clock::duration d) { return std::chrono::duration<double>(d).count(); }

int ExitCode(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

std::string CodeText(int code) {
  return code > 128 ? "ended by signal " + std::to_string(code - 128)
                    : "exited with code " + std::to_string(code);
}

// starts `argv_text` (argv[0] the program) with stdin /dev/null, stdout and stderr to files,
// SIGINT and SIGTERM at their defaults, and `extra_env` ("NAME=value") over the environment
pid_t Spawn(const std::vector<std::string>& argv_text, const std::string& out,
            const std::string& err, const std::vector<std::string>& extra_env) {
  std::vector<std::string> copy = argv_text;
  std::vector<char*> argv;
  for (std::string& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env_text;
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string entry = *e;
    bool replaced = false;
    for (const std::string& x : extra_env) {
      replaced = replaced || entry.compare(0, x.find('=') + 1, x, 0, x.find('=') + 1) == 0;
    }
    if (!replaced) env_text.push_back(entry);
  }
  env_text.insert(env_text.end(), extra_env.begin(), extra_env.end());
  std::vector<char*> envp;
  for (std::string& e : env_text) envp.push_back(e.data());
  envp.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF);
  pid_t pid = -1;
  const int error = posix_spawn(&pid, argv[0], &actions, &attr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  if (error != 0) {
    throw std::runtime_error("cannot start " + argv_text[0] + ": " + std::strerror(error));
  }
  return pid;
}

}  // namespace

void CaseJudge::NodeEnded(int code) {
  node_ended_ = true;
  node_code_ = code;
  if (!failure_ && code != 0) failure_ = CaseOutcome{code, ""};
}

void CaseJudge::ControllerEnded(size_t i, int code, const std::string& last_error_line) {
  if (failure_ || code == 0) return;
  std::string message = "controller " + names_.at(i) + " " + CodeText(code);
  if (!last_error_line.empty()) message += ": " + last_error_line;
  failure_ = CaseOutcome{code, message};
}

CaseOutcome CaseJudge::Outcome() const {
  if (failure_) return *failure_;
  return CaseOutcome{node_code_, ""};
}

CaseRun::CaseRun(const std::string& sim_node, const LocalCase& c) {
  start_ = end_ = Clock::now();
  grace_ = c.grace;
  std::vector<std::string> names;
  for (const CaseController& k : c.controllers) names.push_back(k.name);
  judge_ = CaseJudge(names);
  std::vector<std::string> node_argv = {sim_node};
  node_argv.insert(node_argv.end(), c.arguments.begin(), c.arguments.end());
  std::vector<std::string> env;
  if (!c.controllers.empty()) {
    lock_ = wire::DomainLock::Take(c.domain_first, c.domain_last);
    if (!lock_) {
      immediate_ = CaseOutcome{1, "no free DDS domain id in " + std::to_string(c.domain_first) +
                                      "-" + std::to_string(c.domain_last) +
                                      ": other sweeps or tests hold them all (" +
                                      wire::DomainLock::LockPath(c.domain_first) + ", ...)"};
      done_ = true;
      return;
    }
    const std::string domain = std::to_string(lock_->id());
    node_argv.insert(node_argv.end(), {"--domain", domain});
    env.push_back("ROS_DOMAIN_ID=" + domain);
    // the controllers first: they wait for the node's scene_info
    for (const CaseController& k : c.controllers) {
      std::vector<std::string> argv = {k.program};
      const std::vector<std::string> args = WithDomain(k.args, lock_->id());
      argv.insert(argv.end(), args.begin(), args.end());
      Child child;
      child.err_file = c.dir + "/" + k.name + ".err";
      child.pid = Spawn(argv, c.dir + "/" + k.name + ".out", child.err_file, env);
      child.running = true;
      controllers_.push_back(child);
    }
  }
  node_.err_file = c.dir + "/sim_node.err";
  try {
    node_.pid = Spawn(node_argv, c.dir + "/sim_node.out", node_.err_file, env);
  } catch (...) {
    Stop();
    throw;
  }
  node_.running = true;
}

CaseRun::~CaseRun() {
  // never leave a process behind
  if (!done_ && (node_.running || !controllers_.empty())) Stop();
}

void CaseRun::Signal(Child& child, int signal) {
  if (!child.running) return;
  kill(child.pid, signal);
  if (!child.signalled) child.term_at = Clock::now();
  child.signalled = true;
}

bool CaseRun::Poll() {
  if (done_) return true;
  const Clock::time_point now = Clock::now();
  auto reap = [&](Child& child) {
    if (!child.running) return false;
    int status = 0;
    if (waitpid(child.pid, &status, WNOHANG) != child.pid) return false;
    child.running = false;
    child.code = ExitCode(status);
    end_ = Clock::now();
    return true;
  };
  for (size_t i = 0; i < controllers_.size(); ++i) {
    Child& k = controllers_[i];
    if (reap(k) && !k.signalled) {
      judge_.ControllerEnded(i, k.code, LastLine(ReadTextFile(k.err_file)));
    }
  }
  if (reap(node_)) {
    node_end_ = now;
    // sim_node stopped by SIGINT / SIGTERM from outside (offline: exit 130 / 143)
    if (node_.code == 130 || node_.code == 143) {
      interrupted_ = true;
    } else if (!node_.signalled) {
      judge_.NodeEnded(node_.code);
    }
  }
  // a controller failed: stop the rest
  if (judge_.failed() && !stopped_) {
    Signal(node_, SIGTERM);
    for (Child& k : controllers_) Signal(k, SIGTERM);
  }
  // the node has ended: the controllers' grace, then SIGTERM, then SIGKILL
  if (!node_.running) {
    for (Child& k : controllers_) {
      if (!k.signalled && Seconds(now - node_end_) > grace_) Signal(k, SIGTERM);
    }
  }
  for (Child* c : [&] {
         std::vector<Child*> all = {&node_};
         for (Child& k : controllers_) all.push_back(&k);
         return all;
       }()) {
    if (c->running && c->signalled && Seconds(now - c->term_at) > grace_) {
      kill(c->pid, SIGKILL);
    }
  }
  bool any = node_.running;
  for (const Child& k : controllers_) any = any || k.running;
  done_ = !any;
  return done_;
}

void CaseRun::Stop() {
  stopped_ = true;
  Signal(node_, SIGTERM);
  for (Child& k : controllers_) Signal(k, SIGTERM);
  while (!Poll()) usleep(10000);
}

std::optional<CaseOutcome> CaseRun::outcome() const {
  if (immediate_) return immediate_;
  if (stopped_) return std::nullopt;
  if (judge_.failed()) return judge_.Outcome();
  if (interrupted_ || !judge_.node_ended()) return std::nullopt;
  return judge_.Outcome();
}

double CaseRun::wall_s() const { return Seconds(end_ - start_); }

}  // namespace towsim::app
