#pragma once
// A vessel's time history of poses (core/vessel.h TimeHistory, docs/vessels.md "Time history
// files") as a smooth function of time: one natural cubic spline (core/cubic_spline.h) per
// channel of p = [x, y, z, roll, pitch, yaw] (world NED [m], ZYX Euler angles [rad], yaw
// unwrapped), so that the pose, its rate dp/dt and dp2/dt2 are continuous (C2) between the
// first and the last sample. The rates are time derivatives of the six numbers: the angular
// velocity in the body frame follows from the Euler rates by the usual kinematic relation,
// which is the caller's.
//
// Outside the samples (t_0 .. t_{n-1}):
//   t < t_0:      the first pose held: p = p_0, dp/dt = 0, d2p/dt2 = 0;
//   t > t_{n-1}:  continued along a straight line at the last rate:
//                 p = p_{n-1} + p'(t_{n-1}) (t - t_{n-1}), dp/dt = p'(t_{n-1}), d2p/dt2 = 0.
// Both are discontinuous in the rate (before) or the acceleration (after) at the end sample; a
// scene's history must cover the run (scene/time_history_file.h, TimeHistoryCoverageProblem),
// so a run only meets them in the last step's rounding.
//
// Built once, O(n); Evaluate is O(log n) and does not allocate.

#include <array>

#include <Eigen/Core>

#include "core/cubic_spline.h"
#include "core/vessel.h"

namespace towsim::core {

struct PoseSample {
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  Vector6 pose = Vector6::Zero();          // [x, y, z, roll, pitch, yaw] [m, rad]
  Vector6 velocity = Vector6::Zero();      // d/dt of pose [m/s, rad/s]
  Vector6 acceleration = Vector6::Zero();  // d2/dt2 of pose [m/s^2, rad/s^2]
};

class PoseSpline {
 public:
  PoseSpline() = default;
  // history: at least two samples at strictly increasing times (the reader checks)
  explicit PoseSpline(const TimeHistory& history);

  PoseSample Evaluate(double t) const;

  double start_time() const { return t0_; }
  double end_time() const { return t1_; }

 private:
  std::array<CubicSpline, 6> channels_;
  double t0_ = 0.0;
  double t1_ = 0.0;
};

}  // namespace towsim::core
