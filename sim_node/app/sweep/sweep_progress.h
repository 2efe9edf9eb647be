#pragma once
// The progress line of towsim_sweep on stderr:
//
//   [towsim_sweep] 12/40 cases done, 1 failed, 2 running, about 1m05s left
//
// redrawn in place ('\r') at most 4 times a second; Finish() ends it with a newline. The time
// left is the cases still to run times the wall time per finished case of this invocation
// (which already counts the workers running side by side); "--" before the first case ends.

#include <cstdio>

namespace towsim::app {

class SweepProgress {
 public:
  static constexpr double kMinInterval = 0.25;  // between redraws [s]

  // `total`: cases of the sweep; `already`: finished before this invocation (--resume)
  SweepProgress(int total, int already, std::FILE* out = stderr)
      : total_(total), already_(already), out_(out) {}
  // Finish(): an error that ends the sweep (a full disk) then starts on its own line
  ~SweepProgress() { Finish(); }
  SweepProgress(const SweepProgress&) = delete;
  SweepProgress& operator=(const SweepProgress&) = delete;

  // done and failed: finished by this invocation (failed among them); wall: since its start [s]
  void Update(int done, int failed, int running, double wall, bool force = false);
  void Finish();

 private:
  int total_, already_;
  std::FILE* out_;
  double last_draw_ = -1.0;
  bool drawn_ = false;
};

}  // namespace towsim::app
