#pragma once
// One running case of a sweep: sim_node alone (offline), or sim_node in lockstep beside the
// sweep's controllers on a DDS domain of the case's own (docs/sweeps.md "Controllers").
//
// How a case with controllers ends (CaseJudge, the policy, without processes):
//   - the first failure wins: a controller that ends by itself with a code other than 0
//     (during the run, or after it), or sim_node ending with a code other than 0 (its stderr
//     says why: exit 5 for a failsafe or a lockstep timeout, --fail-on-failsafe);
//   - a controller's failure stops the others and the node (SIGTERM): the case has failed;
//   - when the node has ended, the controllers are given kControllerGrace to end by
//     themselves (every towsim controller does, at the end of the node's run); then SIGTERM,
//     and SIGKILL after as long again; what they exit with after that is not judged;
//   - a controller that ends with 0 while the node runs is no failure by itself (the node,
//     missing its commands, fails on its own with exit 5).
// A case stopped by the sweep (SIGINT / SIGTERM) has not finished: it has no outcome.

#include <sys/types.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "app/sweep/sweep_controllers.h"
#include "wire/domain_lock.h"

namespace towsim::app {

inline constexpr double kControllerGrace = 5.0;  // [s] wall, after the node ended

struct CaseOutcome {
  int exit_code = 0;    // sim_node's, or that of the controller that failed first
  std::string message;  // the controller's failure; empty: sim_node's stderr says why
};

class CaseJudge {
 public:
  explicit CaseJudge(std::vector<std::string> controller_names)
      : names_(std::move(controller_names)) {}
  // sim_node ended with `code` (128 + signal for a signal)
  void NodeEnded(int code);
  // controller i ended by itself with `code`; `last_error_line` its stderr's last line
  void ControllerEnded(size_t i, int code, const std::string& last_error_line);
  bool failed() const { return failure_.has_value(); }
  bool node_ended() const { return node_ended_; }
  // once the node has ended: the case's outcome
  CaseOutcome Outcome() const;

 private:
  std::vector<std::string> names_;
  std::optional<CaseOutcome> failure_;
  bool node_ended_ = false;
  int node_code_ = 0;
};

// a case to run: sim_node's arguments (without --domain), the controllers (none: offline)
struct LocalCase {
  std::string dir;                     // the case's folder
  std::vector<std::string> arguments;  // sim_node's arguments
  std::vector<CaseController> controllers;
  int domain_first = kDefaultSweepDomain;  // with controllers: the ids it may take
  int domain_last = kMaxSweepDomain;
  double grace = kControllerGrace;  // [s] for the controllers after the node ended
};

class CaseRun {
 public:
  using Clock = std::chrono::steady_clock;
  // starts the case's processes (stdout / stderr to <dir>/sim_node.out, .err and
  // <dir>/<controller>.out, .err); throws std::runtime_error if one cannot be started. With
  // controllers and no free domain id the case ends at once, failed, saying so.
  CaseRun(const std::string& sim_node, const LocalCase& c);
  CaseRun(const CaseRun&) = delete;
  CaseRun& operator=(const CaseRun&) = delete;
  ~CaseRun();

  // reaps what ended and applies the rules above; true once every process has ended
  bool Poll();
  // the sweep stops: SIGTERM to every process still running, then waits for them all
  void Stop();
  // once Poll() returned true: the outcome; nullopt if stopped (by the sweep, or sim_node by
  // SIGINT / SIGTERM: exit 130 / 143)
  std::optional<CaseOutcome> outcome() const;
  double wall_s() const;  // from the start to the end of the last process [s]
  int domain() const { return lock_ ? lock_->id() : -1; }

 private:
  struct Child {
    pid_t pid = -1;
    std::string err_file;
    bool running = false;
    bool signalled = false;  // we sent SIGTERM
    Clock::time_point term_at;
    int code = 0;
  };
  void Signal(Child& child, int signal);

  std::optional<wire::DomainLock> lock_;
  Child node_;
  std::vector<Child> controllers_;
  CaseJudge judge_{{}};
  Clock::time_point start_, end_, node_end_;
  bool stopped_ = false;      // by the sweep (Stop)
  bool interrupted_ = false;  // sim_node ended by SIGINT / SIGTERM from outside
  bool done_ = false;
  std::optional<CaseOutcome> immediate_;  // ended before it started (no domain)
  double grace_ = kControllerGrace;
};

}  // namespace towsim::app
