#include "app/node/dds_pacer.h"

#include <sys/prctl.h>
#include <time.h>

#include <algorithm>
#include <cmath>

namespace towsim::app {
namespace {

constexpr double kBinWidth = 1e-6;  // [s]

// sleeps until t on CLOCK_MONOTONIC (steady_clock's clock on Linux), absolute: no drift
void SleepUntil(Pacer::Clock::time_point t) {
  const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(t.time_since_epoch());
  timespec ts;
  ts.tv_sec = static_cast<time_t>(ns.count() / 1000000000);
  ts.tv_nsec = static_cast<long>(ns.count() % 1000000000);
  // EINTR (a signal) ends the sleep early: the caller polls for it between slices
  clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr);
}

Pacer::Clock::duration Seconds(double s) {
  return std::chrono::duration_cast<Pacer::Clock::duration>(std::chrono::duration<double>(s));
}

}  // namespace

void LatenessStats::Add(double lateness) {
  const double x = std::max(0.0, lateness);
  const long bin = std::lround(x / kBinWidth);
  ++bins_[static_cast<size_t>(std::min<long>(bin, kBins))];
  ++count_;
  max_ = std::max(max_, x);
  last_ = x;
}

double LatenessStats::Quantile(double p) const {
  if (count_ == 0) return 0.0;
  const long rank = std::max(1L, static_cast<long>(std::ceil(p * static_cast<double>(count_))));
  long seen = 0;
  for (int b = 0; b < kBins; ++b) {
    seen += bins_[b];
    if (seen >= rank) return b * kBinWidth;
  }
  return max_;  // in the overflow bin
}

void LatenessStats::Clear() { *this = LatenessStats(); }

void Pacer::Start(double period) {
  period_ = period;
  deadline_ = Clock::now() + Seconds(period_);
}

bool Pacer::WaitForDeadline(const std::function<bool()>& keep_waiting, double slice, double spin) {
  if (!slack_set_) {
    // wake-ups as precise as the kernel allows (the default slack is 50 us)
    prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL);
    slack_set_ = true;
  }
  const Clock::duration step = Seconds(slice);
  const Clock::time_point wake = deadline_ - Seconds(spin);
  for (;;) {
    const Clock::time_point now = Clock::now();
    if (now >= wake) break;
    if (keep_waiting && !keep_waiting()) return false;
    SleepUntil(std::min(wake, now + step));
  }
  while (Clock::now() < deadline_) {
    // spin: the last moments before the deadline
  }
  stats_.Add(std::chrono::duration<double>(Clock::now() - deadline_).count());
  return true;
}

bool Pacer::EndStep() {
  const Clock::time_point now = Clock::now();
  deadline_ += Seconds(period_);
  if (now > deadline_) {
    ++overruns_;
    deadline_ = now;  // the next step starts at once; no catch-up burst
    return true;
  }
  return false;
}

}  // namespace towsim::app
