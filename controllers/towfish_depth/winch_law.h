#pragma once
// The slow half of towfish_depth's winch mode (docs/controllers.md "towfish_depth"), a pure
// function (no DDS): the drum speed that moves the towfish's steady depth to the commanded one
// while the elevators (towfish_depth/depth_law.h) take the fast part.
//
// A towed body's steady depth grows with the paid-out length L (for a cable towed at a steady
// speed, dz/dL is the sine of the cable's mean angle below the horizontal, 0.1 .. 0.6 for the
// scenes here), so paying out at v moves the depth at about (dz/dL) v: the length is an
// integrator of the drum speed and a proportional law suffices. The elevators hold the depth
// within seconds (their PID integrates the error away), so the winch answers what they leave
// and what they hold: the depth error AND the elevators' steady "deeper" demand d (the PID's
// output, + pushes the towfish deeper), converted into metres by elevator_depth [m/rad]; it
// pays out while the elevators push down and reels in while they pull up, until the towfish
// sits at the commanded depth with the elevators near neutral:
//   s    = e + elevator_depth d,           e = commanded depth - z  (> 0: too shallow)
//   s_f' = (s - s_f) / T_f
//   v    = 0                                 if |s_f| < deadband (the drum stands still)
//          clamp(k (s_f -+ deadband), -v_max, v_max)   otherwise
// rate-limited to |dv/dt| <= a_max, with v_max and a_max the winch's max_speed and
// max_acceleration (SceneInfo) or less. In the steady state both loops rest: e = 0 (the PID's
// integral) and |d| < deadband / elevator_depth (1.1 deg with the defaults). The filter T_f
// (10 s, against the elevator loop's few seconds) leaves the drum out of the fast part; the
// slow loop's time constant is about 1 / (k dz/dL), 30 s for k = 0.1 1/s and dz/dL = 0.3.

namespace towsim::controllers {

struct WinchDepthParams {
  double gain = 0.1;           // k: drum speed per metre of depth error [1/s]
  double deadband = 0.5;       // [m]
  double elevator_depth = 25.0;  // the elevators' demand as depth [m/rad]
  double filter = 10.0;        // T_f [s], > 0
  double max_speed = 1.0;      // v_max [m/s], > 0
  double max_acceleration = 0.2;  // a_max [m/s^2], > 0
};

struct WinchDepthState {
  bool initialized = false;
  double error = 0.0;  // s_f [m]
  double speed = 0.0;  // the last drum speed commanded [m/s]
};

// the drum speed [m/s] (+ pays out, the towfish goes deeper) answering the commanded depth
// `target`, the depth z [m] (world NED, down positive) and the elevators' deeper demand
// `deeper` [rad] (towfish_depth/depth_law.h: sign * elevator), step dt [s]
double WinchDepthStep(const WinchDepthParams& p, WinchDepthState& state, double target, double z,
                      double deeper, double dt);

}  // namespace towsim::controllers
