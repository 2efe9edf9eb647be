#pragma once
// Folded cable elements during a run (docs/faults.md "Folded cable"): every kCheckInterval of
// simulated time the runner asks the core for a folded element (core/fold_check.h: a slope
// turned against its chord, a strain far outside any cable material). The first one is
// reported on stderr with the element, the time and the strain; a cable still folded
// kPersistence later (at every check in between) cannot be trusted to recover: the run fails
// with exit 3 (app/common/exit_codes.h) instead of continuing with a spurious shape. A fold
// that opens again within kPersistence (a violent transient) only leaves its warning.

#include <string>

#include "core/simulation.h"

namespace towsim::app {

class FoldWatch {
 public:
  static constexpr double kCheckInterval = 0.1;  // [s] of simulated time
  static constexpr double kPersistence = 1.0;    // [s] folded at every check: the run fails

  enum class Event { kNone, kFolded, kFailed };

  // time step h [s]: the checks fall every round(kCheckInterval / h) steps
  explicit FoldWatch(double h);
  // after step `step` (1, 2, ...): kFolded when a fold is first seen (Warning()), kFailed when
  // it has lasted kPersistence (Failure())
  Event Observe(const core::Simulation& sim, long step);
  // "warning: cable 'cable' element 29 (nodes 29-30) folded: ... at t = 12.3 s (the run
  // fails if it stays folded for 1 s)"
  const std::string& Warning() const { return warning_; }
  // "folded cable since t = 12.3 s, still at t = 13.3 s: cable 'cable' element 29 ..."
  const std::string& Failure() const { return failure_; }

 private:
  long stride_ = 1;
  bool folded_ = false;  // at the last check
  double since_ = 0.0;   // start of the current fold [s]
  std::string warning_, failure_;
};

}  // namespace towsim::app
