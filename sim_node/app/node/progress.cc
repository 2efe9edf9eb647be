#include "app/node/progress.h"

namespace towsim::app {

void Progress::Update(double t, double wall) {
  if (wall <= kQuietWall) return;
  if (last_draw_ >= 0.0 && wall - last_draw_ < kMinInterval) return;
  last_draw_ = wall;
  const double percent = duration_ > 0.0 ? 100.0 * t / duration_ : 100.0;
  const double rtf = wall > 0.0 ? t / wall : 0.0;
  std::fprintf(out_, "\r[sim_node] t = %.1f/%.1f s  %.0f%%  RTF %.*fx   ", t, duration_, percent,
               rtf < 10.0 ? 2 : 0, rtf);
  std::fflush(out_);
}

void Progress::Finish() {
  if (last_draw_ < 0.0) return;
  std::fputc('\n', out_);
  std::fflush(out_);
  last_draw_ = -1.0;
}

}  // namespace towsim::app
