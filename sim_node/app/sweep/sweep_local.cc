#include "app/sweep/sweep_local.h"

#include <chrono>
#include <memory>
#include <thread>

#include "app/common/stop_signal.h"
#include "app/sweep/sweep_case.h"

namespace towsim::app {
namespace {

using Clock = std::chrono::steady_clock;

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

struct Running {
  std::unique_ptr<CaseRun> run;
  size_t number = 0;  // index into the cases
};

}  // namespace

int RunLocal(const std::string& sim_node, const std::vector<LocalCase>& cases, int workers,
             const std::function<bool(size_t case_number)>& on_finished, SweepProgress* progress) {
  const Clock::time_point start = Clock::now();
  std::vector<Running> running;
  size_t next = 0;
  int done = 0, failed = 0;
  while (next < cases.size() || !running.empty()) {
    if (const int signal = StopRequested()) {
      // stop cleanly: SIGTERM to each of our processes, then wait for each
      for (Running& r : running) r.run->Stop();
      progress->Finish();
      return 128 + signal;
    }
    while (static_cast<int>(running.size()) < workers && next < cases.size()) {
      ClearCaseStatus(cases[next].dir);
      running.push_back({std::make_unique<CaseRun>(sim_node, cases[next]), next});
      ++next;
    }
    // the cases that ended
    for (size_t i = 0; i < running.size();) {
      if (!running[i].run->Poll()) {
        ++i;
        continue;
      }
      // a case stopped by SIGINT / SIGTERM (Ctrl-C reaches the whole process group; a DDS
      // node exits 0 then) has not finished: no status, so --resume runs it again
      if (StopRequested() != 0) break;
      const std::optional<CaseOutcome> outcome = running[i].run->outcome();
      const double wall = running[i].run->wall_s();
      const int domain = running[i].run->domain();
      const size_t number = running[i].number;
      running.erase(running.begin() + static_cast<long>(i));
      if (!outcome) continue;
      WriteCaseStatus(cases[number].dir, {outcome->exit_code, wall, outcome->message, domain});
      ++done;
      if (!on_finished(number)) ++failed;
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
