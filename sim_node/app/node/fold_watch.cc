#include "app/node/fold_watch.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace towsim::app {

FoldWatch::FoldWatch(double h)
    : stride_(std::max(1L, std::lround(kCheckInterval / h))) {}

FoldWatch::Event FoldWatch::Observe(const core::Simulation& sim, long step) {
  if (step % stride_ != 0) return Event::kNone;
  const core::FoldReport fold = sim.FindFold();
  if (!fold.folded) {
    folded_ = false;
    return Event::kNone;
  }
  const double t = sim.time();
  char text[400];
  if (!folded_) {
    folded_ = true;
    since_ = t;
    std::snprintf(text, sizeof text,
                  "warning: %s at t = %.6g s (the run fails if it stays folded for %g s)",
                  fold.Describe(sim.system()).c_str(), t, kPersistence);
    warning_ = text;
    return Event::kFolded;
  }
  if (t - since_ < kPersistence - 1e-9) return Event::kNone;
  std::snprintf(text, sizeof text,
                "folded cable since t = %.6g s, still at t = %.6g s: %s (the shape is not a "
                "cable's; docs/faults.md)",
                since_, t, fold.Describe(sim.system()).c_str());
  failure_ = text;
  return Event::kFailed;
}

}  // namespace towsim::app
