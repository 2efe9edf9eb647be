#pragma once
// The progress line on stderr during a long run:
//
//   [sim_node] t = 123.4/300.0 s  41%  RTF 523x
//
// redrawn in place ('\r') at most 4 times a second, and only once the run has lasted more
// than 2 s of wall time, so short runs print nothing. Finish() ends the line with a newline
// if one was drawn. RTF = simulated time / wall time.

#include <cstdio>

namespace towsim::app {

class Progress {
 public:
  static constexpr double kQuietWall = 2.0;     // no line before this wall time [s]
  static constexpr double kMinInterval = 0.25;  // between redraws [s]

  // `duration`: the simulated time the run is heading for [s]
  explicit Progress(double duration, std::FILE* out = stderr) : duration_(duration), out_(out) {}

  // t: simulated time reached [s], wall: wall time since the start of the run [s]
  void Update(double t, double wall);
  void Finish();

 private:
  double duration_;
  std::FILE* out_;
  double last_draw_ = -1.0;  // wall time of the last redraw [s], < 0: none yet
};

}  // namespace towsim::app
