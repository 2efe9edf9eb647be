#include "core/pose_spline.h"

#include <vector>

namespace towsim::core {

PoseSpline::PoseSpline(const TimeHistory& history) {
  const size_t n = history.t.size();
  if (n == 0) return;
  t0_ = history.t.front();
  t1_ = history.t.back();
  for (int c = 0; c < 6; ++c) {
    std::vector<double> y(n);
    for (size_t i = 0; i < n; ++i) y[i] = history.pose[i](c);
    channels_[c] = CubicSpline(history.t, std::move(y));
  }
}

PoseSample PoseSpline::Evaluate(double t) const {
  PoseSample s;
  if (t < t0_) {
    // before the first sample: the first pose, at rest
    for (int c = 0; c < 6; ++c) s.pose(c) = channels_[c].Evaluate(t0_).y;
    return s;
  }
  if (t > t1_) {
    // after the last sample: p_end + p'_end (t - t_end), no acceleration
    for (int c = 0; c < 6; ++c) {
      const CubicSpline::Value end = channels_[c].Evaluate(t1_);
      s.pose(c) = end.y + end.dy * (t - t1_);
      s.velocity(c) = end.dy;
    }
    return s;
  }
  for (int c = 0; c < 6; ++c) {
    const CubicSpline::Value v = channels_[c].Evaluate(t);
    s.pose(c) = v.y;
    s.velocity(c) = v.dy;
    s.acceleration(c) = v.d2y;
  }
  return s;
}

}  // namespace towsim::core
