#include "app/sweep/sweep_progress.h"

#include <cmath>

namespace towsim::app {

void SweepProgress::Update(int done, int failed, int running, double wall, bool force) {
  if (!force && last_draw_ >= 0.0 && wall - last_draw_ < kMinInterval) return;
  last_draw_ = wall;
  char left[32] = "--";
  const int remaining = total_ - already_ - done;
  if (done > 0) {
    const long s = std::lround(wall / done * remaining);
    std::snprintf(left, sizeof left, "%ldm%02lds", s / 60, s % 60);
  }
  std::fprintf(out_, "\r[towsim_sweep] %d/%d cases done, %d failed, %d running, about %s left   ",
               already_ + done, total_, failed, running, left);
  std::fflush(out_);
  drawn_ = true;
}

void SweepProgress::Finish() {
  if (!drawn_) return;
  std::fputc('\n', out_);
  std::fflush(out_);
  drawn_ = false;
}

}  // namespace towsim::app
