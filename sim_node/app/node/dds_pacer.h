#pragma once
// Wall-clock pacing of the realtime mode (docs/contract.md §4): step k of a run paced from wall time
// `epoch` starts at its deadline epoch + k * period, period = h / rate. Each step's lateness
// (start - deadline) is measured; a step that ends after the next deadline is an overrun, and
// the schedule then restarts from the end of that step (no burst of catch-up steps).

#include <chrono>
#include <cstdint>
#include <functional>
#include <vector>

namespace towsim::app {

// lateness distribution: 1 us bins up to kRange, the largest value kept exactly
class LatenessStats {
 public:
  static constexpr int kBins = 20000;  // 1 us bins: 0 .. 20 ms
  void Add(double lateness);           // [s], negative counts as 0
  long count() const { return count_; }
  double max() const { return max_; }  // [s]
  double last() const { return last_; }
  // the p-quantile (0 < p <= 1) [s], resolution 1 us; 0 if empty
  double Quantile(double p) const;
  void Clear();

 private:
  std::vector<uint32_t> bins_ = std::vector<uint32_t>(kBins + 1, 0);  // last: overflow
  long count_ = 0;
  double max_ = 0.0, last_ = 0.0;
};

class Pacer {
 public:
  using Clock = std::chrono::steady_clock;

  // the schedule starts now: the next step's deadline is now + period [s]
  void Start(double period);
  // a new period from the next step on, the schedule restarted from now
  void SetPeriod(double period) { Start(period); }
  double period() const { return period_; }

  // Sleeps until the deadline of the next step, in slices of at most `slice` [s]; between
  // slices calls keep_waiting() and returns false at once if it says no (the deadline stays).
  // The last `spin` [s] before the deadline are spent polling the clock instead of sleeping
  // (a sleeping thread wakes up tens to hundreds of microseconds late). On true, the lateness
  // of this step start is recorded in stats().
  bool WaitForDeadline(const std::function<bool()>& keep_waiting, double slice = 0.05,
                       double spin = kDefaultSpin);
  static constexpr double kDefaultSpin = 300e-6;  // [s], 3% of a 100 Hz period
  // the step has ended (physics and publishing): counts an overrun if past the next deadline
  // and then restarts the schedule from now; moves the deadline on by one period
  bool EndStep();

  const LatenessStats& stats() const { return stats_; }
  uint64_t overruns() const { return overruns_; }

 private:
  double period_ = 0.0;
  Clock::time_point deadline_;  // of the next step start
  LatenessStats stats_;
  uint64_t overruns_ = 0;
  bool slack_set_ = false;
};

}  // namespace towsim::app
